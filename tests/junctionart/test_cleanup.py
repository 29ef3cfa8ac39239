import pytest

import junctionart as ja
from junctionart.cleanup import SOLID_NEAR_JUNCTION
from junctionart.params import Params


def _width(c, ds):
    return c.a + c.b * ds + c.c * ds**2 + c.d * ds**3


def _maps():
    p = Params(randomize_lanes=True, width=800, height=800, turn_lane_probability=0.5)
    return [ja.generate_layout(p, seed) for seed in range(4)]


@pytest.fixture(scope="module")
def maps():
    return _maps()


def test_lane_count_changes_are_tapers_with_links(maps):
    tapers = 0
    for result in maps:
        for road in result.document.roads:
            if road.junction != "-1":
                continue
            secs = road.sections
            for i, sec in enumerate(secs):
                end = secs[i + 1].s if i + 1 < len(secs) else road.length
                L = end - sec.s
                nxt = secs[i + 1] if i + 1 < len(secs) else None
                prv = secs[i - 1] if i > 0 else None
                for lane in (*sec.left, *sec.right):
                    (w,) = lane.widths
                    w0, w1 = _width(w, 0.0), _width(w, L)
                    assert w0 >= 0 and w1 >= -1e-12
                    if lane.type != "driving":
                        continue
                    if abs(w0 - w1) > 1e-9:
                        tapers += 1
                        assert min(w0, w1) == pytest.approx(0.0, abs=1e-9)
                        # the slope vanishes at both ends: a smooth split / merge
                        assert w.b == 0.0
                        assert w.b + 2 * w.c * L + 3 * w.d * L**2 == pytest.approx(0.0, abs=1e-9)
                    ids_next = {ln.id for ln in (*nxt.left, *nxt.right)} if nxt else set()
                    ids_prev = {ln.id for ln in (*prv.left, *prv.right)} if prv else set()
                    if w1 > 0 and lane.id in ids_next:
                        assert lane.successor == lane.id
                    if w1 == pytest.approx(0.0, abs=1e-9):
                        assert lane.successor is None
                    if w0 > 0 and lane.id in ids_prev:
                        assert lane.predecessor == lane.id
                    if w0 == pytest.approx(0.0, abs=1e-9):
                        assert lane.predecessor is None
    assert tapers > 0


def _left(sec):
    return sec.left


def _right(sec):
    return sec.right


def test_markings(maps):
    solid_near = broken = beside_taper = 0
    for result in maps:
        for road in result.document.roads:
            for sec in road.sections:
                if road.junction != "-1":
                    assert all(m.type == "none" for ln in (*sec.left, sec.center, *sec.right) for m in ln.marks)
                    continue
                two_way = all(
                    any(ln.type == "driving" for s in road.sections for ln in lanes(s)) for lanes in (_left, _right)
                )
                (centre,) = sec.center.marks
                assert centre.type == "solid"
                assert centre.color == ("yellow" if two_way else "standard")
                for side in (sec.left, sec.right):
                    driving = sorted((ln for ln in side if ln.type == "driving"), key=lambda ln: abs(ln.id))
                    for k, lane in enumerate(driving):
                        kinds = [m.type for m in lane.marks]
                        if k == len(driving) - 1:
                            assert kinds == ["solid"], "road edge is solid"
                        elif any(w.c or w.d for w in driving[k + 1].widths):
                            # the lane outside opens or closes here: its traffic crosses this line, near a junction too
                            assert [(m.type, m.lane_change) for m in lane.marks] == [("broken", "both")]
                            beside_taper += 1
                        elif "broken" in kinds:
                            broken += 1
                            if road.successor is not None and road.sections[-1] is sec:
                                assert kinds[-1] == "solid"
                                last = lane.marks[-1]
                                end = road.length - sec.s
                                assert end - last.s == pytest.approx(SOLID_NEAR_JUNCTION) or last.s == 0.0
                                solid_near += 1
    assert broken > 0 and solid_near > 0 and beside_taper > 0


def test_turn_lanes_appear_before_junctions(maps):
    """A lane starting at zero width near a junction end and reaching full width at it: a turn lane."""
    found = 0
    for result in maps:
        for rp in result.layout.roads:
            if rp.end_junction is not None and rp.fwd_end > rp.lanes.forward:
                found += 1
            if rp.start_junction is not None and rp.bwd_start > rp.lanes.backward:
                found += 1
    assert found > 0
