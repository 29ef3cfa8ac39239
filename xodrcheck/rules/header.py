"""The header, default regulations and whole-file recommendations (``H0xx``).

Each rule enforces a rule of ASAM OpenDRIVE 1.9.0 Annex F, named in its docstring (sections 6.4 and 8.5).
"""

from __future__ import annotations

import math

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.rules import road_uids as U
from xodrcheck.rules.context import Context
from xodrcheck.rules.registry import rule


def _extent(ctx: Context) -> tuple[float, float, float, float] | None:
    """Bounding box (min x, min y, max x, max y) of the start points of every plan-view element."""
    xs = [g.x for road in ctx.document.roads for g in road.plan_view]
    ys = [g.y for road in ctx.document.roads for g in road.plan_view]
    x, y = np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)
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
    centre of the box around every plan-view element's start lies further from (0, 0) than the
    ``centre_distance`` tolerance (10 km) and further than half the box's diagonal (so the origin is not within the
    map's own extent). Move the geometry by minus that centre and add the shift to ``<offset>``.

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
        f"the map's plan view spans x {x0:.1f}..{x1:.1f}, y {y0:.1f}..{y1:.1f}: its centre ({cx:.1f}, {cy:.1f}) lies "
        f"{distance / 1000:.4g} km from (0, 0) (32-bit floats step by {step:.3g} m at its farthest point, "
        f"{math.hypot(far_x, far_y) / 1000:.4g} km out); move the geometry by ({-cx:.1f}, {-cy:.1f}) and add "
        f"({cx:.1f}, {cy:.1f}) to the header's <offset>",
        x=cx,
        y=cy,
        line=(header.line if header is not None else 0) or None,
    )
