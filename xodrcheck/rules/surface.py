"""Road surfaces: OpenCRG references (10.6, 12.12) and cross section surfaces (10.5.4, OpenDRIVE 1.8):
``U001``-``U003`` and ``U010``-``U012``. XML only: the CRG files themselves are outside the map.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from xodrcheck.findings import Category, Severity
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import feature_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover - the model's surface module loads for a file with surfaces
    from xodrcheck.model import CrossSectionSurface, Road, SurfaceCrg, SurfaceStrip

_POLYNOMIALS = ("width", "constant", "linear", "quadratic", "cubic")


def _written(record: Any, name: str, attribute: str) -> str | None:
    """An enumerated attribute as the file wrote it (``None``: absent)."""
    value = getattr(record, name)
    return record.xml.text(attribute) if value is None else value.value


def _crg_owners(ctx: Context) -> Iterator[tuple[str, str, tuple[SurfaceCrg, ...]]]:
    """(``"road"`` or ``"junction"``, its id, its ``<CRG>`` records) for every owner with some."""
    for road in ctx.document.roads:
        if road.surface is not None and road.surface.crgs:
            yield "road", road.id, road.surface.crgs
    for junction in ctx.document.junctions:
        if junction.surface is not None and junction.surface.crgs:
            yield "junction", junction.id, junction.surface.crgs


def _crg_problems(crg: SurfaceCrg) -> Iterator[tuple[str, str]]:
    """(UID, what is wrong) for one ``<CRG>``'s attributes."""
    mode, purpose = _written(crg, "mode", "mode"), _written(crg, "purpose", "purpose")
    purpose = "elevation" if purpose is None else purpose
    given = crg.xml.given
    if mode == "attached" and purpose == "friction":
        yield U.CRG_ATTACH_FRICTION, 'mode="attached" adds to the road\'s height and cannot carry friction values'
    if purpose == "friction":
        scaled = [name for name in ("zOffset", "zScale") if given(name)]
        if scaled:
            yield U.CRG_FRICTION_Z, f"friction values take no {' or '.join(scaled)} (only elevation data is scaled)"
    if given("hOffset") and mode not in ("genuine", "global"):
        yield U.CRG_H_OFFSET, f"hOffset is for modes genuine and global only, not mode={mode!r}"
    if _written(crg, "orientation", "orientation") == "opposite" and mode not in ("attached", "attached0"):
        yield U.CRG_NO_OPPOSITE, f'orientation="opposite" is for modes attached and attached0 only, not mode={mode!r}'
    if mode == "global":
        placed = [name for name in ("sOffset", "tOffset") if given(name)]
        if placed:
            yield (
                U.CRG_ST_OFFSET_GLOBAL,
                f'mode="global" places the data by x/y/z/hOffset; it takes no {" or ".join(placed)}',
            )


@rule(
    "U001",
    "crg-attribute-for-mode",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.CRG_ATTACH_FRICTION, U.CRG_FRICTION_Z, U.CRG_H_OFFSET, U.CRG_NO_OPPOSITE, U.CRG_ST_OFFSET_GLOBAL),
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
                    f"<CRG file={crg.file!r}> of {kind} {owner_id}: {why}",
                    uid=uid,
                    road=owner_id if kind == "road" else None,
                    line=crg.line or None,
                )


@rule("U002", "crg-junction-and-connecting-road", Category.SURFACE, Severity.ERROR, uids=(U.CRG_JUNCTION,))
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
            f"{junctions[road.junction].line or None}) covers it: remove one of them",
            road=owner_id,
            line=crgs[0].line or None,
        )


@rule("U003", "crg-overlap", Category.SURFACE, Severity.WARNING, uids=(U.CRG_ONE_PER_S,))
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
            start, end = crg.s_start, crg.s_end
            if start is not None and end is not None:
                purpose = _written(crg, "purpose", "purpose")
                spans.append((min(start, end), max(start, end), "elevation" if purpose is None else purpose, crg))
        for i, (a0, a1, purpose, a) in enumerate(spans):
            for b0, b1, other, b in spans[i + 1 :]:
                if purpose == other and min(a1, b1) - max(a0, b0) > ctx.tolerances.position:
                    yield crg_overlap.finding(
                        f"<CRG file={b.file!r}> of {kind} {owner_id} overlaps <CRG file={a.file!r}> "
                        f"(line {a.line or None}) from s={metres(max(a0, b0))} to {metres(min(a1, b1))} for purpose "
                        f"{purpose}: give one CRG file per position and purpose",
                        road=owner_id if kind == "road" else None,
                        s=max(a0, b0) if kind == "road" else None,
                        line=b.line or None,
                    )


