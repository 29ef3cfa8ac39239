"""Small inline OpenDRIVE documents and finding helpers for the reader tests (test_reader*.py)."""

from __future__ import annotations

from xodrcheck import model as m
from xodrcheck.reader import ReadResult, read

DECL = '<?xml version="1.0" encoding="UTF-8"?>\n'

LINE_GEOMETRY = '<geometry s="0" x="1" y="2" hdg="0.5" length="10"><line/></geometry>'
LANES = (
    '<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>'
    '<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>'
    "</laneSection></lanes>"
)


def road(
    body: str = "",
    *,
    attrs: str = 'id="1" length="10" junction="-1"',
    plan_view: str = f"<planView>{LINE_GEOMETRY}</planView>",
    lanes: str = LANES,
) -> str:
    return f"<road {attrs}>{body}{plan_view}{lanes}</road>"


def xodr(*elements: str, version: tuple[int, int] = (1, 8), header: str | None = None) -> bytes:
    head = f'<header revMajor="{version[0]}" revMinor="{version[1]}"/>' if header is None else header
    # The header shares line 2 with <OpenDRIVE>, so the first element is on line 3, the next on line 4...
    return (DECL + "<OpenDRIVE>" + head + "\n" + "\n".join(elements) + "\n</OpenDRIVE>\n").encode()


def codes(result: ReadResult) -> list[str]:
    return [f.code for f in result.findings]


def only(result: ReadResult, code: str):
    found = [f for f in result.findings if f.code == code]
    assert len(found) == 1, f"expected one {code}, got {[(f.code, f.message) for f in result.findings]}"
    return found[0]


def clean(data: bytes) -> m.Document:
    result = read(data)
    assert result.findings == (), [f.message for f in result.findings]
    assert result.document is not None
    return result.document


def first_road(data: bytes) -> m.Road:
    return clean(data).roads[0]


def section(*sides: str, attrs: str = 's="0"') -> str:
    return f"<laneSection {attrs}>" + "".join(sides) + "</laneSection>"


CENTER = '<center><lane id="0" type="none"/></center>'


def lanes_of(*sections: str, offsets: str = "") -> str:
    return "<lanes>" + offsets + "".join(sections) + "</lanes>"
