"""The fix loop (:mod:`xodrcheck.fix.driver`): a repair stays only when its finding is gone and nothing new appears;
the others are rolled back with the reason, and the good repairs of a batch stay beside a bad one."""

from __future__ import annotations

import gzip

import pytest

from tests.xodrcheck.fix.test_fixes import ROAD1_LANE1, T_JUNCTION, damaged
from xodrcheck.check import check
from xodrcheck.config import ConfigError
from xodrcheck.findings import ReadError
from xodrcheck.fix import registry
from xodrcheck.fix.edits import remove_element, set_attribute
from xodrcheck.fix.registry import Fixer, Repair

#: Road 1's lanes 1 and -1, and road 2's lane 1, each given an empty <link/>.
THREE = T_JUNCTION
for _old in (ROAD1_LANE1, ROAD1_LANE1.replace(b'id="1"', b'id="-1"')):
    THREE = damaged(THREE, _old, _old.replace(b"\n", b"\n            <link/>\n", 1))
THREE = THREE.replace(ROAD1_LANE1, ROAD1_LANE1.replace(b"\n", b"\n            <link/>\n", 1), 1)


def _links(ws):
    return [
        e
        for e in ws.text.elements
        if e.tag == "link" and e.parent is not None and e.parent.tag == "lane" and not e.children
    ]


def _use(monkeypatch, plan):
    """Only the test's fix, for L024 (the families are loaded first: else they would register into the test's dict)."""
    registry.load_fixers()
    fx = Fixer("L024", "test-fix", True, "moves nothing", "A test's fix.", plan)
    monkeypatch.setattr(registry, "FIXERS", {"L024": (fx,)})


def test_the_three_damages_are_found_and_fixed():
    assert [f.code for f in check(THREE).findings] == ["L024"] * 3
    result = registry_free_fix(THREE)
    assert result.data == T_JUNCTION and result.fixed() == {"L024": 3}


def registry_free_fix(data, **kw):
    from xodrcheck.fix.result import fix

    return fix(data, **kw)


def test_a_repair_whose_finding_remains_is_rolled_back(monkeypatch):
    def plan(ws, findings):
        header = ws.text.root.find("header")
        for f in findings:  # claims the finding, edits something else
            yield Repair((f,), (set_attribute(ws.text, header, "name", f"n{f.line}"),), f"renamed for line {f.line}")

    _use(monkeypatch, plan)
    result = registry_free_fix(THREE)
    assert result.data == THREE and not result.applied
    assert len(result.rolled_back) == 3 and all("remained" in r.reason for r in result.rolled_back)
    assert all(why.startswith("a repair was rolled back") for f, why in result.remaining)


@pytest.mark.parametrize("where", ["road", "geometry"])
def test_a_repair_that_brings_a_finding_is_rolled_back_and_the_others_stay(monkeypatch, where):
    """The new finding (G004, at road 2's line) lies on a line the bad repair edits (``road``: it is blamed at once)
    or not (``geometry``: the batch is halved until it is found)."""

    def plan(ws, findings):
        links = {e.line: e for e in _links(ws)}
        road2 = next(e for e in ws.text.root.findall("road") if e.get("id") == "2")
        target = road2 if where == "road" else road2.find("planView").find("geometry")
        for f in findings:
            edits = [remove_element(ws.text, links[f.line])]
            if (f.road, f.lane) == ("1", -1):  # this one also shortens road 2 or its geometry: a new finding
                edits.append(set_attribute(ws.text, target, "length", "90"))
            yield Repair((f,), tuple(edits), f"removed the link of road {f.road} lane {f.lane}")

    _use(monkeypatch, plan)
    result = registry_free_fix(THREE)
    assert len(result.applied) == 2 and len(result.rolled_back) == 1
    assert "it brought a new finding" in result.rolled_back[0].reason
    assert result.data.count(b"<link/>") == 1 and b'length="90"' not in result.data
    assert result.rolled_back[0].repair.findings[0].lane == -1
    assert [f.code for f in result.report.findings] == ["L024"]


def test_overlapping_repairs_wait_for_the_next_round(monkeypatch):
    def plan(ws, findings):
        link = _links(ws)[0]
        finding = next(f for f in findings if f.line == link.line)
        for n in range(2):  # two repairs of one element: the second waits, and is planned afresh next round
            yield Repair((finding,), (remove_element(ws.text, link),), f"removed the link at line {link.line} ({n})")

    _use(monkeypatch, plan)
    result = registry_free_fix(THREE)
    assert len(result.applied) == 3 and result.data == T_JUNCTION
    assert {a.round for a in result.applied} == {1, 2, 3}


def test_what_cannot_be_read_or_edited_is_left_with_the_reason(tmp_path):
    broken = b"<OpenDRIVE><header revMajor='1' revMinor='4'/><road"
    result = registry_free_fix(broken)
    assert result.data == broken and not result.applied and result.report.errors >= 1
    assert {why for f, why in result.remaining} == {"no fix for this rule"}
    wide = THREE.decode().replace('encoding="UTF-8"', 'encoding="UTF-16"').encode("utf-16")
    assert [f.code for f in check(wide).findings] == ["X104"] + ["L024"] * 3  # (X104: not UTF-8)
    result = registry_free_fix(wide)
    assert result.data == wide and all(
        "cannot be edited safely" in why and "UTF-16" in why for _, why in result.remaining
    )
    packed = tmp_path / "map.xodrz"
    packed.write_bytes(gzip.compress(THREE))
    with pytest.raises(ReadError, match="gzip"):
        registry_free_fix(packed)
    with pytest.raises(ReadError, match=r"(?i)no such file"):
        registry_free_fix(tmp_path / "missing.xodr")
    with pytest.raises(ConfigError):
        registry_free_fix(THREE, select=["Q999"])


def test_select_and_ignore_choose_what_is_fixed_and_reported():
    broken = damaged(
        THREE, b'contactPoint="end">\n      <laneLink from="1" to="1"/>', b'>\n      <laneLink from="1" to="1"/>'
    )
    assert sorted({f.code for f in check(broken).findings}) == ["J002", "L024"]
    only = registry_free_fix(broken, select=["J002"])
    assert only.fixed() == {"J002": 1} and [f.code for f in only.report.findings] == []
    assert only.data.count(b"<link/>") == 3
    rest = registry_free_fix(broken, ignore=["J002"])
    assert rest.fixed() == {"L024": 3} and b"<link/>" not in rest.data
    assert {f.code for f in rest.report.findings} == set()
    assert {f.code for f in check(rest.data).findings} == {"J002"}
