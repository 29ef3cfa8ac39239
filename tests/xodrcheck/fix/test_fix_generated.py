"""Generated maps: clean, so they come out byte-identical; damaged in many places at once with what the safe fixes
repair (empty lane links, centre-lane widths, connections' contact points and lane links), fixed back to the very
bytes the generator wrote."""

from __future__ import annotations

import re

import pytest

import junctionart as ja
from junctionart.params import Params
from tests.xodrcheck.fix.acceptance import largest_move
from xodrcheck.check import check
from xodrcheck.fix.result import fix


@pytest.fixture(scope="module", params=["1.8", "1.7"])
def generated(request, tmp_path_factory) -> bytes:
    path = tmp_path_factory.mktemp("generated") / f"map-{request.param}.xodr"
    ja.write(
        ja.generate(Params(width=500, height=500, randomize_lanes=True, version=request.param), 3), path, request.param
    )
    return path.read_bytes()


def _damage(data: bytes) -> tuple[bytes, int]:
    """Empty <link/> in every lane without links, a width on every third centre lane, and of every four connections
    one's contact point flipped and another's first laneLink pointing to a lane that does not exist; with how
    many."""
    count = 0

    def lane(m: re.Match[bytes]) -> bytes:
        nonlocal count
        count += 1
        return m.group(1) + m.group(2) + b"<link/>\n" + m.group(2) + m.group(3)

    data = re.sub(rb'(<lane id="-?[1-9]\d*" type="\w+" level="false">\n)( +)(<width)', lane, data)
    centres = iter(range(10**6))

    def centre(m: re.Match[bytes]) -> bytes:
        nonlocal count
        if next(centres) % 3:
            return m.group(0)
        count += 1
        return m.group(1) + m.group(2) + b'<width sOffset="0" a="0" b="0" c="0" d="0"/>\n' + m.group(2) + m.group(3)

    data = re.sub(rb'(<lane id="0" type="none" level="false">\n)( +)(<roadMark)', centre, data)
    connections = iter(range(10**6))

    def connection(m: re.Match[bytes]) -> bytes:  # one damage a connection: its contact point or a lane link
        nonlocal count
        k, text = next(connections), m.group(0)
        if k % 4 == 0:
            count += 1
            return re.sub(
                rb'contactPoint="(start|end)"',
                lambda c: b'contactPoint="%s"' % (b"end" if c.group(1) == b"start" else b"start"),
                text,
            )
        if k % 4 == 2:
            count += 1
            return re.sub(rb'(<laneLink from="-?\d+" to=")-?\d+"', rb'\g<1>-9"', text, count=1)
        return text

    data = re.sub(rb"<connection [^>]*>.*?</connection>", connection, data, flags=re.S)
    return data, count


def test_a_generated_map_has_nothing_to_fix(generated):
    assert check(generated).findings == ()
    result = fix(generated, unsafe=True)
    assert result.data == generated and not result.applied


def test_a_damaged_generated_map_is_fixed_back_to_the_generators_bytes(generated):
    broken, made = _damage(generated)
    before = check(broken)
    assert {f.code for f in before.findings} >= {"L024", "L002", "J002", "R012"} and made > 20
    result = fix(broken)
    assert result.data == generated, result.diff()[:3000]
    assert sum(result.fixed().values()) >= made and not result.report.findings
    assert largest_move(broken, result.data) == 0.0
