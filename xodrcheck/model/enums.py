"""The standard's enumerations used by the model (attribute values with a closed list of spellings), and the element
names of object outline points and skeleton vertices (the kinds of :class:`~xodrcheck.model.OutlinePoint` and
:class:`~xodrcheck.model.Vertex`).

An enumeration whose list changes from version to version (road types, lane access restrictions, object and signal
types, road mark types and colours) stays a string in the model, as the file spelt it.
"""

from __future__ import annotations

import enum

__all__ = [
    "CORNER_LOCAL",
    "CORNER_ROAD",
    "CURVE_LOCAL",
    "DIRECTED_LANE_TYPES",
    "DRIVABLE_LANE_TYPES",
    "VERTEX_LOCAL",
    "VERTEX_ROAD",
    "AccessRule",
    "ConnectionType",
    "ContactPoint",
    "CrgMode",
    "CrgOrientation",
    "CrgPurpose",
    "ElementDir",
    "ElementType",
    "JunctionGroupType",
    "JunctionType",
    "LaneAdvisory",
    "LaneDirection",
    "LaneLayer",
    "LaneType",
    "MaxSpeed",
    "Orientation",
    "PRange",
    "ReferenceType",
    "Side",
    "StationType",
    "SwitchPosition",
    "TrafficRule",
]

#: Element names of an object outline's points (13.2): the kinds :attr:`xodrcheck.model.Outline.kind` reports.
CORNER_ROAD, CORNER_LOCAL, CURVE_LOCAL = "cornerRoad", "cornerLocal", "curveLocal"
#: Element names of an object skeleton's vertices (13.3).
VERTEX_ROAD, VERTEX_LOCAL = "vertexRoad", "vertexLocal"


class ElementType(enum.Enum):
    ROAD = "road"
    JUNCTION = "junction"


class ContactPoint(enum.Enum):
    START = "start"
    END = "end"

    @property
    def opposite(self) -> ContactPoint:
        """The road's other end."""
        return ContactPoint.END if self is ContactPoint.START else ContactPoint.START


class ElementDir(enum.Enum):
    """OpenDRIVE 1.8 ``elementDir`` of a link into a direct junction / road: ``+`` or ``-``."""

    PLUS = "+"
    MINUS = "-"


class TrafficRule(enum.Enum):
    RHT = "RHT"
    LHT = "LHT"


class PRange(enum.Enum):
    ARC_LENGTH = "arcLength"
    NORMALIZED = "normalized"


class JunctionType(enum.Enum):
    DEFAULT = "default"
    DIRECT = "direct"
    VIRTUAL = "virtual"
    CROSSING = "crossing"


class LaneLayer(enum.Enum):
    """OpenDRIVE 1.9 lane layer (11.2): every road has the permanent layer; a temporary one (roadworks) may lie on top
    of it, with its own lane offset and lane sections and priority for driving."""

    PERMANENT = "permanent"
    TEMPORARY = "temporary"


class LaneType(enum.Enum):
    """Lane types of OpenDRIVE 1.4 to 1.8 (lower-case spellings of older files map onto these)."""

    NONE = "none"
    DRIVING = "driving"
    STOP = "stop"
    SHOULDER = "shoulder"
    BIKING = "biking"
    SIDEWALK = "sidewalk"
    WALKING = "walking"
    BORDER = "border"
    RESTRICTED = "restricted"
    PARKING = "parking"
    BIDIRECTIONAL = "bidirectional"
    MEDIAN = "median"
    SPECIAL1 = "special1"
    SPECIAL2 = "special2"
    SPECIAL3 = "special3"
    ROAD_WORKS = "roadWorks"
    TRAM = "tram"
    RAIL = "rail"
    ENTRY = "entry"
    EXIT = "exit"
    OFF_RAMP = "offRamp"
    ON_RAMP = "onRamp"
    CONNECTING_RAMP = "connectingRamp"
    BUS = "bus"
    TAXI = "taxi"
    HOV = "HOV"
    MWY_ENTRY = "mwyEntry"
    MWY_EXIT = "mwyExit"
    SLIP_LANE = "slipLane"
    CURB = "curb"
    # Not in the standard: the file named a type no version defines. The reader records a finding with the raw name.
    UNKNOWN = "unknown"


