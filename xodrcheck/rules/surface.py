"""Road surfaces: OpenCRG references (10.6, 12.12) and cross section surfaces (10.5.4, OpenDRIVE 1.8):
``U001``-``U003`` and ``U010``-``U012``. XML only: the CRG files themselves are outside the map.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from lxml import etree

from xodrcheck.findings import Category, Severity
from xodrcheck.rules import feature_uids as U
from xodrcheck.rules.context import Context
from xodrcheck.rules.registry import rule
from xodrcheck.support.quantities import metres
from xodrcheck.xmlvalues import local

_POLYNOMIALS = ("width", "constant", "linear", "quadratic", "cubic")


def _number(el: etree._Element, name: str) -> float | None:
    try:
        value = float(el.get(name))
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def _crg_owners(ctx: Context) -> Iterator[tuple[str, str, list[etree._Element]]]:
    """(``"road"`` or ``"junction"``, its id, its ``<CRG>`` elements) for every owner with some."""
    if ctx.tree is None or (ctx.data is not None and b"CRG" not in ctx.data):
        return
    for owner in ctx.tree.getroot():
        kind = local(owner)
        if kind not in ("road", "junction"):
            continue
        crgs = [crg for surface in owner.iterchildren("{*}surface") for crg in surface.iterchildren("{*}CRG")]
        if crgs:
            yield kind, owner.get("id", "?"), crgs


def _crg_problems(crg: etree._Element) -> Iterator[tuple[str, str]]:
    """(UID, what is wrong) for one ``<CRG>``'s attributes."""
    mode, purpose = crg.get("mode"), crg.get("purpose", "elevation")
    if mode == "attached" and purpose == "friction":
        yield U.CRG_ATTACH_FRICTION, 'mode="attached" adds to the road\'s height and cannot carry friction values'
    if purpose == "friction":
        given = [name for name in ("zOffset", "zScale") if crg.get(name) is not None]
        if given:
            yield U.CRG_FRICTION_Z, f"friction values take no {' or '.join(given)} (only elevation data is scaled)"
    if crg.get("hOffset") is not None and mode not in ("genuine", "global"):
        yield U.CRG_H_OFFSET, f"hOffset is for modes genuine and global only, not mode={mode!r}"
    if crg.get("orientation") == "opposite" and mode not in ("attached", "attached0"):
        yield U.CRG_NO_OPPOSITE, f'orientation="opposite" is for modes attached and attached0 only, not mode={mode!r}'
    if mode == "global":
        given = [name for name in ("sOffset", "tOffset") if crg.get(name) is not None]
        if given:
            yield (
                U.CRG_ST_OFFSET_GLOBAL,
                f'mode="global" places the data by x/y/z/hOffset; it takes no {" or ".join(given)}',
            )


@rule(
    "U001",
    "crg-attribute-for-mode",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.CRG_ATTACH_FRICTION, U.CRG_FRICTION_Z, U.CRG_H_OFFSET, U.CRG_NO_OPPOSITE, U.CRG_ST_OFFSET_GLOBAL),
    xml=True,
)
def crg_attribute_for_mode(ctx: Context):
    """A ``<CRG>`` uses an attribute its mode or purpose does not allow.

    10.6 (Annex F ``road.crg``): ``mode="attached"`` is not used with ``purpose="friction"``
    (``attach_vs_friction``); friction data takes no ``zOffset``/``zScale`` (``friction_no_z_offset_scale``);
    ``hOffset`` only with modes genuine and global (``h_offset_only_genuine_global``, 1.9); ``orientation="opposite"``
    only with modes attached and attached0 (``no_opposite``); ``sOffset``/``tOffset`` not with mode global
    (``s_t_offset_no_global``).

    Passes::

        <CRG file="cobbles.crg" sStart="0" sEnd="100" orientation="same" mode="attached" tOffset="0.5"/>

    Fails::

        <CRG file="mu.crg" sStart="0" sEnd="100" orientation="same" mode="attached" purpose="friction"/>
    """
    for kind, owner_id, crgs in _crg_owners(ctx):
        for crg in crgs:
            for uid, why in _crg_problems(crg):
                yield crg_attribute_for_mode.finding(
                    f"<CRG file={crg.get('file')!r}> of {kind} {owner_id}: {why}",
                    uid=uid,
                    road=owner_id if kind == "road" else None,
                    line=crg.sourceline,
                )


