"""Expressive-range metrics on hand-built junctions whose answers are worked out by hand, plus the corpus and the CLI.

Every junction here is built as OpenDRIVE text: straight legs of one lane each way (3.5 m, the reference line in the
middle) starting at their incident point and pointing away from the junction, and connecting roads that are straight
lines or quarter circles, so every angle and area is elementary geometry.
"""

from __future__ import annotations

import csv
import io
import json
import math

import pytest

from xodrcheck.analysis.metrics import LOOKBACK, complexity, map_metrics
from xodrcheck.cli import main as cli_main
from xodrcheck.config import Tolerances
from xodrcheck.model import JunctionType
from xodrcheck.reader import read

W = 3.5  # lane width


def _lanes(left: int, right: int) -> str:
    lanes = "".join(
        f'<lane id="{i}" type="driving" level="false"><width sOffset="0" a="{W}" b="0" c="0" d="0"/></lane>'
        for i in range(left, 0, -1)
    )
    right_lanes = "".join(
        f'<lane id="{-i}" type="driving" level="false"><width sOffset="0" a="{W}" b="0" c="0" d="0"/></lane>'
        for i in range(1, right + 1)
    )
    return (
        '<lanes><laneSection s="0">'
        + (f"<left>{lanes}</left>" if left else "")
        + '<center><lane id="0" type="none" level="false"/></center>'
        + (f"<right>{right_lanes}</right>" if right else "")
        + "</laneSection></lanes>"
    )


def _road(rid, x, y, hdg, length, *, curvature=None, junction="-1", links="", left=1, right=1) -> str:
    shape = "<line/>" if curvature is None else f'<arc curvature="{curvature!r}"/>'
    return (
        f'<road id="{rid}" length="{length!r}" junction="{junction}"><link>{links}</link>'
        f'<planView><geometry s="0" x="{x!r}" y="{y!r}" hdg="{hdg!r}" length="{length!r}">{shape}</geometry></planView>'
        f"{_lanes(left, right)}</road>"
    )


def junction_xodr(angles_deg, radii, connections=()) -> bytes:
    """A junction "J" at the origin with one straight leg per angle (leg k starts at radii[k] along angles_deg[k],
    heading away) and the given connecting roads: (from leg, to leg, x, y, hdg, length, curvature or None), each one
    right lane wide with its reference line on the lane's left border."""
    roads, conns = [], []
    for k, (angle, r) in enumerate(zip(angles_deg, radii)):
        a = math.radians(angle)
        link = '<predecessor elementType="junction" elementId="J"/>'
        roads.append(_road(f"L{k}", r * math.cos(a), r * math.sin(a), a, 100.0, links=link))
    for n, (i, j, x, y, hdg, length, curvature) in enumerate(connections):
        links = (
            f'<predecessor elementType="road" elementId="L{i}" contactPoint="start"/>'
            f'<successor elementType="road" elementId="L{j}" contactPoint="start"/>'
        )
        roads.append(_road(f"C{n}", x, y, hdg, length, curvature=curvature, junction="J", links=links, left=0))
        conns.append(
            f'<connection id="{n}" incomingRoad="L{i}" connectingRoad="C{n}" contactPoint="start">'
            f'<laneLink from="1" to="-1"/></connection>'
        )
    text = (
        '<?xml version="1.0" encoding="UTF-8"?><OpenDRIVE><header revMajor="1" revMinor="8" name="t"/>'
        + "".join(roads)
        + f'<junction id="J" name="j">{"".join(conns)}</junction></OpenDRIVE>'
    )
    return text.encode()


def metrics_of(data: bytes):
    result = read(data)
    assert result.document is not None
    (m,) = map_metrics(result.document)
    return m


def _straight_cross(r: float):
    """The four straight-through lanes of a cross with incident radius r (eastbound lane south of the x axis...)."""
    return [
        (2, 0, -r, 0.0, 0.0, 2 * r, None),  # west leg -> east leg, y in [-W, 0]
        (0, 2, r, 0.0, math.pi, 2 * r, None),  # east -> west, y in [0, W]
        (3, 1, 0.0, -r, math.pi / 2, 2 * r, None),  # south -> north, x in [0, W]
        (1, 3, 0.0, r, -math.pi / 2, 2 * r, None),  # north -> south, x in [-W, 0]
    ]


