"""Unsafe fixes of the plan view (``G001``, ``G006``): they move geometry, by at most the bound each states, and say
by how much."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.findings import Finding
from xodrcheck.fix.edits import Edit, remove_element, set_attribute
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element
from xodrcheck.model import Geometry, Line, Road


def _number(value: float) -> str:
    """The shortest spelling that reads back as ``value``."""
    return repr(float(value))


def _elements(ws: Workspace, road: Road) -> list[tuple[Geometry, Element]] | None:
    """The road's plan-view records with their ``<geometry>`` elements, in file order (``None`` when they do not
    pair up)."""
    element = ws.road_element(road)
    views = element.findall("planView") if element is not None else []
    if len(views) != 1:
        return None
    found = views[0].findall("geometry")
    if len(found) != len(road.plan_view) or any(e.line != g.line for e, g in zip(found, road.plan_view)):
        return None
    return list(zip(road.plan_view, found))


def _record_at(ws: Workspace, finding: Finding) -> tuple[Road, list[tuple[Geometry, Element]], int] | None:
    road = ws.road(finding.road)
    pairs = _elements(ws, road) if road is not None else None
    if road is None or pairs is None:
        return None
    index = [k for k, (g, _) in enumerate(pairs) if g.line == finding.line and g.s == finding.s]
    return (road, pairs, index[0]) if len(index) == 1 else None


def _end(ws: Workspace, road: Road, g: Geometry) -> tuple[float, float]:
    from xodrcheck.geometry.planview import evaluate_element

    pose = evaluate_element(g, np.array([g.length]))
    return float(pose.x[0]), float(pose.y[0])


def snap_bound(ws: Workspace) -> float:
    """How far a snap may move geometry: the ``gap`` tolerance, and never less than its default (1 cm), so that the
    strict profile, which grades gaps over 1 mm as errors, does not also forbid closing them."""
    return max(ws.tolerances.gap, Tolerances.gap)


@fixer("G001", "snap-plan-view-gap", safe=False, bound="moves part of a road by up to `gap` (1 cm)")
def snap_plan_view_gap(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Closes a plan-view gap of up to the ``gap`` tolerance (1 cm; more when it is set higher) by moving the element
    after it, and every element after that on the road, by the gap (their ``x`` and ``y``; headings, lengths and
    shapes kept), so that no other joint opens.

    That part of the road and everything placed along it (lanes, objects) moves by the gap, at most ``gap``, and so
    does the road's end; the repair says by how much. Larger gaps are left: closing them is a design decision.
    """
    for finding in findings:
        found = _record_at(ws, finding)
        if found is None:
            continue
        road, pairs, k = found
        if k == 0:
            continue
        before, g = pairs[k - 1][0], pairs[k][0]
        x, y = _end(ws, road, before)
        dx, dy = x - g.x, y - g.y
        moved = math.hypot(dx, dy)
        if not math.isfinite(moved) or moved > snap_bound(ws):
            yield Skip(finding, f"the gap is {moved:.4g} m, over the gap tolerance ({snap_bound(ws):g} m)")
            continue
        edits = tuple(
            edit
            for later, element in pairs[k:]
            for edit in (
                set_attribute(ws.text, element, "x", _number(later.x + dx)),
                set_attribute(ws.text, element, "y", _number(later.y + dy)),
            )
        )
        view = pairs[k][1].parent
        scope = (view.start, view.end) if view is not None else None
        action = f"road {road.id}: moved the elements from s={g.s:g} on onto the previous one's end"
        yield Repair((finding,), edits, action, moved, scope)


@fixer("G006", "remove-zero-length-geometry", safe=False, bound="moves the reference line by up to the removed length")
def remove_zero_length_geometry(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Removes a plan-view element shorter than ``length_abs`` (or of length 0), lengthening the previous element by
    what it covered so that ``s`` runs on; a first element is removed only when the next is a line, which is drawn
    back over the same stretch.

    The reference line there moves by at most the removed length (a few micrometres on the corpus); the repair says
    by how much. Negative lengths are left: what they mean is unclear.
    """
    for finding in findings:
        found = _record_at(ws, finding)
        if found is None or len(found[1]) < 2:
            continue
        road, pairs, k = found
        g, element = pairs[k]
        if not 0 <= g.length < ws.tolerances.length_abs:
            yield Skip(finding, "its length is negative or not small")
            continue
        moved = g.length
        edits: tuple[Edit, ...]
        if k > 0:
            before, before_element = pairs[k - 1]
            edits = (
                remove_element(ws.text, element),
                set_attribute(ws.text, before_element, "length", _number(before.length + g.length)),
            )
        else:
            after, after_element = pairs[1]
            if not isinstance(after, Line):
                yield Skip(finding, "it is the first element and the next is not a line")
                continue
            x, y = after.x - g.length * math.cos(after.hdg), after.y - g.length * math.sin(after.hdg)
            edits = (
                remove_element(ws.text, element),
                set_attribute(ws.text, after_element, "s", _number(g.s)),
                set_attribute(ws.text, after_element, "x", _number(x)),
                set_attribute(ws.text, after_element, "y", _number(y)),
                set_attribute(ws.text, after_element, "length", _number(after.length + g.length)),
            )
            moved = max(g.length, math.hypot(x - g.x, y - g.y))
        view = element.parent
        scope = (view.start, view.end) if view is not None else None
        action = f"road {road.id}: removed the {g.length:.3g} m element at s={g.s:g}"
        yield Repair((finding,), edits, action, moved, scope)