@rule("U002", "crg-junction-and-connecting-road", Category.SURFACE, Severity.ERROR, uids=(U.CRG_JUNCTION,), xml=True)
def crg_junction_and_connecting_road(ctx: Context):
    """A junction and one of its connecting roads both have ``<CRG>`` data.

    If a ``<junction>`` contains a ``<CRG>``, none of its connecting roads shall have one (Annex F
    ``road.crg.junction``, 10.6, 12.12): the junction's surface supersedes theirs, so theirs would be ignored.

    Passes::

        <junction id="10"><surface><CRG .../></surface></junction>  <!-- its roads have no <surface> -->

    Fails::

        <road id="3" junction="10"><surface><CRG .../></surface></road> ... <junction id="10"><surface><CRG .../>
    """
    owners = list(_crg_owners(ctx))
    junctions = {owner_id: crgs[0] for kind, owner_id, crgs in owners if kind == "junction"}
    if not junctions:
        return
    for kind, owner_id, crgs in owners:
        road = ctx.road(owner_id) if kind == "road" else None
        if road is None or road.junction not in junctions:
            continue
        yield crg_junction_and_connecting_road.finding(
            f"road {owner_id} has <CRG> data but belongs to junction {road.junction}, whose own <CRG> (line "
            f"{junctions[road.junction].sourceline}) covers it: remove one of them",
            road=owner_id,
            line=crgs[0].sourceline,
        )


@rule("U003", "crg-overlap", Category.SURFACE, Severity.WARNING, uids=(U.CRG_ONE_PER_S,), xml=True)
def crg_overlap(ctx: Context):
    """Two ``<CRG>`` entries of one road or junction with the same purpose overlap in ``s``.

    Each road or junction should contain only one CRG file per ``s``-position and purpose (Annex F
    ``road.crg.only_on_per_s``, 10.6): today the last entry wins (``use_last_entry``), future versions may combine
    them.

    Passes::

        <CRG file="a.crg" sStart="0" sEnd="50" .../><CRG file="b.crg" sStart="50" sEnd="100" .../>

    Fails::

        <CRG file="a.crg" sStart="0" sEnd="60" .../><CRG file="b.crg" sStart="40" sEnd="100" .../>
    """
    for kind, owner_id, crgs in _crg_owners(ctx):
        spans = []
        for crg in crgs:
            start, end = _number(crg, "sStart"), _number(crg, "sEnd")
            if start is not None and end is not None:
                spans.append((min(start, end), max(start, end), crg.get("purpose", "elevation"), crg))
        for i, (a0, a1, purpose, a) in enumerate(spans):
            for b0, b1, other, b in spans[i + 1 :]:
                if purpose == other and min(a1, b1) - max(a0, b0) > ctx.tolerances.position:
                    yield crg_overlap.finding(
                        f"<CRG file={b.get('file')!r}> of {kind} {owner_id} overlaps <CRG file={a.get('file')!r}> "
                        f"(line {a.sourceline}) from s={metres(max(a0, b0))} to {metres(min(a1, b1))} for purpose "
                        f"{purpose}: give one CRG file per position and purpose",
                        road=owner_id if kind == "road" else None,
                        s=max(a0, b0) if kind == "road" else None,
                        line=b.sourceline,
                    )


def _surfaces(ctx: Context) -> Iterator[tuple[etree._Element, etree._Element]]:
    """(road element, its ``<crossSectionSurface>``) for every road with one."""
    if ctx.tree is None or (ctx.data is not None and b"crossSectionSurface" not in ctx.data):
        return
    for road in ctx.tree.getroot().iterchildren("{*}road"):
        for profile in road.iterchildren("{*}lateralProfile"):
            for surface in profile.iterchildren("{*}crossSectionSurface"):
                yield road, surface


@rule(
    "U010",
    "cross-section-surface-with-shape",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.SURFACE_NO_SHAPE,),
    xml=True,
)
def cross_section_surface_with_shape(ctx: Context):
    """A road has a cross section surface and also ``<shape>`` or ``<superelevation>`` records.

    A cross section surface shall not be used in combination with road shape or superelevation (Annex F
    ``road.cross_section_surface.no_shape_superelevation``, 10.5.4): it describes the whole lateral profile itself.

    Passes::

        <lateralProfile><crossSectionSurface>...</crossSectionSurface></lateralProfile>

    Fails::

        <lateralProfile><superelevation s="0" a="0.02" .../><crossSectionSurface>...</crossSectionSurface>
    """
    for road, surface in _surfaces(ctx):
        profile = surface.getparent()
        others = [el for el in profile if local(el) in ("shape", "superelevation")]
        if others:
            names = sorted({local(el) for el in others})
            yield cross_section_surface_with_shape.finding(
                f"road {road.get('id')} has a <crossSectionSurface> and {len(others)} "
                f"<{'>/<'.join(names)}> record(s) (first at line {others[0].sourceline}): the cross section surface "
                "replaces them; remove one description",
                road=road.get("id"),
                line=surface.sourceline,
            )