def _surfaces(ctx: Context) -> Iterator[tuple[Road, CrossSectionSurface]]:
    """(road, its cross section surface) for every road with one."""
    for road in ctx.document.roads:
        if road.cross_section_surface is not None:
            yield road, road.cross_section_surface


@rule(
    "U010",
    "cross-section-surface-with-shape",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.SURFACE_NO_SHAPE,),
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
        others = sorted(
            [(record.line, "superelevation") for record in road.superelevation]
            + [(record.line, "shape") for record in road.shapes]
        )
        if others:
            names = sorted({name for _, name in others})
            yield cross_section_surface_with_shape.finding(
                f"road {road.id} has a <crossSectionSurface> and {len(others)} "
                f"<{'>/<'.join(names)}> record(s) (first at line {others[0][0] or None}): the cross section surface "
                "replaces them; remove one description",
                road=road.id,
                line=surface.line or None,
            )


@rule(
    "U011",
    "cross-section-surface-extent",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.SURFACE_START_END,),
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
    for owner, surface in _surfaces(ctx):
        road_id = owner.id
        road = ctx.road(road_id)
        length = None if road is None else road.length
        lists = [] if surface.t_offset is None else [(surface.t_offset, "<tOffset>")]
        for strip in surface.strips:
            lists += [
                (p, f"<{p.kind}> of strip {_strip_id(strip)}") for p in strip.polynomials if p.kind in _POLYNOMIALS
            ]
        for polynomial, what in lists:
            records = [(c, c.s) for c in polynomial.coefficients if c.s is not None]
            if records and abs(records[0][1]) > tol:
                yield cross_section_surface_extent.finding(
                    f"road {road_id}: the cross section surface's {what} starts at s={metres(records[0][1])}, not at "
                    'the road\'s start: its first <coefficients> shall be at s="0"',
                    road=road_id,
                    s=records[0][1],
                    line=records[0][0].line or None,
                )
            beyond = [(c, s) for c, s in records if length is not None and s > length + tol]
            if beyond:
                c, s = beyond[0]
                yield cross_section_surface_extent.finding(
                    f"road {road_id}: the cross section surface's {what} has <coefficients> from s={metres(s)}, beyond "
                    f"the road's end (length {metres(length)}): the surface ends with the road",
                    road=road_id,
                    line=c.line or None,
                )


@rule(
    "U012",
    "cross-section-surface-strips",
    Category.SURFACE,
    Severity.ERROR,
    uids=(U.SURFACE_USE_STRIP, U.SURFACE_USE_WIDTH),
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
    for road, surface in _surfaces(ctx):
        road_id = road.id
        strips = surface.strips
        for sign, side in ((1, "left"), (-1, "right")):
            mine = [s for s in strips if (s.id or 0) * sign > 0]
            has_width = {id(s): s.polynomial("width") is not None for s in mine}
            if len(mine) == 1:
                (strip,) = mine
                wrong = [f"id {_strip_id(strip)} instead of {sign}"] if strip.id != sign else []
                wrong += ["a <width>"] if has_width[id(strip)] else []
                if wrong:
                    yield cross_section_surface_strips.finding(
                        f"road {road_id}: the only strip on the {side} has {' and '.join(wrong)}: a single strip has "
                        f'id="{sign}" and no width (it reaches the outer edge of the {side} lanes)',
                        uid=U.SURFACE_USE_STRIP,
                        road=road_id,
                        line=strip.line or None,
                    )
            elif len(mine) == 2:
                inner = [s for s in mine if s.id == sign]
                if inner and not has_width[id(inner[0])]:
                    yield cross_section_surface_strips.finding(
                        f"road {road_id}: the inner {side} strip (id {sign}) has no <width>, so it is not known where "
                        f"the outer strip starts: give the inner strip's width",
                        uid=U.SURFACE_USE_WIDTH,
                        road=road_id,
                        line=inner[0].line or None,
                    )


def _strip_id(strip: SurfaceStrip) -> str | None:
    """A strip's id as the file wrote it (``None``: absent)."""
    return strip.xml.text("id") if strip.id is None else str(strip.id)
