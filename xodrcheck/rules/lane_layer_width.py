"""The temporary lane layer stays on the permanent layer's surface (``G016``, OpenDRIVE 1.9)."""

from __future__ import annotations

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.sampled import grid_step
from xodrcheck.support.quantities import metres


def _edges(geometry, index: int, s: np.ndarray) -> tuple[np.ndarray | None, np.ndarray | None]:
    """``t`` of the outer border of the outermost left and right lane of a section at ``s`` (``None`` for a side
    without lanes): each side's lane offset plus the sum of its lane widths."""
    borders = geometry.borders(index, s)
    left, right = geometry.side_lanes(index)
    return (
        borders[left.lanes[-1].id] if left.lanes else None,
        borders[right.lanes[-1].id] if right.lanes else None,
    )


@rule("G016", "temporary-layer-wider", Category.GEOMETRY, Severity.ERROR, uids=(U.LAYER_GROUP_WIDTH_TEMPORARY,))
def temporary_layer_wider(ctx: Context):
    """A lane group of the temporary lane layer reaches further out than the permanent layer's at some ``s``.

    Annex F ``road.lane.layer.lane_group_width_temporary`` (1.9): for each lane group, the sum of all lane widths and
    lane offsets on the temporary layer shall not be greater than on the permanent layer. That sum is the ``t`` of the
    group's outer edge: the temporary left lanes end at or inside the permanent left lanes' edge, the temporary right
    lanes at or inside the permanent right lanes' edge (within ``position``), so the temporary lanes stay on the road's
    surface, which only the permanent layer describes. Checked at every knot of both layers and in steps of the
    geometric rules' grid.

    Passes (permanent right lanes 7 m wide; temporary 6.5 m)::

        <lanes><laneSection s="0"> ... <right> two lanes of 3.5 m ...
        <lanes layer="temporary"><laneSection s="20" length="30"> ... <right> two lanes of 3.25 m ...

    Fails (temporary right lanes 8 m wide)::

        <lanes layer="temporary"><laneSection s="20" length="30"> ... <right> two lanes of 4 m ...
    """
    from xodrcheck.geometry.lanes import temporary_geometry_of

    temporary = temporary_geometry_of(ctx.document)
    tol = ctx.tolerances.position
    step = grid_step(ctx.tolerances)
    for road in ctx.document.roads:
        if road.temporary_lanes is None or road.id not in temporary:
            continue
        permanent = ctx.usable_geometry(road)
        if permanent is None:
            continue
        layer = temporary[road.id]
        for j, section in enumerate(road.temporary_lanes.lane_sections):
            a, e = layer.section_range(j)
            if not e > a:
                continue
            count = int(min(np.ceil((e - a) / step), ctx.tolerances.max_samples_per_section))
            s = np.unique(np.concatenate([np.linspace(a, e, count + 1), layer.knots(j)]))
            s = s[(s >= a) & (s <= e)]
            yield from _compare(temporary_layer_wider, road, layer, j, section, permanent, s, tol)


def _compare(rule_, road, layer, j, section, permanent, s, tol):
    """At most one finding per side of a temporary lane section: where its lanes reach furthest past the permanent
    layer's."""
    temp_left, temp_right = _edges(layer, j, s)
    reach = {"left": np.full(len(s), -np.inf), "right": np.full(len(s), -np.inf)}
    index = permanent.section_index(s)
    for i in np.unique(index):
        if i < 0:
            continue
        here = index == i
        perm_left, perm_right = _edges(permanent, int(i), s[here])
        centre = permanent.borders(int(i), s[here])[0]
        for name, temp, perm, sign in (("left", temp_left, perm_left, 1.0), ("right", temp_right, perm_right, -1.0)):
            if temp is not None:
                reach[name][here] = sign * (temp[here] - (perm if perm is not None else centre))
    for name, beyond in reach.items():
        k = int(np.argmax(beyond))
        if beyond[k] > tol:
            yield rule_.finding(
                f"road {road.id}: the temporary layer's {name} lanes (lane section s={metres(section.s)}) reach "
                f"{beyond[k]:.3g} m further out than the permanent layer's at s={metres(float(s[k]))}; the temporary "
                "lanes' widths and lane offset must keep them on the permanent lanes",
                road=road.id,
                section_s=section.s,
                s=float(s[k]),
                line=section.line or None,
            )
