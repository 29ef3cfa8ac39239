"""The OpenDRIVE document as plain, frozen, typed data: what :mod:`xodrcheck.reader` builds from a file and every
rule, view and writer reads.

Nothing here parses XML or evaluates geometry (:mod:`xodrcheck.geometry` evaluates). One
small class per element kind of the standard, numbers parsed once, enumerations where the standard has a closed list
(:mod:`.enums`). Every record keeps its element's ``line`` and ``xml``, the facts about the XML itself (attributes
given or defaulted, child order, unknown children, unparsable text: :mod:`.facts`, the one place they are kept).

The package's names load with their module on first use (PEP 562; ``__init__.pyi`` names them for type checkers):
reading a file without objects, signals or junction parts does not create their classes. Import names from the
package (``from xodrcheck.model import Road``).

Conventions: lengths in metres, angles in radians; ``s`` of a record inside a lane section is its ``sOffset``, of a
road-level record absolute; a value the file did not give and the standard does not default is ``None``.

The main types::

    Document                      header, roads, junctions, controllers, junction groups, stations, vms groups,
    |                             xml (the root's facts), elements (ElementTable: XPath of a line),
    |                             ids (IdTable: the ids the file defines and names, as written)
    +- Header                     revision, extent, offset, geoReferences, license, DefaultRegulations
    +- Road                       id, length, junction, rule, RoadLink x2
    |  +- plan_view               Line | Arc | Spiral | Poly3 | ParamPoly3
    |  +- elevation, superelevation, lane_offset: Cubic profiles; types (RoadType, RoadSpeed); shapes (Shape);
    |  |  cross_section_surface; surface (Surface of SurfaceCrg); railroad (Switch, SwitchTrack, SwitchPartner)
    |  +- lanes, temporary_lanes  Lanes (one per lane layer)
    |  |  +- LaneSection          s, length, left / center / right
    |  |     +- Lane              id, type, links (LaneLinks), widths / borders (Cubic), RoadMark (type lines,
    |  |                          explicit lines, sways), Speed, LaneHeight, LaneAccess, LaneMaterial, LaneRule,
    |  |                          LaneVisibility, direction, advisory
    |  +- objects                 RoadObject: Outline (CornerRoad | CornerLocal | CurveLocal, OutlinePoint,
    |  |                          Markings), Repeat, Skeleton (Polyline, Vertex), ObjectBorder, ObjectMaterial,
    |  |                          ObjectSurface (ObjectCrg), ParkingSpace, LaneValidity
    |  +- object_references, tunnels, bridges
    |  +- signals                 Signal: PositionRoad, PositionInertial, StaticBoard (Sign), VmsBoard
    |  |                          (DisplayArea), Semantics (Semantic), SignalDependency, SignalLink, LaneValidity
    |  +- signal_references       SignalReference
    +- Junction                   id, type, Connection (JunctionLaneLink, ConnectionEnd), CrossPath, Priority,
    |                             JunctionController, RoadSection, Boundary (LaneSegment | JointSegment),
    |                             ElevationGrid (GridRow), JunctionPlanView (JunctionGeometry), surface, objects
    +- Controller (Control), JunctionGroup (JunctionReference), Station (Platform, PlatformSegment),
       VmsGroup (VmsBoardReference)
"""

from __future__ import annotations

import importlib
from typing import Any

#: The package's modules and the public names each defines (loaded on first use: see the module's note).
_MODULES = {
    "enums": (
        "CORNER_LOCAL CORNER_ROAD CURVE_LOCAL DIRECTED_LANE_TYPES DRIVABLE_LANE_TYPES VERTEX_LOCAL VERTEX_ROAD "
        "AccessRule ConnectionType ContactPoint CrgMode CrgOrientation CrgPurpose ElementDir ElementType "
        "JunctionGroupType JunctionType LaneAdvisory LaneDirection LaneLayer LaneType MaxSpeed Orientation PRange "
        "ReferenceType Side StationType SwitchPosition TrafficRule"
    ),
    "facts": "NO_FACTS UnknownElement UnreadLink XmlFacts facts_field",
    "planview": "Arc Cubic Geometry Line ParamPoly3 PlanViewElement Poly3 Profile Spiral",
    "lanes": "Lane LaneHeight LaneKey LaneLinks LaneSection Lanes RoadMark Speed lane_type_name",
    "lane_records": (
        "LaneAccess LaneMaterial LaneRule LaneVisibility RoadMarkExplicit RoadMarkLine RoadMarkSway RoadMarkType"
    ),
    "roads": "Road RoadLink",
    "road_records": "Railroad RoadSpeed RoadType Shape Switch SwitchPartner SwitchTrack",
    "surface": "CrossSectionSurface Surface SurfaceCoefficients SurfaceCrg SurfacePolynomial SurfaceStrip",
    "objects": (
        "Bridge CornerLocal CornerReference CornerRoad CurveLocal CurveShape LaneValidity Marking Markings "
        "ObjectBorder ObjectCrg ObjectMaterial ObjectReference ObjectSurface Outline OutlinePoint ParkingSpace "
        "Polyline Repeat RoadObject RoadStructure Skeleton Tunnel Vertex"
    ),
    "signals": (
        "Control Controller DisplayArea PositionInertial PositionRoad Semantic Semantics Sign Signal "
        "SignalDependency SignalLink SignalReference StaticBoard VmsBoard VmsBoardReference VmsGroup"
    ),
    "junctions": "Connection Junction JunctionLaneLink",
    "junction_parts": (
        "Boundary BoundarySegment ConnectionEnd CrossPath CrossPathLink ElevationGrid GridRow JointSegment "
        "JunctionController JunctionGeometry JunctionGroup JunctionPlanView JunctionReference LaneSegment "
        "OtherSegment Priority RoadPlace RoadSection"
    ),
    "ids": "ID_CLASSES ID_REFERENCES RECORDED SIGNAL_LINKS SIGNS IdElement IdTable",
    "header": "GeoReference Header Offset",
    "regulations": "DefaultRegulations License RoadRegulation SignalRegulation",
    "railroad": "Platform PlatformSegment Station",
    "document": "Document ElementTable document_cache",
}
#: Public name -> the module that defines it.
_EXPORTS = {name: module for module, names in _MODULES.items() for name in names.split()}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))