def _right_turns(r: float):
    """The four right turns of a cross: quarter circles of radius r (reference) centred on the corners (+-r, +-r)."""
    out = []
    for k, (x, y, hdg) in enumerate(
        [(-r, 0.0, 0.0), (0.0, -r, math.pi / 2), (r, 0.0, math.pi), (0.0, r, -math.pi / 2)]
    ):
        incoming = (2, 3, 0, 1)[k]  # west, south, east, north legs (indices of angles 0, 90, 180, 270)
        outgoing = (3, 0, 1, 2)[k]
        out.append((incoming, outgoing, x, y, hdg, math.pi * r / 2, -1.0 / r))
    return out


# --------------------------------------------------------------------------------------------------------------------
# Leg metrics
# --------------------------------------------------------------------------------------------------------------------
def test_symmetric_cross_leg_metrics_and_straight_lanes():
    r = 10.0
    m = metrics_of(junction_xodr([0, 90, 180, 270], [r] * 4, _straight_cross(r)))
    assert m.legs == 4 and m.n_connection_lanes == 4 and m.n_u_turn_lanes == 0
    curvature = 90 / (r * math.sqrt(2))  # a quarter turn over the chord between neighbouring incident points
    for leg in m.leg_metrics:
        assert leg.fov == pytest.approx(90.0)  # the neighbours' incident points are 45 degrees off the approach
        assert leg.corner_deviation == pytest.approx(45.0)
        assert leg.max_curvature == pytest.approx(curvature)
        assert leg.complexity == pytest.approx(0.5 * curvature / 36 + 0.25 * 90 / 198 + 0.25 * 45 / 90)
    # two 2r x 2W bands crossing: 8 r W - 4 W^2; every lane crosses the two perpendicular ones: the 2W x 2W centre
    assert m.area == pytest.approx(8 * r * W - 4 * W * W, rel=1e-9)
    assert m.conflict_area == pytest.approx(4 * W * W, rel=1e-9)
    assert m.conflict_ratio == pytest.approx(4 * W * W / (8 * r * W - 4 * W * W), rel=1e-9)


def test_t_junction_with_a_deeper_stem():
    # bar legs at 10 m east and west, the stem 15 m south: the stem's incident point is atan(15/10) off the bar's view
    bar = [(1, 0, -10.0, 0.0, 0.0, 20.0, None), (0, 1, 10.0, 0.0, math.pi, 20.0, None)]  # west->east, east->west
    m = metrics_of(junction_xodr([0, 180, 270], [10.0, 10.0, 15.0], bar))
    east, west, stem = m.leg_metrics
    wide, narrow = math.degrees(math.atan2(15, 10)), math.degrees(math.atan2(10, 15))
    for bar in (east, west):
        assert bar.fov == pytest.approx(2 * wide)
        assert bar.corner_deviation == pytest.approx(narrow)  # the sight line to the stem vs the southward exit
        assert bar.max_curvature == pytest.approx(90 / math.hypot(10, 15))  # straight on costs 0 deg over 20 m
    assert stem.fov == pytest.approx(2 * narrow)
    assert stem.corner_deviation == pytest.approx(wide)
    assert stem.max_curvature == pytest.approx(90 / math.hypot(10, 15))
    # the two bar lanes lie side by side (touching along y = 0): area 2 x 20 x W, no conflict
    assert m.area == pytest.approx(2 * 20 * W, rel=1e-9)
    assert m.conflict_area == 0.0 and m.conflict_ratio == 0.0


