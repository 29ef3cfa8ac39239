import numpy as np
import pytest

from tests.xodrcheck.roadbuild import lane, section, straight, width
from xodrcheck.check import check
from xodrcheck.config import Tolerances
from xodrcheck.geometry import arc, spiral
from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.model import Arc, Cubic, Line, Road, Spiral


def _chord_error(g: RoadGeometry, index: int, s: np.ndarray) -> float:
    """Largest distance from densely evaluated border points to the polyline through the sampled points."""
    frac = np.linspace(0.0, 1.0, 41)[1:-1]
    dense = (s[:-1, None] + np.diff(s)[:, None] * frac).ravel()
    worst = 0.0
    at_samples, at_dense = g.border_curves(index, s), g.border_curves(index, dense)
    for lane_id, line in at_samples.items():
        a = np.stack([line.x[:-1], line.y[:-1]], axis=1)
        b = np.stack([line.x[1:], line.y[1:]], axis=1)
        p = np.stack([at_dense[lane_id].x, at_dense[lane_id].y], axis=1).reshape(len(a), len(frac), 2)
        ab = b - a
        t = np.clip(((p - a[:, None]) * ab[:, None]).sum(2) / (ab**2).sum(1)[:, None], 0.0, 1.0)
        worst = max(worst, float(np.linalg.norm(p - (a[:, None] + t[..., None] * ab[:, None]), axis=2).max()))
    return worst


def _curvy_road() -> RoadGeometry:
    first = Spiral(0.0, 0.0, 0.0, 0.0, 60.0, 0.0, 0.08)
    end = spiral.evaluate(first, 60.0)
    second = Arc(60.0, end.x[0], end.y[0], end.hdg[0], 40.0, 0.08)
    end = arc.evaluate(second, 40.0)
    third = Line(100.0, end.x[0], end.y[0], end.hdg[0], 50.0)
    lanes_left = [
        lane(1, width(3.0, 0.02)),
        lane(2, (Cubic(0.0, 2.0, 0.0, 0.0, 0.0), Cubic(70.0, 2.0, 0.05, 0.0, 0.0))),
    ]
    lanes_right = [lane(-1, width(3.5, 0.0, 0.001, -1e-5)), lane(-2, width(4.0))]
    road = Road(
        id="curvy",
        length=150.0,
        plan_view=(first, second, third),
        lane_offset=(Cubic(0.0, 0.0, 0.0, 0.0, 0.0), Cubic(120.0, 0.0, 0.0, 0.004, -5e-5)),
        lane_sections=(section(0.0, lanes_left, lanes_right), section(130.0, lanes_left[:1], lanes_right)),
    )
    return RoadGeometry(road)


@pytest.mark.parametrize("chord", [0.05, 0.01, 0.001])
def test_border_polylines_stay_within_the_chord_tolerance(chord):
    g = _curvy_road()
    for index in (0, 1):
        s = g.sample_s(index, chord=chord, max_step=10.0)
        assert _chord_error(g, index, s) <= chord


def test_finer_tolerance_gives_more_points():
    g = _curvy_road()
    assert len(g.sample_s(0, chord=0.001)) > 2 * len(g.sample_s(0, chord=0.05))


def test_samples_cover_the_section_with_every_knot():
    g = _curvy_road()
    s = g.sample_s(0, chord=0.05, max_step=10.0)
    assert s[0] == 0.0 and s[-1] == 130.0
    assert np.all(np.diff(s) > 0)
    for knot in (60.0, 100.0, 70.0, 120.0):  # element joints, a width record start, a laneOffset record start
        assert knot in s
    s = g.sample_s(1, chord=0.05, max_step=10.0)
    assert s[0] == 130.0 and s[-1] == 150.0


def test_straight_road_is_sampled_at_the_maximum_step():
    g = straight([section(0.0, [lane(1, width(3.0))])], length=100.0)
    s = g.sample_s(0)
    assert np.allclose(np.diff(s), Tolerances().max_step)
    assert len(g.sample_s(0, max_step=2.0)) == 51


def test_arc_road_step_follows_the_outermost_border():
    k, chord = 0.1, 0.01
    lanes_left = [lane(1, width(3.0)), lane(2, width(3.0))]
    g = RoadGeometry(
        Road(
            id="a",
            length=30.0,
            plan_view=(Arc(0.0, 0.0, 0.0, 0.0, 30.0, k),),
            lane_sections=(section(0.0, lanes_left, [lane(-1, width(4.0))]),),
        )
    )
    s = g.sample_s(0, chord=chord, max_step=100.0)
    # Lane -1's outer border has radius 14 and runs 1.4 m per metre of s: h <= sqrt(8 chord / k_b) / speed.
    allowed = np.sqrt(8 * chord * 14.0) / 1.4
    assert np.diff(s).max() <= allowed
    assert np.diff(s).max() > 0.8 * allowed
    assert _chord_error(g, 0, s) <= chord


def test_non_positive_tolerances_are_refused():
    g = straight([section(0.0, [lane(1, width(3.0))])])
    with pytest.raises(ValueError):
        g.sample_s(0, chord=0.0)
    with pytest.raises(ValueError):
        g.sample_s(0, max_step=-1.0)


HUGE_ROAD = b"""<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" junction="-1" length="1e300"><planView>
<geometry s="0" x="1e300" y="0" hdg="0" length="1e300"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving">
<width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>
</OpenDRIVE>"""


@pytest.mark.filterwarnings("error")
def test_astronomical_coordinates_give_no_numpy_warning():
    g = straight([section(0.0, [], [lane(-1, width(3.5))])], length=1e300)
    s = g.sample_s(0)
    assert s[0] == 0.0 and s[-1] == 1e300
    report = check(HUGE_ROAD)  # every rule evaluates the damaged road
    assert report.version == "1.6" and len(report.rules_run) > 50
    assert not [f.message for f in report.findings if f.name == "rule-crashed"]
