"""Broken, hostile and odd inputs: each gives findings (or a ReadError), in bounded time, never a traceback.

Every case runs twice: through :func:`xodrcheck.reader.read` in process (under a generous alarm, so a runaway loop
fails instead of hanging), and through ``python -m xodrcheck info`` in a subprocess (under a timeout), whose exit code
must say what the findings say: 2 when the file cannot be read, 1 with an error-level finding, 0 with warnings only.
"""

from __future__ import annotations

import contextlib
import gzip
import re
import signal
import subprocess
import sys
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import pytest

from xodrcheck.findings import ReadError, Severity
from xodrcheck.reader import read
from xodrcheck.rules import xml as R

REPO = Path(__file__).resolve().parents[2]
#: Generous bounds: a case that needs this long is hanging, not slow.
READ_TIMEOUT_S = 120
CLI_TIMEOUT_S = 300
SECRET_MARKER = "XODRCHECK-SECRET-5d1e0b"
READER_CODES = {rule.code for rule in R.READER_RULES}

DECL = b'<?xml version="1.0" encoding="UTF-8"?>\n'
HEADER = b'<header revMajor="1" revMinor="6"/>'
ROAD = (
    b'<road id="{id}" length="10" junction="-1">\n'
    b'  <planView><geometry s="0" x="0" y="{y}" hdg="0" length="10"><line/></geometry></planView>\n'
    b'  <lanes><laneSection s="0"><center><lane id="0" type="none"/></center>\n'
    b'    <right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>\n'
    b"  </laneSection></lanes>\n"
    b"</road>\n"
)


def road(road_id: int = 1, y: float = 0.0) -> bytes:
    return ROAD.replace(b"{id}", str(road_id).encode()).replace(b"{y}", repr(y).encode())


def xodr(*elements: bytes, header: bytes = HEADER) -> bytes:
    return DECL + b"<OpenDRIVE>" + header + b"\n" + b"".join(elements) + b"</OpenDRIVE>\n"


GOOD = xodr(road())


def _cut(data: bytes, start: bytes, end: bytes) -> bytes:
    """``data`` without the first element running from ``start`` to the ``end`` tag."""
    i = data.index(start)
    return data[:i] + data[data.index(end, i) + len(end) :]


def billion_laughs() -> bytes:
    entities = b'<!ENTITY lol0 "lollollollollollollollollollol">' + b"".join(
        b'<!ENTITY lol%d "%s">' % (i, b"&lol%d;" % (i - 1) * 10) for i in range(1, 10)
    )
    doctype = b"<!DOCTYPE OpenDRIVE [" + entities + b"]>\n"
    body = xodr(road(), header=b'<header revMajor="1" revMinor="6" name="&lol9;"/>')
    return body.replace(b"<OpenDRIVE>", doctype + b"<OpenDRIVE><userData>&lol9;</userData>", 1)


def external_entity(tmp: Path) -> bytes:
    secret = tmp / "secret.txt"
    secret.write_text(SECRET_MARKER)
    doctype = f'<!DOCTYPE OpenDRIVE [<!ENTITY s SYSTEM "file://{secret}">]>\n'.encode()
    body = xodr(road().replace(b'id="1"', b'id="&s;"'), header=b'<header revMajor="1" revMinor="6" name="&s;"/>')
    return body.replace(b"<OpenDRIVE>", doctype + b"<OpenDRIVE><userData>&s;</userData>", 1)


#: The big generated file: roads crowded with objects (as maps with many signs, poles and markings are), some 25 MB
#: and 140 000 lines in all, yet few enough roads that ``xodrcheck info`` samples them quickly.
BIG_ROADS = 2_500
OBJECTS_PER_ROAD = 50
OBJECT = (
    b'    <object id="o{i}" type="pole" s="{s}" t="-4.5" zOffset="0" height="2.5" radius="0.05" hdg="0" pitch="0" '
    b'roll="0" orientation="none" name="delineator post with a long descriptive name"/>\n'
)


def _objects(road_id: int) -> bytes:
    return (
        b"  <objects>\n"
        + b"".join(
            OBJECT.replace(b"{i}", b"%d_%d" % (road_id, k)).replace(b"{s}", b"%g" % (k * 0.2))
            for k in range(OBJECTS_PER_ROAD)
        )
        + b"  </objects>\n"
    )


def big_file(tmp: Path) -> Path:
    """Tens of MB of roads, the last with a broken length and heading (findings far beyond line 65535)."""
    path = tmp / "big.xodr"
    with path.open("wb") as out:
        out.write(DECL + b"<OpenDRIVE>" + HEADER + b"\n")
        for i in range(BIG_ROADS):
            out.write(road(i, y=i * 10.0).replace(b"</road>", _objects(i) + b"</road>"))
        out.write(road(BIG_ROADS).replace(b'length="10"', b'length="seven"', 1).replace(b'hdg="0"', b'hdg="NaN"'))
        out.write(b"</OpenDRIVE>\n")
    return path