@rule(
    "U011",
    "cross-section-surface-extent",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.SURFACE_START_END,),
    xml=True,
)
def cross_section_surface_extent(ctx: Context):
    """A cross section surface's polynomials do not start at the road's start, or start beyond its end.

    A cross section surface shall start and end at the start and end of the road reference line (Annex F
    ``road.cross_section_surface.start_end_match_with_refline``, 10.5.4): the first ``<coefficients>`` of its
    ``<tOffset>`` and of each strip's polynomials is at ``s="0"``, and none starts beyond the road's length.

    Passes::

        <tOffset><coefficients s="0" a="0"/><coefficients s="50" a="1"/></tOffset>   <!-- road length 100 -->

    Fails::

        <tOffset><coefficients s="10" a="0"/></tOffset>
    """
    tol = ctx.tolerances.position
    for road_el, surface in _surfaces(ctx):
        road_id = road_el.get("id")
        road = ctx.road(road_id)
        length = None if road is None else road.length
        lists = [(el, "<tOffset>") for el in surface.iterchildren("{*}tOffset")]
        for strips in surface.iterchildren("{*}surfaceStrips"):
            for strip in strips.iterchildren("{*}strip"):
                lists += [
                    (el, f"<{local(el)}> of strip {strip.get('id')}") for el in strip if local(el) in _POLYNOMIALS
                ]
        for el, what in lists:
            records = [(c, s) for c in el.iterchildren("{*}coefficients") if (s := _number(c, "s")) is not None]
            if records and abs(records[0][1]) > tol:
                yield cross_section_surface_extent.finding(
                    f"road {road_id}: the cross section surface's {what} starts at s={metres(records[0][1])}, not at "
                    'the road\'s start: its first <coefficients> shall be at s="0"',
                    road=road_id,
                    s=records[0][1],
                    line=records[0][0].sourceline,
                )
            beyond = [(c, s) for c, s in records if length is not None and s > length + tol]
            if beyond:
                c, s = beyond[0]
                yield cross_section_surface_extent.finding(
                    f"road {road_id}: the cross section surface's {what} has <coefficients> from s={metres(s)}, beyond "
                    f"the road's end (length {metres(length)}): the surface ends with the road",
                    road=road_id,
                    line=c.sourceline,
                )


@rule(
    "U012",
    "cross-section-surface-strips",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.SURFACE_USE_STRIP, U.SURFACE_USE_WIDTH),
    xml=True,
)
def cross_section_surface_strips(ctx: Context):
    """A side of a cross section surface uses its strips wrongly.

    On each side there are one or two strips (10.5.4): one strip alone has ``id="1"`` (left) or ``id="-1"``
    (right) and no ``<width>``: it reaches the outer edge of the lanes (Annex F
    ``road.cross_section_surface.use_strip``); with two strips the inner one (``1``/``-1``) gives its ``<width>``,
    where the outer one (``2``/``-2``) starts (``use_width``).

    Passes::

        <strip id="1"><width>...</width><constant>...</constant></strip><strip id="2"><constant>...</constant></strip>

    Fails::

        <strip id="-1"><width>...</width><constant>...</constant></strip>   <!-- the only strip on the right -->
    """
    for road_el, surface in _surfaces(ctx):
        road_id = road_el.get("id")
        strips = [s for group in surface.iterchildren("{*}surfaceStrips") for s in group.iterchildren("{*}strip")]
        for sign, side in ((1, "left"), (-1, "right")):
            mine = [s for s in strips if (_int(s.get("id")) or 0) * sign > 0]
            has_width = {id(s): any(local(el) == "width" for el in s) for s in mine}
            if len(mine) == 1:
                (strip,) = mine
                wrong = [f"id {strip.get('id')} instead of {sign}"] if _int(strip.get("id")) != sign else []
                wrong += ["a <width>"] if has_width[id(strip)] else []
                if wrong:
                    yield cross_section_surface_strips.finding(
                        f"road {road_id}: the only strip on the {side} has {' and '.join(wrong)}: a single strip has "
                        f'id="{sign}" and no width (it reaches the outer edge of the {side} lanes)',
                        uid=U.SURFACE_USE_STRIP,
                        road=road_id,
                        line=strip.sourceline,
                    )
            elif len(mine) == 2:
                inner = [s for s in mine if _int(s.get("id")) == sign]
                if inner and not has_width[id(inner[0])]:
                    yield cross_section_surface_strips.finding(
                        f"road {road_id}: the inner {side} strip (id {sign}) has no <width>, so it is not known where "
                        f"the outer strip starts: give the inner strip's width",
                        uid=U.SURFACE_USE_WIDTH,
                        road=road_id,
                        line=inner[0].sourceline,
                    )


def _int(raw: str | None) -> int | None:
    if raw is None:
        return None
    try:
        return int(raw)
    except (TypeError, ValueError):
        return None
