"""Road types, country codes, lateral shapes and the elevation profile's extent (``G052``-``G059``).

Read from the document: a road's types, shapes and the country codes of its types, signals and signs. Each rule
enforces a rule of ASAM OpenDRIVE 1.9.0 Annex F, named in its docstring.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Iterator

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.model import Road, Shape
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.sampled import section_lines
from xodrcheck.support.quantities import metres

_ALPHA_2 = re.compile(r"[A-Z]{2}")


@rule("G052", "road-type-out-of-order", Category.GEOMETRY, Severity.ERROR, uids=(U.TYPE_ORDER,))
def road_type_out_of_order(ctx: Context):
    """A road's ``<type>`` records are not in ascending order of ``s``.

    A road type holds from its ``s`` until the next ``<type>``; readers that take the records in file order and
    readers that sort them disagree about which type applies where (Annex F ``road.type.elem_asc_order``, 10.4).
    Reported at the first record that starts before its predecessor.

    Passes::

        <type s="0" type="town"/><type s="50" type="rural"/>

    Fails::

        <type s="50" type="rural"/><type s="0" type="town"/>
    """
    for road in ctx.document.roads:
        for prev, nxt in itertools.pairwise(t for t in road.types if t.s is not None):
            if nxt.s is not None and prev.s is not None and nxt.s < prev.s:  # (both are: filtered above)
                yield road_type_out_of_order.finding(
                    f"road {road.id}: the <type> at line {nxt.line} starts at s={metres(nxt.s)}, before the one at "
                    f"line {prev.line} (s={metres(prev.s)}); write the road's types in ascending order of s",
                    road=road.id,
                    s=nxt.s,
                    line=nxt.line,
                )
                break


@rule("G053", "country-code-not-alpha2", Category.GEOMETRY, Severity.ERROR, uids=(U.TYPE_ALPHA_2,))
def country_code_not_alpha2(ctx: Context):
    """A ``country`` attribute is not an ISO 3166-1 ALPHA-2 code (two capital letters).

    Only ALPHA-2 codes may be used, not ALPHA-3 codes, because only ALPHA-2 codes take the ISO 3166-2 state
    identifiers (Annex F ``road.type.only_alpha_2_country_codes``, 10.4). The schema still admits the deprecated
    ALPHA-3 codes and country names (``USA``, ``Germany``); this rule does not. Every ``country`` is checked: of road
    types, signals and the signs of static boards alike, except that a signal's (or a sign's) ``country="OpenDRIVE"``
    names the types of the OpenDRIVE signal reference (traffic lights and the like, 14.1).

    Passes::

        <type s="0" type="town" country="DE"/>

    Fails (an ALPHA-3 code)::

        <type s="0" type="town" country="DEU"/>
    """
    for road in ctx.document.roads:
        for tag, line, code in _countries(road):
            if _ALPHA_2.fullmatch(code) or (code == "OpenDRIVE" and tag != "type"):
                continue
            yield country_code_not_alpha2.finding(
                f'{f"road {road.id}: " if road.id else ""}the <{tag}> at line {line} has country="{code}", '
                f'{_what_code(code)}; use the ISO 3166-1 ALPHA-2 code (two capital letters, e.g. "DE")',
                road=road.id,
                line=line,
            )


def _countries(road: Road) -> Iterator[tuple[str, int, str]]:
    """The tag, line and ``country`` of every element of ``road`` that gives one: its types, signals and signs."""
    for record in road.types:
        if record.country is not None:
            yield "type", record.line, record.country
    for signal in road.signals:
        if signal.country is not None:
            yield "signal", signal.line, signal.country
        for sign in signal.signs:
            if sign.country is not None:
                yield "sign", sign.line, sign.country


def _what_code(code: str) -> str:
    if re.fullmatch(r"[A-Za-z]{3}", code):
        return "an ALPHA-3 code"
    if re.fullmatch(r"[A-Za-z]{2}", code):
        return f'not in capitals (write "{code.upper()}")'
    return "not a country code" if code.strip() else "empty"


@rule("G054", "shape-out-of-order", Category.GEOMETRY, Severity.ERROR, uids=(U.SHAPE_ORDER,))
def shape_out_of_order(ctx: Context):
    """A road's ``<shape>`` records are not in ascending order, first of ``s``, then of ``t``.

    The shapes at one ``s`` describe the cross section from right to left, each from its ``t`` to the next one's; out
    of order, readers disagree about which polynomial applies where (Annex F ``road.shape.elem_asc_order``, 10.5.3).
    Reported at the first record that comes before its predecessor.

    Passes::

        <shape s="0" t="-4" .../><shape s="0" t="0" .../><shape s="50" t="-4" .../>

    Fails (``t`` descending at s=0)::

        <shape s="0" t="0" .../><shape s="0" t="-4" .../>
    """
    for road in ctx.document.roads:
        shapes = [sh for sh in road.shapes if sh.s is not None and sh.t is not None]
        for prev, nxt in itertools.pairwise(shapes):
            if (nxt.s, nxt.t) < (prev.s, prev.t):
                which = "s" if nxt.s != prev.s else f"t at s={metres(nxt.s)}"
                yield shape_out_of_order.finding(
                    f"road {road.id}: the <shape> at line {nxt.line} (s={metres(nxt.s)}, t={metres(nxt.t)}) comes "
                    f"after the one at line {prev.line} (s={metres(prev.s)}, t={metres(prev.t)}): {which} descends; "
                    "order the shapes by s, then by t",
                    road=road.id,
                    s=nxt.s,
                    line=nxt.line,
                )
                break


def shape_groups(shapes: tuple[Shape, ...]) -> Iterator[tuple[float, list[Shape]]]:
    """The shapes of each ``s`` (with a valid ``s`` and ``t``), ordered by ``t``, in order of first appearance."""
    groups: dict[float, list[Shape]] = {}
    for sh in shapes:
        if sh.s is not None and sh.t is not None:
            groups.setdefault(sh.s, []).append(sh)
    for s, group in groups.items():
        yield s, sorted(group, key=_t)


def _t(shape: Shape) -> float:
    return math.nan if shape.t is None else shape.t  # (never NaN here: shape_groups keeps shapes with a t)


def _right_edge(ctx: Context, road: Road) -> tuple[float, float] | None:
    """The smallest ``t`` any lane border of the road reaches (its right edge at its widest), and where (``s``)."""
    if ctx.usable_geometry(road) is None:
        return None
    best: tuple[float, float] | None = None
    for index in range(len(road.lane_sections)):
        lines = section_lines(ctx, road, index)
        t = np.min(np.vstack(list(lines.t.values())), axis=0)
        k = int(np.argmin(t))
        if math.isfinite(t[k]) and (best is None or t[k] < best[0]):
            best = (float(t[k]), float(lines.s[k]))
    return best


@rule("G055", "shape-t-coverage", Category.GEOMETRY, Severity.ERROR, uids=(U.SHAPE_T_COVERAGE,))
def shape_t_coverage(ctx: Context):
    """The ``<shape>`` records at some ``s`` do not cover the road's full width: the first starts left of the road's
    right edge.

    At every ``s`` the t-definition has to cover the maximum width of the entire road (Annex F
    ``road.shape.t_definition_coverage``, 10.5.3, Figure 45): the shapes at one ``s`` run from the first one's ``t``
    leftwards, the last one to the road's left edge, so the first must start at or right of the smallest ``t`` any
    lane border of the road reaches, anywhere along it (within the ``position`` tolerance). Heights between two
    profiles are interpolated, so a profile that starts too far left leaves part of the road without a height.

    Passes (lanes -1 and -2 reach t = -7)::

        <shape s="0" t="-7" a="0" b="0.02" c="0" d="0"/>

    Fails (the shapes start at t = -3.5)::

        <shape s="0" t="-3.5" a="0" b="0.02" c="0" d="0"/>
    """
    tol = ctx.tolerances.position
    for road in ctx.document.roads:
        if not road.shapes:
            continue
        edge = _right_edge(ctx, road)
        if edge is None:
            continue
        t_edge, s_edge = edge
        geometry = ctx.geometry(road.id)
        for s, group in shape_groups(road.shapes):
            t_first = group[0].t
            if geometry is not None and t_first is not None and t_first > t_edge + tol:
                first = group[0]
                pose = geometry.reference(np.array([s]))
                yield shape_t_coverage.finding(
                    f"road {road.id}: the shapes at s={metres(s)} start at t={metres(t_first)}, but the road "
                    f"reaches t={t_edge:.4g} (at s={s_edge:.4g}): the lateral profile leaves {t_first - t_edge:.4g} m "
                    f"of the road's width uncovered; start the first shape at t <= {t_edge:.4g}",
                    road=road.id,
                    s=s,
                    x=float(pose.x[0]),
                    y=float(pose.y[0]),
                    line=first.line,
                )


@rule("G056", "shapes-start-left", Category.GEOMETRY, Severity.ERROR, uids=(U.SHAPES_START_RIGHT,))
def shapes_start_left(ctx: Context):
    """The ``<shape>`` records at some ``s`` do not start at the right side of the road: the first ``t`` is not
    negative.

    To model road shapes, shape elements shall start at the right side of the road and run in positive t-direction,
    that is, start with negative t-values (Annex F ``road.use_cases.shape_elements_start_right``, 1.9). Whether they
    reach the right edge is ``shape-t-coverage``'s.

    Passes::

        <shape s="0" t="-5" a="0" b="-0.02" c="0" d="0"/><shape s="0" t="0" a="-0.1" b="0.02" c="0" d="0"/>

    Fails (the profile at s=0 starts on the reference line)::

        <shape s="0" t="0" a="-0.1" b="0.02" c="0" d="0"/><shape s="0" t="3.5" a="-0.03" b="-0.02" c="0" d="0"/>
    """
    for road in ctx.document.roads:
        for s, group in shape_groups(road.shapes):
            first = group[0]
            if first.t is not None and first.t >= 0:  # (it has a t: shape_groups keeps those only)
                yield shapes_start_left.finding(
                    f"road {road.id}: the shapes at s={metres(s)} start at t={metres(first.t)}: shapes start at "
                    "the right side of the road (a negative t) and run leftwards; add a shape at the right edge",
                    road=road.id,
                    s=s,
                    line=first.line,
                )


@rule(
    "G057",
    "elevation-beyond-road",
    Category.GEOMETRY,
    Severity.ERROR,
    uids=(U.ELEVATION_ALONG_REF_LINE,),
    every_version=True,
)
def elevation_beyond_road(ctx: Context):
    """An ``<elevation>`` record starts beyond the end of the road's reference line.

    Roads are elevated along their reference line (Annex F ``road.elevation.elev_along_ref_line``, 10.5.1): each
    record gives the height from its ``s`` on, along the reference line, which ends at the road's ``length``. A record
    that starts past it (by more than ``length_abs``) elevates no part of the road: its ``s`` is wrong (often that of
    another road, or in the wrong unit) and the heights it was meant to give are missing.

    Passes (road length 100)::

        <elevation s="0" a="0" b="0.01" c="0" d="0"/><elevation s="60" a="0.6" b="0" c="0" d="0"/>

    Fails::

        <elevation s="0" a="0" b="0.01" c="0" d="0"/><elevation s="160" a="1.6" b="0" c="0" d="0"/>
    """
    tol = ctx.tolerances.length_abs
    for road in ctx.document.roads:
        if not math.isfinite(road.length):
            continue
        for record in road.elevation:
            if record.s > road.length + tol:
                yield elevation_beyond_road.finding(
                    f"road {road.id}: the <elevation> at s={metres(record.s)} starts beyond the end of the road's "
                    f"reference line (length {metres(road.length)}): it elevates no part of the road; fix its s",
                    road=road.id,
                    s=record.s,
                    line=record.line or road.line or None,
                )