@dataclass(frozen=True)
class Case:
    name: str
    #: The file's bytes, or (for cases that need the temporary folder) a function returning bytes or a path.
    content: bytes | Callable[[Path], bytes | Path]
    #: Reader codes that must be among the findings; empty when the input cannot be read at all.
    codes: tuple[str, ...]
    #: The worst severity among the findings; ``None`` when ``read`` must raise ReadError.
    worst: Severity | None = Severity.ERROR
    #: Whether a document (possibly partial) must come back.
    document: bool = True


CASES = [
    Case("truncated", GOOD[: GOOD.index(b"<lanes>") + 20], ("X101",)),
    Case("empty file", b"", ("X101",), document=False),
    Case("blank file", b"  \n\n\t ", ("X101",), document=False),
    Case("binary garbage", bytes(range(256)) * 64, ("X101",), document=False),
    Case("no header", xodr(road(), header=b""), ("X203",)),
    Case("not OpenDRIVE", DECL + b"<OpenSCENARIO><FileHeader revMajor='1'/></OpenSCENARIO>", ("X201",), document=False),
    Case("html page", b"<!DOCTYPE html><html><head><meta charset=utf-8></head></html>", ("X201",), document=False),
    Case("revMinor seven", xodr(road(), header=b'<header revMajor="1" revMinor="seven"/>'), ("X206",)),
    Case("NaN coordinate", GOOD.replace(b'x="0"', b'x="NaN"'), ("X206",)),
    Case("negative length", GOOD.replace(b'length="10" junction', b'length="-10" junction'), ("X206",)),
    Case("infinite heading", GOOD.replace(b'hdg="0"', b'hdg="-INF"'), ("X206",)),
    Case("decimal comma", GOOD.replace(b'a="3.5"', b'a="3,5"'), ("X206",)),
    Case("unknown geometry element", GOOD.replace(b"<line/>", b'<clothoid k0="0"/>'), ("X207",)),
    Case("geometry missing x", GOOD.replace(b'x="0" ', b""), ("X205",)),
    Case("road without id", GOOD.replace(b'id="1" ', b"", 1), ("X205",)),
    Case(
        "lane section without lane 0",
        GOOD.replace(b'<center><lane id="0" type="none"/></center>', b""),
        ("X203",),
    ),
    Case("road without planView", _cut(GOOD, b"<planView>", b"</planView>"), ("X203",)),
    Case("lanes without laneSection", _cut(GOOD, b"<laneSection", b"</laneSection>"), ("X203",)),
    Case(
        "records out of order",
        GOOD.replace(b'<laneSection s="0">', b'<laneSection s="0.5">').replace(
            b"</lanes>", b'<laneSection s="0"><center><lane id="0" type="none"/></center></laneSection></lanes>'
        ),
        ("X209",),
    ),
    Case("unknown lane type", GOOD.replace(b'type="driving"', b'type="carriageway"'), ("X208",), Severity.WARNING),
    Case("entity expansion bomb", billion_laughs(), ("X102",)),  # the references are counted in X102
    Case("external entity naming a local file", external_entity, ("X102",)),
    Case(
        "unterminated DOCTYPE", DECL + b'<!DOCTYPE OpenDRIVE [ <!ENTITY a "b">\n<OpenDRIVE/>', ("X101",), document=False
    ),
    Case("comment before the declaration", b"<!-- exported -->\n" + GOOD, ("X103",), Severity.WARNING),
    Case("BOM and text before the declaration", b"\xef\xbb\xbfexported by hand\n" + GOOD, ("X103",), Severity.WARNING),
    Case("UTF-16 with BOM", GOOD.decode().replace("UTF-8", "UTF-16").encode("utf-16"), ("X104",), Severity.WARNING),
    Case("bytes not in the declared encoding", GOOD.replace(b'id="1"', b'id="caf\xe9"'), ("X101",)),
    Case("duplicated attribute", GOOD.replace(b'x="0"', b'x="0" x="1"'), ("X101",)),
    Case("mismatched tags", GOOD.replace(b"</planView>", b"</plan>"), ("X101",)),
    Case("unterminated comment", GOOD.replace(b"<lanes>", b"<!-- <lanes>"), ("X101",)),
    Case("deeply nested unknown elements", xodr(b"<a>" * 5000 + b"</a>" * 5000, road()), ("X101",)),
    Case("corrupt gzip", gzip.compress(GOOD)[:40], ("X101",), document=False),
    Case("tens of MB of roads", big_file, ("X206",)),
    Case("missing file", lambda tmp: tmp / "absent.xodr", (), None, document=False),
    Case("a directory", lambda tmp: tmp, (), None, document=False),
]