def _on_circle(angles_deg, r):
    """Expected leg metrics when every incident point lies on one circle of radius r around the junction centre:
    the chord to a leg phi away makes (180 - phi) / 2 with both radii (isosceles triangle), and the heading change
    into that leg is 180 - phi."""
    out = []
    for i, a in enumerate(angles_deg):
        phis = [abs((b - a + 180) % 360 - 180) for j, b in enumerate(angles_deg) if j != i]
        fov = 180 - min(phis)
        dev = (180 - min(phis)) / 2
        curv = max((180 - phi) / (2 * r * math.sin(math.radians(phi) / 2)) for phi in phis)
        out.append((fov, dev, curv))
    return out


def test_y_junction():
    r = 12.0
    m = metrics_of(junction_xodr([90, 210, 330], [r] * 3))
    for leg, (fov, dev, curv) in zip(m.leg_metrics, _on_circle([90, 210, 330], r)):
        assert (fov, dev) == (pytest.approx(60.0), pytest.approx(30.0))
        assert leg.fov == pytest.approx(fov) and leg.corner_deviation == pytest.approx(dev)
        assert leg.max_curvature == pytest.approx(60 / (r * math.sqrt(3))) == curv
    assert m.n_connection_lanes == 0 and m.area == 0.0 and m.conflict_ratio is None


def test_skewed_five_way_wraps_heading_differences():
    angles, r = [0, 75, 130, 190, 280], 12.0
    m = metrics_of(junction_xodr(angles, [r] * 5))
    assert m.legs == 5
    expected = _on_circle(angles, r)
    for leg, (fov, dev, curv) in zip(m.leg_metrics, expected):
        assert leg.fov == pytest.approx(fov)
        assert leg.corner_deviation == pytest.approx(dev)
        assert leg.max_curvature == pytest.approx(curv)
        assert leg.complexity == pytest.approx(complexity(fov, curv, dev))
    # leg 0 approaches heading 180 deg and leaves by leg 3 heading 190 (= -170) deg: a 10 degree turn, not 350
    first = m.leg_metrics[0]
    assert first.fov == pytest.approx(105.0)  # nearest neighbour 75 degrees away
    assert first.max_curvature == pytest.approx(105 / (2 * r * math.sin(math.radians(37.5))))
    unwrapped = 350 / (2 * r * math.sin(math.radians(85)))
    assert first.max_curvature < unwrapped


def test_right_turns_only_do_not_conflict():
    r = 10.0
    m = metrics_of(junction_xodr([0, 90, 180, 270], [r] * 4, _right_turns(r)))
    assert m.n_connection_lanes == 4
    # four quarter annuli between radii r - W and r; neighbours touch at one point only. The borders are sampled with
    # a chord error of at most the chord tolerance, so the area may be off by at most that times the perimeter.
    perimeter = 4 * (math.pi / 2 * (2 * r - W) + 2 * W)
    assert m.area == pytest.approx(math.pi * (r * r - (r - W) ** 2), abs=Tolerances().chord * perimeter)
    assert m.conflict_area == 0.0


def test_right_turn_and_straight_overlap_where_they_diverge():
    r = 10.0
    straight_east, right_south = _straight_cross(r)[0], _right_turns(r)[0]  # both leave the west leg's lane
    m = metrics_of(junction_xodr([0, 90, 180, 270], [r] * 4, [straight_east, right_south]))
    # the quarter annulus (centre (-r, -r), radii r - W .. r) inside the band -W <= y <= 0: integrate over y
    # the annulus' x-extent at height y is sqrt(r^2 - (y + r)^2) - sqrt((r - W)^2 - (y + r)^2) (second term 0 if < 0)
    n = 200_000
    total = 0.0
    for k in range(n):
        y = -W + (k + 0.5) * W / n
        dy = y + r
        outer = math.sqrt(max(r * r - dy * dy, 0.0))
        inner = math.sqrt(max((r - W) ** 2 - dy * dy, 0.0))
        total += (outer - inner) * W / n
    annulus = math.pi / 4 * (r * r - (r - W) ** 2)
    bound = Tolerances().chord * (math.pi / 2 * (2 * r - W) + 2 * W)  # chord error times the annulus' perimeter
    assert m.conflict_area == pytest.approx(total, abs=bound)
    assert m.area == pytest.approx(2 * r * W + annulus - total, abs=2 * bound)