#: Lane types a motor vehicle may drive on (used by rules that only concern drivable lanes).
DRIVABLE_LANE_TYPES = frozenset(
    {
        LaneType.DRIVING,
        LaneType.ENTRY,
        LaneType.EXIT,
        LaneType.OFF_RAMP,
        LaneType.ON_RAMP,
        LaneType.CONNECTING_RAMP,
        LaneType.BIDIRECTIONAL,
        LaneType.BUS,
        LaneType.TAXI,
        LaneType.HOV,
        LaneType.MWY_ENTRY,
        LaneType.MWY_EXIT,
        LaneType.SLIP_LANE,
    }
)


#: Lane types whose traffic has one direction of travel (11.3.1: the lane's side and the road's RHT/LHT give it,
#: @direction may change it): vehicle lanes and ``biking``. The others carry no directed traffic: ``none``,
#: ``border``, ``shoulder``, ``curb``, ``median`` and ``restricted`` are not driven on, ``walking``/``sidewalk``
#: lanes are walked both ways, ``parking``, ``stop`` (a hard shoulder for emergency stops), ``tram``, ``rail``,
#: ``roadWorks`` and ``special1-3`` do not state one; ``bidirectional`` carries both.
DIRECTED_LANE_TYPES = (DRIVABLE_LANE_TYPES - {LaneType.BIDIRECTIONAL}) | {LaneType.BIKING}


class Side(enum.Enum):
    LEFT = "left"
    CENTER = "center"
    RIGHT = "right"


# --------------------------------------------------------------------------------------------------------------------
# One cubic-profile type for width, border, laneOffset, elevation and superelevation
# --------------------------------------------------------------------------------------------------------------------


class Orientation(enum.Enum):
    """Which direction of travel an object or signal is valid for (``e_orientation``): along s, against s, both."""

    PLUS = "+"
    MINUS = "-"
    NONE = "none"


class LaneDirection(enum.Enum):
    """A lane's ``@direction`` (1.8, 11.3.1): ``standard`` keeps the direction its side and the road's traffic rule
    give, ``reversed`` turns it round, ``both`` allows both (it replaces the deprecated type ``bidirectional``)."""

    STANDARD = "standard"
    REVERSED = "reversed"
    BOTH = "both"


class LaneAdvisory(enum.Enum):
    """A lane's ``@advisory`` (1.8): on which side lane changes are advised against."""

    NONE = "none"
    INNER = "inner"
    OUTER = "outer"
    BOTH = "both"


class AccessRule(enum.Enum):
    """Whether an ``<access>`` record allows or denies its restriction."""

    ALLOW = "allow"
    DENY = "deny"


class ConnectionType(enum.Enum):
    """A junction connection's ``@type`` (1.7+): ``virtual`` connections join roads without a connecting road."""

    DEFAULT = "default"
    VIRTUAL = "virtual"


class CrgMode(enum.Enum):
    """How a road's or junction's OpenCRG data applies (10.6)."""

    ATTACHED = "attached"
    ATTACHED0 = "attached0"
    GENUINE = "genuine"
    GLOBAL = "global"


class CrgPurpose(enum.Enum):
    """What an OpenCRG file gives: heights or friction."""

    ELEVATION = "elevation"
    FRICTION = "friction"


class CrgOrientation(enum.Enum):
    """Whether OpenCRG data runs along the road's s or against it (``e_direction``)."""

    SAME = "same"
    OPPOSITE = "opposite"


class MaxSpeed(enum.Enum):
    """The words a road type's speed ``max`` may hold instead of a number."""

    NO_LIMIT = "no limit"
    UNDEFINED = "undefined"


class ReferenceType(enum.Enum):
    """What a signal's ``<reference>`` names: an object or another signal."""

    OBJECT = "object"
    SIGNAL = "signal"


class SwitchPosition(enum.Enum):
    """A railroad switch's position (15.3)."""

    DYNAMIC = "dynamic"
    STRAIGHT = "straight"
    TURN = "turn"


class StationType(enum.Enum):
    """A station's size (15.4)."""

    SMALL = "small"
    MEDIUM = "medium"
    LARGE = "large"


class JunctionGroupType(enum.Enum):
    """What a junction group is (12.15)."""

    ROUNDABOUT = "roundabout"
    UNKNOWN = "unknown"
    COMPLEX_JUNCTION = "complexJunction"
    HIGHWAY_INTERCHANGE = "highwayInterchange"