def _materialise(case: Case, tmp: Path) -> Path:
    content = case.content(tmp) if callable(case.content) else case.content
    if isinstance(content, Path):
        return content
    path = tmp / "input.xodr"
    path.write_bytes(content)
    return path


@contextlib.contextmanager
def time_limit(seconds: int) -> Iterator[None]:
    """Fail (rather than hang) when the block runs past ``seconds``."""

    def expire(signum, frame):
        raise TimeoutError(f"still running after {seconds} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def test_there_are_enough_cases():
    assert len(CASES) >= 22
    assert len({case.name for case in CASES}) == len(CASES)


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_read_gives_findings_not_tracebacks(case: Case, tmp_path: Path):
    path = _materialise(case, tmp_path)
    with time_limit(READ_TIMEOUT_S):
        if case.worst is None:
            with pytest.raises(ReadError):
                read(path)
            return
        result = read(path)
    found = {f.code for f in result.findings}
    assert set(case.codes) <= found, [(f.code, f.message) for f in result.findings]
    assert found <= READER_CODES
    assert max(f.severity for f in result.findings) is case.worst
    assert (result.document is not None) is case.document
    for finding in result.findings:
        assert finding.message and "Traceback" not in finding.message
    assert SECRET_MARKER not in repr(result)


def test_big_file_is_read_whole(tmp_path: Path):
    path = big_file(tmp_path)
    assert path.stat().st_size > 20_000_000
    with time_limit(READ_TIMEOUT_S):
        result = read(path)
    assert len(result.document.roads) == BIG_ROADS + 1
    assert [len(r.objects) for r in result.document.roads] == [OBJECTS_PER_ROAD] * BIG_ROADS + [0]
    road_line = 3 + BIG_ROADS * (ROAD.count(b"\n") + OBJECTS_PER_ROAD + 2)
    geometry, length = result.findings
    # Past line 65535 libxml2 knows lines only from the text node next to an element: the road's line comes out one
    # too far (its first text node ends on the next line), and the compact <geometry>, which has no text node of its
    # own, is located by the road it is in.
    assert length.road == geometry.road == str(BIG_ROADS)
    assert road_line <= length.line <= road_line + 1
    assert f'<road> at about line {length.line} has length="seven"' in length.message
    assert geometry.line == length.line
    assert f"<geometry> after about line {length.line} (in <road>)" in geometry.message
    assert result.document.roads[-2].plan_view[0].y == (BIG_ROADS - 1) * 10.0


def _exit_code(case: Case) -> int:
    if case.worst is None:
        return 2
    return 1 if case.worst >= Severity.ERROR else 0


def _info(path: Path) -> subprocess.CompletedProcess | subprocess.TimeoutExpired:
    try:
        return subprocess.run(
            [sys.executable, "-m", "xodrcheck", "info", str(path)],
            capture_output=True,
            text=True,
            timeout=CLI_TIMEOUT_S,
            cwd=REPO,
            check=False,
        )
    except subprocess.TimeoutExpired as exc:
        return exc


@pytest.fixture(scope="module")
def info_runs(tmp_path_factory) -> dict[str, tuple[Path, subprocess.CompletedProcess | subprocess.TimeoutExpired]]:
    """``xodrcheck info`` on every case, a few processes at a time (they mostly wait for imports)."""
    paths = {case.name: _materialise(case, tmp_path_factory.mktemp("info")) for case in CASES}
    with ThreadPoolExecutor(max_workers=4) as pool:
        runs = dict(zip(paths, pool.map(_info, paths.values())))
    return {name: (paths[name], runs[name]) for name in paths}


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_info_command_exits_cleanly(case: Case, info_runs):
    path, done = info_runs[case.name]
    assert not isinstance(done, subprocess.TimeoutExpired), f"xodrcheck info still running after {CLI_TIMEOUT_S} s"
    assert "Traceback" not in done.stderr and "Traceback" not in done.stdout
    whole = case.worst is not None and read(path).not_whole() is None
    assert done.returncode == (_exit_code(case) if whole else 2), done.stderr
    assert SECRET_MARKER not in done.stdout + done.stderr
    lines = [line for line in done.stderr.splitlines() if line.strip()]
    if done.returncode == 0:
        assert lines == []
        return
    assert len(lines) == 1, done.stderr
    if case.worst is None:
        assert lines[0].startswith(f"xodrcheck: cannot read {path}: ")
    elif not whole:  # like every command, info refuses a file it cannot read whole: nothing printed
        assert lines[0].startswith(f"xodrcheck: cannot read {path} whole, so nothing is written for it: X")
        assert done.stdout == ""
    else:  # the first error-level finding: file, code, name, message
        assert re.match(rf"xodrcheck: {re.escape(str(path))}: X\d{{3}} [a-z-]+: \S", lines[0]), lines[0]


# -------------------------------------------------------------------------------------------------------- every value
#: A small document using every element the reader builds.
RICH = (
    DECL
    + b"""<OpenDRIVE><header revMajor="1" revMinor="8" name="rich" north="1" south="0" east="1" west="0">
<geoReference><![CDATA[+proj=utm]]></geoReference><offset x="1" y="2" z="0" hdg="0"/></header>
<road id="1" length="30" junction="-1" rule="RHT">
  <link><predecessor elementType="road" elementId="2" contactPoint="end"/>
    <successor elementType="junction" elementId="9" elementS="0" elementDir="+"/></link>
  <planView>
    <geometry s="0" x="0" y="0" hdg="0" length="5"><line/></geometry>
    <geometry s="5" x="5" y="0" hdg="0" length="5"><arc curvature="0.01"/></geometry>
    <geometry s="10" x="10" y="0" hdg="0" length="5"><spiral curvStart="0" curvEnd="0.01"/></geometry>
    <geometry s="15" x="15" y="0" hdg="0" length="5"><poly3 a="0" b="0" c="0" d="0"/></geometry>
    <geometry s="20" x="20" y="0" hdg="0" length="10">
      <paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="normalized"/></geometry>
  </planView>
  <elevationProfile><elevation s="0" a="0" b="0" c="0" d="0"/></elevationProfile>
  <lateralProfile><superelevation s="0" a="0" b="0" c="0" d="0"/></lateralProfile>
  <lanes>
    <laneOffset s="0" a="0" b="0" c="0" d="0"/>
    <laneSection s="0" singleSide="false">
      <left><lane id="1" type="driving" level="false"><border sOffset="0" a="3" b="0" c="0" d="0"/></lane></left>
      <center><lane id="0" type="none"><roadMark sOffset="0" type="solid" width="0.1"/></lane></center>
      <right><lane id="-1" type="driving" level="true">
        <link><predecessor id="-1"/><successor id="-1"/></link>
        <width sOffset="0" a="3" b="0" c="0" d="0"/>
        <roadMark sOffset="0" type="broken" weight="standard" color="white" width="0.12" laneChange="both"/>
        <speed sOffset="0" max="20" unit="m/s"/>
      </lane></right>
    </laneSection>
  </lanes>
  <objects><object id="o"/></objects><signals><signal id="s"/></signals>
</road>
<junction id="9" name="j" type="default">
  <connection id="0" incomingRoad="1" connectingRoad="3" contactPoint="start"><laneLink from="-1" to="-1"/></connection>
</junction>
</OpenDRIVE>
"""
)

#: Values every attribute is set to in turn.
BAD_VALUES = ("", " ", "NaN", "-inf", "1e999", "-1", "1,5", "seven", "true", "start", "+", "0x10", "1_0", "\u00e9")
#: Of those, the ones that are no number at all.
NOT_NUMBERS = frozenset({"", " ", "NaN", "-inf", "1e999", "1,5", "seven", "true", "start", "+", "0x10", "\u00e9"})
#: Attributes the reader reads as numbers (lane ``id`` and the lane-link ids are integers).
NUMERIC = frozenset(
    {
        "s",
        "x",
        "y",
        "z",
        "hdg",
        "length",
        "curvature",
        "curvStart",
        "curvEnd",
        "a",
        "b",
        "c",
        "d",
        "aU",
        "bU",
        "cU",
        "dU",
        "aV",
        "bV",
        "cV",
        "dV",
        "sOffset",
        "max",
        "north",
        "south",
        "east",
        "west",
        "elementS",
        "revMajor",
        "revMinor",
        "from",
        "to",
        "width",
    }
)


def _attributes(data: bytes) -> list[tuple[str, int, int]]:
    """(name, start, end) of every attribute value in ``data`` (byte spans of the value)."""
    spans = []
    pos = 0
    while (eq := data.find(b'="', pos)) >= 0:
        name = data[data.rindex(b" ", 0, eq) + 1 : eq].decode()
        end = data.index(b'"', eq + 2)
        spans.append((name, eq + 2, end))
        pos = end + 1
    return spans


def test_rich_document_reads_clean():
    result = read(RICH)
    assert result.findings == ()
    assert len(result.document.roads[0].plan_view) == 5


def test_any_attribute_set_to_any_bad_value_never_raises():
    spans = _attributes(RICH)[2:]  # the XML declaration's own version and encoding are not OpenDRIVE's
    assert len(spans) > 100
    with time_limit(READ_TIMEOUT_S):
        for name, start, end in spans:
            for value in BAD_VALUES:
                result = read(RICH[:start] + value.encode() + RICH[end:])
                assert result.document is not None
                assert {f.code for f in result.findings} <= READER_CODES
                if name in NUMERIC and value in NOT_NUMBERS:
                    assert any(name in f.message for f in result.findings), (name, value)