def test_lookback_point_sets_the_approach_direction():
    # a leg shorter than LOOKBACK still gives its far end as p0; a straight leg's direction does not depend on it
    data = junction_xodr([0, 90, 180, 270], [10.0] * 4).replace(b'length="100.0"', f'length="{LOOKBACK / 5}"'.encode())
    m = metrics_of(data)
    assert all(leg.fov == pytest.approx(90.0) for leg in m.leg_metrics)


def test_u_turns_are_counted_but_left_out_of_the_area():
    r = 10.0
    # a U-turn from the west leg back into itself: a half circle of radius W/2 ... written as two legs' worth of road
    u_turn = (2, 2, -r, 0.0, 0.0, math.pi * W / 2, 2.0 / W)
    data = junction_xodr([0, 90, 180, 270], [r] * 4, [*_straight_cross(r), u_turn])
    m = metrics_of(data)
    assert m.n_connection_lanes == 5 and m.n_u_turn_lanes == 1
    assert m.area == pytest.approx(8 * r * W - 4 * W * W, rel=1e-9)


def test_direct_junction_has_counts_but_no_interior(corpus_dir):
    result = read(corpus_dir / "esmini/EnvironmentSimulator/Unittest/xodr/direct_junction_simple.xodr")
    (m,) = map_metrics(result.document)
    assert m.type is JunctionType.DIRECT and m.legs == 3 and m.n_connection_lanes > 0
    assert m.area is None and m.conflict_area is None
    assert all(leg.fov is None for leg in m.leg_metrics)


# --------------------------------------------------------------------------------------------------------------------
# Corpus and command line
# --------------------------------------------------------------------------------------------------------------------
@pytest.mark.corpus
def test_carla_towns_give_sane_metrics(corpus_dir):
    towns = sorted((corpus_dir / "carla-towns").rglob("Town0[1-5].xodr"))
    assert towns
    for path in towns:
        metrics = map_metrics(read(path).document)
        assert metrics, path
        for m in metrics:
            assert m.legs >= 2 and m.n_connection_lanes > 0
            assert m.area > 0 and 0 <= m.conflict_area <= m.area + 1e-6
            for leg in m.leg_metrics:
                assert 0 <= leg.fov <= 360 and 0 <= leg.corner_deviation <= 180
                assert leg.max_curvature >= 0 and 0 <= leg.complexity <= 1


def test_cli_csv_and_json(tmp_path, capsys):
    path = tmp_path / "cross.xodr"
    path.write_bytes(junction_xodr([0, 90, 180, 270], [10.0] * 4, _straight_cross(10.0)))
    out = tmp_path / "m.csv"
    assert cli_main(["metrics", str(path), "-o", str(out)]) == 0
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert len(rows) == 4 and {r["road"] for r in rows} == {"L0", "L1", "L2", "L3"}
    assert float(rows[0]["fov_deg"]) == pytest.approx(90.0) and rows[0]["legs"] == "4"
    # every column that has a unit says it in its name
    assert {"x_m", "y_m", "area_m2", "conflict_area_m2", "max_curvature_deg_per_m", "corner_deviation_deg"} <= set(
        rows[0]
    )
    assert not {"fov", "area", "max_curvature", "x"} & set(rows[0])
    assert cli_main(["metrics", "--format", "json", str(path)]) == 0
    doc = json.loads(capsys.readouterr().out)
    (junction,) = doc["junctions"]
    assert junction["conflict_area_m2"] == pytest.approx(4 * W * W) and len(junction["leg_metrics"]) == 4


def test_cli_bad_input_is_one_line(tmp_path, capsys):
    assert cli_main(["metrics", str(tmp_path / "missing.xodr")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no such file" in err
    garbage = tmp_path / "g.xodr"
    garbage.write_text("<OpenDRIVE><road")
    assert cli_main(["metrics", str(garbage)]) == 2  # cannot be read whole: one line, no CSV header either
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "whole" in err and "Traceback" not in err
