"""Variable message boards and the gantries they hang on (14.7.4, 13.14.4): ``T008``.

A file does not say which gantry a board is on; here a board's gantry is the ``<object type="gantry">`` whose
bounding box (``length`` along the object's heading, ``width`` across it, centred on the object's ``s``/``t``, widened
by the ``gantry_reach`` tolerance) holds the position of the board's signal. Boards outside every gantry's box are
left out.
"""

from __future__ import annotations

import math

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import feature_uids as U
from xodrcheck.rules.shared.context import Context

_LEFT_OUT = (
    "boards are placed on the gantry object whose bounding box (length x width around its s/t, plus gantry_reach) "
    "holds their signal's s/t; boards outside every gantry's box, and gantries without length and width, are not "
    "checked"
)


def _place(ctx: Context, road_id: str, s: float, t: float) -> tuple[float, float, float] | None:
    """Inertial x, y and the reference line's heading at ``s``, ``t`` of a road (``None`` when unknown)."""
    geometry = ctx.geometry(road_id)
    if geometry is None or not geometry.road.plan_view:
        return None
    with np.errstate(all="ignore"):
        pose = geometry.reference(np.array([float(s)]))
    x, y, hdg = float(pose.x[0]), float(pose.y[0]), float(pose.hdg[0])
    if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(hdg)):
        return None
    return x - t * math.sin(hdg), y + t * math.cos(hdg), hdg


def _gantry_boxes(ctx: Context) -> list[tuple[str, float, float, float, float, float, str, int | None]]:
    """(gantry id, centre x, centre y, heading, half length, half width, road, line) of every gantry with a bounding
    box."""
    reach = ctx.tolerances.gantry_reach
    out = []
    for road in ctx.document.roads:
        road_id = road.id
        for obj in road.objects:
            s, t, length, width = obj.s, obj.t, obj.length, obj.width
            if obj.type != "gantry" or s is None or t is None or length is None or width is None:
                continue
            placed = _place(ctx, road_id, s, t)
            if placed is None:
                continue
            x, y, hdg = placed
            half_l, half_w = length / 2 + reach, width / 2 + reach
            out.append((obj.id, x, y, hdg + (obj.hdg or 0.0), half_l, half_w, road_id, obj.line or None))
    return out


def _gantry_of(boxes, x: float, y: float) -> str | None:
    for gantry, cx, cy, hdg, half_l, half_w, _, _ in boxes:
        du, dv = x - cx, y - cy
        u = du * math.cos(hdg) + dv * math.sin(hdg)
        v = -du * math.sin(hdg) + dv * math.cos(hdg)
        if abs(u) <= half_l and abs(v) <= half_w:
            return gantry
    return None


@rule(
    "T008",
    "vms-boards-gantry",
    Category.SIGNAL,
    Severity.ERROR,
    partial={U.GANTRY_SAME: _LEFT_OUT, U.GANTRY_VMS_GROUP: _LEFT_OUT},
)
def vms_boards_gantry(ctx: Context):
    """A ``<vmsGroup>`` lists boards of different gantries, or a gantry's boards are not in exactly one group.

    Variable message boards on the same gantry are grouped in a ``<vmsGroup>`` (14.7.4): all boards of one group
    shall belong to the same gantry (Annex F ``road.signal.gantry.all_variable_boards_same_gantry``), and each gantry
    shall have one ``<vmsGroup>`` with at least one ``<vmsBoardReference>``
    (``gantry.vmsgroup_at_least_one_reference``). A board's gantry is the ``<object type="gantry">`` whose bounding
    box holds the board's signal (see the module documentation).

    Passes::

        <object id="g1" type="gantry" s="25" t="0" length="0.5" width="8" .../>
        <signal id="30" s="25" t="-2" type="vmsBoard" ...>  <vmsGroup id="1"><vmsBoardReference signalId="30" .../>

    Fails::

        <object id="g1" type="gantry" s="25" .../> <object id="g2" type="gantry" s="75" .../>
        <vmsGroup id="1"><vmsBoardReference signalId="30" .../><vmsBoardReference signalId="40" .../></vmsGroup>
    """
    document = ctx.document
    boxes = _gantry_boxes(ctx)
    if not boxes:
        return
    on: dict[str, str] = {}  # board signal id -> gantry id
    for signal in (signal for road in document.roads for signal in road.signals):
        if signal.vms_boards and signal.id is not None and signal.s is not None and signal.t is not None:
            placed = _place(ctx, signal.road, signal.s, signal.t)
            gantry = None if placed is None else _gantry_of(boxes, placed[0], placed[1])
            if gantry is not None:
                on[signal.id] = gantry
    groups_of: dict[str, list[str]] = {}
    for group in document.vms_groups:
        gantries = {on[r.signal_id]: r.signal_id for r in group.references if r.signal_id in on}
        for gantry in gantries:
            groups_of.setdefault(gantry, []).append(str(group.id))
        if len(gantries) > 1:
            listed = ", ".join(f"board {board} on gantry {gantry}" for gantry, board in sorted(gantries.items()))
            yield vms_boards_gantry.finding(
                f"vmsGroup {group.id!r} lists boards of {len(gantries)} gantries ({listed}): a group holds the boards "
                "of one gantry; give each gantry its own <vmsGroup>",
                uid=U.GANTRY_SAME,
                line=group.line or None,
            )
    where = {box[0]: (box[6], box[7]) for box in boxes}
    for gantry in dict.fromkeys(on.values()):
        boards = sorted(board for board, g in on.items() if g == gantry)
        groups = groups_of.get(gantry, [])
        if len(groups) != 1:
            why = (
                "no <vmsGroup> lists them" if not groups else f"{len(groups)} vmsGroups list them ({', '.join(groups)})"
            )
            yield vms_boards_gantry.finding(
                f"gantry {gantry} carries variable message boards {', '.join(boards)} but {why}: each gantry has one "
                "<vmsGroup> with a <vmsBoardReference> per board",
                uid=U.GANTRY_VMS_GROUP,
                road=where[gantry][0],
                line=where[gantry][1],
            )
