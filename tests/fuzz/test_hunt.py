"""The slow-input hunt: hostile documents grow as asked, the hunt keeps its slowest documents, and the regression
documents it found (``tests/fuzz/slow``) and the winding roads of O002 check within a fixed amount of counted work
(:mod:`xodrcheck.support.work`: counted, not timed)."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from lxml import etree

from junctionart.fuzz import campaign, hunt
from junctionart.fuzz.documents import opendrive_documents
from junctionart.fuzz.hostile import Growth, hostile_documents
from junctionart.fuzz.xodrbuild import DocumentSpec, Element, LaneSpec, Pose, RoadSpec, to_bytes
from xodrcheck.check import check
from xodrcheck.support import work

SLOW = Path(__file__).parent / "slow"
WINDING = Path(__file__).parents[1] / "xodrcheck" / "rules" / "fixtures" / "lane-fold"


def _road(length: float = 50.0) -> bytes:
    lanes = (LaneSpec(-1, "driving", 3.5), LaneSpec(1, "driving", 3.5))
    return to_bytes(DocumentSpec(roads=(RoadSpec("1", Pose(0.0, 0.0, 0.0), (Element("line", length),), lanes),)))


def _grown(kind: str, tag: str, picks: tuple[int, int], amount: float) -> bytes:
    """The one-road document grown at its first ``tag`` element (made again on every run: no large file kept)."""
    data = _road()
    at = [el.tag for el in etree.fromstring(data).iter()][1:].index(tag)
    grown = Growth(kind, (at, *picks), amount).apply(data, max_size=100 * 1024 - 1)
    assert grown is not None
    return grown


#: Documents of the kinds the hunt climbs toward, made from growths: thousands of width records 1 cm apart on one
#: lane, thousands of lane sections 10 cm apart, and a pole with a 50-corner outline every millimetre of a road.
GROWN = {
    "width-records": lambda: _grown("repeat", "width", (0, 0), 1.0),
    "lane-sections": lambda: _grown("repeat", "laneSection", (1, 0), 1.0),
    "dense-objects": lambda: _grown("objects", "road", (3, 47), 0.6),
}
REGRESSIONS = [*sorted(SLOW.glob("*.xodr")), *sorted(WINDING.glob("fail-winding*.xodr")), *sorted(GROWN)]


def test_scale_multiplies_one_number_by_a_power_of_ten():
    grown = Growth("scale", (0, 0, 0), amount=1.0).apply(_road())
    assert grown is not None and Growth("scale", (0,), amount=1.0).exponent == 12
    before = etree.fromstring(_road())
    after = etree.fromstring(grown)
    changed = [
        (el.tag, name, el.get(name), other.get(name))
        for el, other in zip(before.iter(), after.iter())
        for name in el.keys()  # noqa: SIM118 - lxml: attribute names
        if el.get(name) != other.get(name)
    ]
    assert len(changed) == 1
    _, _, old, new = changed[0]
    assert float(new) == pytest.approx(float(old) * 1e12)


def test_repeat_spreads_copies_along_the_road_and_stays_under_the_size():
    data = _road()
    widths = [i for i, el in enumerate(etree.fromstring(data).iter()) if el.tag == "width"]
    picks = (widths[0] - 1, 2, 0)  # the first width record (elements counted without the root), 1 m apart
    grown = Growth("repeat", picks, amount=0.5).apply(data)
    assert grown is not None
    offsets = [float(w.get("sOffset")) for w in etree.fromstring(grown).iter("width")]
    copies = Growth("repeat", picks, amount=0.5).copies
    assert len(offsets) == 2 + copies and offsets[: copies + 1] == [float(k) for k in range(copies + 1)]
    small = Growth("repeat", picks, amount=1.0).apply(data, max_size=len(data) + 2000)
    assert small is not None and len(data) < len(small) <= len(data) + 2000


def test_objects_are_repeated_densely_along_a_road():
    grown = Growth("objects", (0, 3, 2), amount=0.75).apply(_road())
    (repeat,) = etree.fromstring(grown).iter("repeat")
    assert float(repeat.get("length")) == pytest.approx(50.0 * 10.0 ** Growth("x", (0,), 0.75).exponent)
    assert float(repeat.get("distance")) == 1e-3
    assert len(list(etree.fromstring(grown).iter("cornerLocal"))) == 5


@settings(max_examples=10, database=None, deadline=None)
@given(hostile_documents(opendrive_documents(max_roads_per_chain=1, max_elements=1, max_lanes=1), max_size=30_000))
def test_hostile_documents_stay_under_their_size(data):
    """The base documents here are under 30 kB; no change takes them over."""
    assert len(data) <= 30_000 and data.lstrip().startswith(b"<")


def test_the_hunt_keeps_its_slowest_documents(tmp_path, monkeypatch):
    """Three examples of the ``slow`` run: each is measured, targeted and kept; the slowest are written out."""
    monkeypatch.setattr(hunt, "SLOWEST", [])
    before = campaign.TRIED["slow"]
    campaign.hypothesis_test("slow", settings(max_examples=3, database=None, deadline=None))()
    assert campaign.TRIED["slow"] - before >= 3
    assert len(hunt.SLOWEST) >= 1 and all(cost.size > 0 and cost.cpu >= 0 for *_, cost in hunt.SLOWEST)
    written = hunt.save_slowest(tmp_path / "slow")
    assert [p.read_bytes() for p in written] == [d for _, _, d, _ in sorted(hunt.SLOWEST, reverse=True)]


def test_regression_documents_exist():
    assert len(REGRESSIONS) >= 6 and all(len(GROWN[k]()) > 50_000 for k in ("width-records", "lane-sections"))


@pytest.mark.parametrize("which", REGRESSIONS, ids=lambda p: getattr(p, "name", p))
def test_regression_document_checks_within_the_work_bound(which):
    """Each document that once kept the checker busy (found by the hunt, the winding road of issue 31, or grown as
    the hunt grows them) checks within :data:`hunt.WORK_BOUNDS` of every kind of counted work, without a crash."""
    data = which.read_bytes() if isinstance(which, Path) else GROWN[which]()
    with work.counting() as done:
        report = check(data)
    assert not [f for f in report.findings if f.code in ("X900", "X901")]
    assert done["line points"] > 0 and done["mesh vertices"] > 0
    over = {kind: n for kind, n in done.items() if n > hunt.WORK_BOUNDS.get(kind, 0)}
    assert over == {}, f"{which}: more work than {hunt.WORK_BOUNDS}: {over}"
