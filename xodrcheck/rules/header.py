"""The header, default regulations and whole-file recommendations (``H0xx``).

Each rule enforces a rule of ASAM OpenDRIVE 1.9.0 Annex F, named in its docstring (sections 6.4 and 8.5).
"""

from __future__ import annotations

import math
import re

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.geometry.planview import evaluate_element
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context

#: Longest stretch of a reference line between two of the points :func:`_extent` takes (metres): an arc of radius
#: 50 m bulges 6 cm between points this far apart.
_EXTENT_STEP = 5.0


def _extent(ctx: Context) -> tuple[float, float, float, float] | None:
    """Bounding box (min x, min y, max x, max y) of the roads' whole reference lines: every plan-view element from
    its start to its end, at points at most :data:`_EXTENT_STEP` apart (arcs, spirals and curves bulge between their
    ends). Lane borders are left out: evaluating them costs as much as the geometry rules' sampling, and they widen
    the box by a road's half width at most."""
    xs: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    for road in ctx.document.roads:
        for g in road.plan_view:
            if not math.isfinite(g.length) or g.length < 0.0:
                continue
            count = 2 + min(int(g.length // _EXTENT_STEP), 100_000)
            pose = evaluate_element(g, np.linspace(0.0, g.length, count))
            xs.append(np.asarray(pose.x, dtype=float).ravel())
            ys.append(np.asarray(pose.y, dtype=float).ravel())
    if not xs:
        return None
    x, y = np.concatenate(xs), np.concatenate(ys)
    keep = np.isfinite(x) & np.isfinite(y)
    if not keep.any():
        return None
    x, y = x[keep], y[keep]
    return float(x.min()), float(y.min()), float(x.max()), float(y.max())


@rule(
    "H001",
    "coordinates-off-centre",
    Category.HEADER,
    Severity.WARNING,
    uids=(U.HEADER_CENTERED_COORDS,),
)
def coordinates_off_centre(ctx: Context):
    """The map's coordinates are not centred around (0, 0): it lies far from the origin of its own frame.

    The header's ``<offset>`` should be chosen so that x and y are about centred on (0, 0) (Annex F
    ``header.offset.centered_coords``, 8.5): applications that keep coordinates in floating point lose precision on
    large values (a 32-bit float steps by 1 mm at 8 km, by 0.5 m at 5000 km, UTM's northings). Reported when the
    centre of the box around the roads' whole reference lines (lane borders are left out: they add at most a road's
    half width) lies further from (0, 0) than the ``centre_distance`` tolerance (10 km) and further than half the
    box's diagonal (so the origin is not within the map's own extent). Move the geometry by minus that centre and add
    the shift to ``<offset>``.

    Passes (a map around the origin)::

        <geometry s="0" x="-50" y="0" hdg="0" length="100"><line/></geometry>

    Fails (UTM coordinates written as they are)::

        <geometry s="0" x="500000" y="5400000" hdg="0" length="100"><line/></geometry>
    """
    box = _extent(ctx)
    if box is None:
        return
    x0, y0, x1, y1 = box
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    distance = math.hypot(cx, cy)
    half_diagonal = math.hypot(x1 - x0, y1 - y0) / 2
    if distance <= max(ctx.tolerances.centre_distance, half_diagonal):
        return
    far_x, far_y = max(abs(x0), abs(x1)), max(abs(y0), abs(y1))
    step = float(np.spacing(np.float32(max(far_x, far_y))))
    header = ctx.document.header
    yield coordinates_off_centre.finding(
        f"the map's reference lines span x {x0:.1f}..{x1:.1f}, y {y0:.1f}..{y1:.1f}: their centre ({cx:.1f}, "
        f"{cy:.1f}) lies {distance / 1000:.4g} km from (0, 0) (32-bit floats step by {step:.3g} m at the farthest "
        f"point, {math.hypot(far_x, far_y) / 1000:.4g} km out); move the geometry by ({0.0 - cx:.1f}, "
        f"{0.0 - cy:.1f}) and add ({cx:.1f}, {cy:.1f}) to the header's <offset>",
        x=cx,
        y=cy,
        line=(header.line if header is not None else 0) or None,
    )


#: What ``<semantics>`` inside ``<defaultRegulations>`` may hold (6.4.3), besides additional data (6.2).
_REGULATION_CONTENT = frozenset({"speed", "priority", "userData", "include", "dataQuality"})


@rule(
    "H002",
    "default-regulations-content",
    Category.HEADER,
    Severity.ERROR,
    uids=(U.DEFAULT_REGULATIONS_ONLY_SPEED_PRIORITY,),
)
def default_regulations_content(ctx: Context):
    """The header's ``<defaultRegulations>`` use a signal semantic other than ``<speed>`` and ``<priority>``.

    Default regulations give a country's default speed limits per road type and default priorities per sign type
    (6.4.3); only ``<speed>`` and ``<priority>`` elements shall be used in them (Annex F
    ``defaultRegulations.only_speed_priority``). Anything else (``<prohibited>``, ``<lane>``, ``<warning>``...) belongs
    to a signal's or a road's own semantics.

    Passes::

        <roadRegulations type="town"><semantics><speed type="maximum" value="50" unit="km/h"/></semantics>

    Fails::

        <roadRegulations type="town"><semantics><prohibited/></semantics>
    """
    header = ctx.document.header
    regulations = None if header is None else header.default_regulations
    if regulations is None:
        return
    owners = [(owner.line, "roadRegulations", owner.semantics) for owner in regulations.road_regulations]
    owners += [(owner.line, "signalRegulations", owner.semantics) for owner in regulations.signal_regulations]
    for line, tag, semantics in sorted(owners, key=lambda owner: owner[0]):
        for item in () if semantics is None else semantics.items:
            if item.kind not in _REGULATION_CONTENT:
                yield default_regulations_content.finding(
                    f"the default regulations' <{tag}> (line {line}) use <{item.kind}>: only <speed> and "
                    "<priority> may be used in <defaultRegulations>; give it on the roads or signals it concerns",
                    line=item.line,
                )


_PROJ_DEFINITION = re.compile(r"\+(?:proj|init)=\S+|(?<![=:\w])EPSG:\d+", re.IGNORECASE)


@rule("H003", "projection-repeated", Category.HEADER, Severity.ERROR, uids=(U.HEADER_MAX_ONE_PROJ,))
def projection_repeated(ctx: Context):
    """The map defines its projection more than once: several ``<geoReference>`` elements, or one whose PROJ string
    holds several definitions.

    There shall be no more than one definition of the projection (Annex F ``header.proj.max_one_proj``, 8.5); with
    two, readers pick either. A ``<geoReference>`` is one PROJ string of one coordinate reference system: one
    ``+proj=`` (or ``+init=``, or an ``EPSG:`` code). Without any, the map is in a local Cartesian system.

    Passes::

        <geoReference><![CDATA[+proj=utm +zone=32 +ellps=GRS80 +units=m +no_defs]]></geoReference>

    Fails::

        <geoReference><![CDATA[+proj=utm +zone=32 +ellps=GRS80 +units=m +no_defs]]></geoReference>
        <geoReference><![CDATA[+proj=tmerc +lat_0=49 +lon_0=8 +ellps=GRS80 +units=m]]></geoReference>
    """
    header = ctx.document.header
    found = () if header is None else header.geo_references
    if len(found) > 1:
        lines = ", ".join(str(reference.line) for reference in found)
        yield projection_repeated.finding(
            f"the header has {len(found)} <geoReference> elements (lines {lines}): one projection only; keep the one "
            "the coordinates are in",
            line=found[1].line,
        )
    for reference in found:
        definitions = _PROJ_DEFINITION.findall(reference.text)
        if len(definitions) > 1:
            yield projection_repeated.finding(
                f"the <geoReference> at line {reference.line} holds {len(definitions)} projection definitions "
                f"({', '.join(definitions)}): one PROJ string defines one projection; keep the one the coordinates "
                "are in",
                line=reference.line,
            )
