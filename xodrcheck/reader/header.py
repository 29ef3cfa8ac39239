"""The ``<header>`` to :class:`~xodrcheck.model.Header`: the revision (which decides how the rest is read), extent,
georeference, offset, licence and default regulations."""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import GeoReference, Header, Offset
from xodrcheck.reader.context import LEAF, Context, describe
from xodrcheck.rules import xml as R

#: Versions this reader knows: 1.1 to 1.9.
KNOWN_VERSIONS = frozenset((1, minor) for minor in range(1, 10))

_OFFSET = ["x", "y", "z", "hdg"]
_NONE: tuple[int, ...] = ()
_BOUNDS = ("north", "south", "east", "west")
_HEADER = frozenset({"geoReference", "offset", "license", "defaultRegulations"})


def build_header(ctx: Context, el: etree._Element) -> Header:
    rev_major = ctx.integer(el, "revMajor", "the OpenDRIVE version is unknown")
    rev_minor = ctx.integer(el, "revMinor", "the OpenDRIVE version is unknown")
    if rev_major is not None and rev_minor is not None:
        if (rev_major, rev_minor) in KNOWN_VERSIONS:
            ctx.version = (rev_major, rev_minor)
        else:
            ctx.report(
                R.UNKNOWN_VERSION,
                f"{describe(el)} declares OpenDRIVE {rev_major}.{rev_minor}, which is not one of 1.1 to 1.9; "
                "it is read as an OpenDRIVE 1.9 file, so what that version changed may be misread",
                el,
            )
    north, south, east, west = (ctx.number(el, name, "read as absent", required=False) for name in _BOUNDS)
    references: list[GeoReference] = []
    offset = licence = regulations = None
    for child in el:
        tag = child.tag
        if tag == "geoReference":
            text = "".join(child.itertext()).strip()
            references.append(GeoReference(text, child.sourceline, ctx.facts(child, LEAF)))
        elif tag == "offset" and offset is None:
            v = ctx.floats(child, _OFFSET, _NONE, "the offset is ignored")
            if v is not None:
                offset = Offset(v[0], v[1], v[2], v[3], child.sourceline, ctx.facts(child, LEAF))
        elif tag == "license" and licence is None:
            from xodrcheck.reader.regulations import license_of

            licence = license_of(ctx, child)
        elif tag == "defaultRegulations" and regulations is None:
            from xodrcheck.reader.regulations import default_regulations

            regulations = default_regulations(ctx, child)
    return Header(
        rev_major,
        rev_minor,
        el.get("name"),
        el.get("version"),
        el.get("date"),
        el.get("vendor"),
        north,
        south,
        east,
        west,
        geo_reference=references[0].text if references else None,
        offset=offset,
        line=el.sourceline,
        geo_references=tuple(references),
        license=licence,
        default_regulations=regulations,
        xml=ctx.facts(el, _HEADER),
    )
