import math
from dataclasses import replace

import numpy as np
import pytest

from tests.xodrcheck.roadbuild import lane, section, straight, width
from xodrcheck.geometry import spiral
from xodrcheck.geometry.lanes import RoadGeometry, geometry_of
from xodrcheck.model import Arc, Cubic, Document, Lane, LaneHeight, LaneType, Line, Road, Spiral

S = np.array([0.0, 10.0, 37.5, 99.0])


def test_widths_accumulate_outward_from_lane_0():
    g = straight(
        [section(0.0, [lane(1, width(3.0)), lane(2, width(2.0, 0.01))], [lane(-1, width(3.5)), lane(-2, width(1.0))])]
    )
    t = g.borders(0, S)
    assert set(t) == {2, 1, 0, -1, -2}
    assert np.allclose(t[0], 0.0) and np.allclose(t[1], 3.0) and np.allclose(t[2], 5.0 + 0.01 * S)
    assert np.allclose(t[-1], -3.5) and np.allclose(t[-2], -4.5)
    inner, outer = g.inner_outer(0, 2, S)
    assert np.allclose(inner, 3.0) and np.allclose(outer, t[2])
    centre = g.lane_points(0, 2, S)
    assert np.allclose(centre.y, 3.0 + (2.0 + 0.01 * S) / 2) and np.allclose(centre.x, S)
    assert np.allclose(g.lane_points(0, -2, S).y, -4.0)


def test_file_order_of_lanes_does_not_matter():
    g = straight([section(0.0, [lane(2, width(2.0)), lane(1, width(3.0))])])
    assert np.allclose(g.borders(0, S)[2], 5.0)


def test_width_records_are_relative_to_their_section():
    w = (Cubic(0.0, 3.0, 0.0, 0.0, 0.0), Cubic(10.0, 4.0, 0.1, 0.0, 0.0))
    g = straight([section(0.0, [lane(1, width(1.0))]), section(50.0, [lane(1, w)])])
    assert np.allclose(g.borders(1, [55.0, 60.0, 65.0])[1], [3.0, 4.0, 4.5])


def test_lane_offset_shifts_lane_0_and_every_width_lane():
    g = straight([section(0.0, [lane(1, width(3.0))], [lane(-1, width(2.0))])], lane_offset=width(1.0, 0.02))
    t = g.borders(0, S)
    offset = 1.0 + 0.02 * S
    assert np.allclose(g.lane_offset(S), offset)
    assert np.allclose(t[0], offset) and np.allclose(t[1], offset + 3.0) and np.allclose(t[-1], offset - 2.0)
    assert np.allclose(g.lane_points(0, 0, S).y, offset)
    assert np.allclose(g.lane_points(0, -1, S).y, offset - 1.0)


def test_border_records_give_the_outer_border_from_the_reference_line():
    right = [lane(-1, borders=width(-4.0, -0.01)), lane(-2, width(2.0))]
    left = [lane(1, width(3.0), borders=width(10.0))]  # both given: the widths win (11.6.1)
    g = straight([section(0.0, left, right)], lane_offset=width(1.0))
    t = g.borders(0, S)
    assert np.allclose(t[-1], -4.0 - 0.01 * S)  # not shifted by the lane offset
    assert np.allclose(t[-2], -6.0 - 0.01 * S)
    assert np.allclose(t[1], 4.0)
    assert np.allclose(g.lane_points(0, -1, S).y, (1.0 + (-4.0 - 0.01 * S)) / 2)


def test_lane_without_records_is_zero_wide():
    g = straight([section(0.0, [lane(1), lane(2, width(3.0))])])
    t = g.borders(0, S)
    assert np.allclose(t[1], 0.0) and np.allclose(t[2], 3.0)


def test_single_side_section_keeps_the_other_side_of_the_previous_section():
    first = section(0.0, [lane(1, width(3.0))], [lane(-1, width(2.0, 0.01)), lane(-2, width(1.0))])
    left_only = section(40.0, [lane(1, width(3.0)), lane(2, width(2.5))], single_side=True)
    g = straight([first, left_only])
    t = g.borders(1, [50.0, 60.0])
    assert set(t) == {2, 1, 0, -1, -2}
    assert np.allclose(t[-1], [-2.5, -2.6])  # records still relative to the first section's start
    assert np.allclose(t[2], 5.5)
    assert np.allclose(g.lane_points(1, -2, [60.0]).y, -3.1)


def test_section_without_single_side_does_not_inherit():
    g = straight([section(0.0, [lane(1, width(3.0))], [lane(-1, width(2.0))]), section(40.0, [lane(1, width(3.0))])])
    assert set(g.borders(1, [50.0])) == {0, 1}


def test_section_index_gives_a_boundary_to_the_section_starting_there():
    g = straight(
        [
            section(0.0, [lane(1, width(3.0))]),
            section(30.0, [lane(1, width(3.0))]),
            section(60.0, [lane(1, width(3.0))]),
        ]
    )
    assert g.section_index([-1.0, 0.0, 29.9, 30.0, 60.0, 100.0]).tolist() == [0, 0, 0, 1, 2, 2]
    assert g.section_range(1) == (30.0, 60.0) and g.section_range(2) == (60.0, 100.0)


@pytest.mark.parametrize("k", [0.02, -0.02])
def test_lane_centres_on_an_arc_road_are_concentric(k):
    radius = 1.0 / k
    road = Road(
        id="arc",
        length=100.0,
        plan_view=(Arc(0.0, 0.0, 0.0, 0.0, 100.0, k),),
        lane_sections=(section(0.0, [lane(1, width(3.0)), lane(2, width(3.0))], [lane(-1, width(3.0))]),),
    )
    g = RoadGeometry(road)
    s = np.linspace(0.0, 100.0, 11)
    centre = (0.0, radius)
    for lane_id, t in ((1, 1.5), (2, 4.5), (-1, -1.5)):
        p = g.lane_points(0, lane_id, s)
        assert np.allclose(np.hypot(p.x - centre[0], p.y - centre[1]), abs(radius - t), rtol=0, atol=1e-9)
        assert np.allclose(p.curvature, 1.0 / (radius - t), rtol=1e-12)
        assert np.allclose(p.hdg, k * s, rtol=0, atol=1e-12)
        assert np.allclose(p.speed, 1.0 - t * k, rtol=1e-12)


def test_widening_lane_heading_and_curvature_on_a_straight_road():
    w = width(3.0, 0.1, -0.001, 2e-6)
    g = straight([section(0.0, [lane(1, w)])])
    s = np.linspace(0.0, 100.0, 21)
    q = (3.0 + 0.1 * s - 0.001 * s**2 + 2e-6 * s**3) / 2
    dq = (0.1 - 0.002 * s + 6e-6 * s**2) / 2
    ddq = (-0.002 + 12e-6 * s) / 2
    p = g.lane_points(0, 1, s)
    assert np.allclose(p.y, q) and np.allclose(p.hdg, np.arctan(dq), atol=1e-14)
    assert np.allclose(p.curvature, ddq / (1 + dq**2) ** 1.5, rtol=1e-12, atol=1e-15)


def test_lane_curvature_on_a_spiral_with_widening_lane_matches_finite_differences():
    """The offset-curve curvature, with the reference's curvature change and the width change, checked against the
    curvature of the computed points themselves."""
    g = RoadGeometry(
        Road(
            id="sp",
            length=80.0,
            plan_view=(Spiral(0.0, 0.0, 0.0, 0.3, 80.0, 0.0, 0.04),),
            lane_sections=(
                section(0.0, [lane(1, width(3.0, 0.05, 0.001))], [lane(-1, width(3.5, 0.0, -0.0005, 1e-5))]),
            ),
        )
    )
    s0 = np.array([10.0, 40.0, 70.0])
    h = 1e-3
    for lane_id in (1, -1):
        pts = [g.lane_points(0, lane_id, s0 + j * h, where="outer") for j in (-2, -1, 0, 1, 2)]
        x = np.array([p.x for p in pts])
        y = np.array([p.y for p in pts])
        dx = (x[0] - 8 * x[1] + 8 * x[3] - x[4]) / (12 * h)
        dy = (y[0] - 8 * y[1] + 8 * y[3] - y[4]) / (12 * h)
        ddx = (-x[0] + 16 * x[1] - 30 * x[2] + 16 * x[3] - x[4]) / (12 * h * h)
        ddy = (-y[0] + 16 * y[1] - 30 * y[2] + 16 * y[3] - y[4]) / (12 * h * h)
        numeric = (dx * ddy - dy * ddx) / (dx * dx + dy * dy) ** 1.5
        assert np.allclose(pts[2].curvature, numeric, rtol=1e-5, atol=1e-7)
        assert np.allclose(pts[2].hdg, np.arctan2(dy, dx), atol=1e-8)
        assert np.allclose(pts[2].speed, np.hypot(dx, dy), rtol=1e-8)
    reference = spiral.evaluate(g.reference_line.elements[0], s0)
    assert np.allclose(g.reference(s0).x, reference.x)


def test_elevation_gives_z():
    g = straight([section(0.0, [lane(1, width(3.0))])], elevation=width(2.0, 0.05))
    assert np.allclose(g.lane_points(0, 1, S).z, 2.0 + 0.05 * S)


def test_superelevation_rolls_lanes_about_the_reference_line():
    phi = 0.1
    g = straight(
        [section(0.0, [lane(1, width(3.0))], [lane(-1, width(3.0))])], superelevation=width(phi), elevation=width(1.0)
    )
    left = g.lane_points(0, 1, S, where="outer")
    right = g.lane_points(0, -1, S, where="outer")
    assert np.allclose(left.y, 3.0 * math.cos(phi)) and np.allclose(left.z, 1.0 + 3.0 * math.sin(phi))
    assert np.allclose(right.y, -3.0 * math.cos(phi)) and np.allclose(right.z, 1.0 - 3.0 * math.sin(phi))
    assert np.allclose(g.borders(0, S)[1], 3.0)  # t is measured in the rolled plane: the width is unchanged


def test_level_lane_stays_horizontal_from_its_inner_border():
    phi = 0.2
    g = straight(
        [section(0.0, [lane(1, width(3.0)), lane(2, width(2.0), level=True), lane(3, width(1.0))])],
        superelevation=width(phi),
    )
    one, two, three = (g.lane_points(0, i, [5.0], where="outer") for i in (1, 2, 3))
    assert one.y[0] == pytest.approx(3.0 * math.cos(phi)) and one.z[0] == pytest.approx(3.0 * math.sin(phi))
    assert two.y[0] == pytest.approx(one.y[0] + 2.0) and two.z[0] == pytest.approx(one.z[0])
    assert three.y[0] == pytest.approx(two.y[0] + math.cos(phi)) and three.z[0] == pytest.approx(
        two.z[0] + math.sin(phi)
    )


def test_lane_height_lifts_a_lane_normal_to_the_rolled_surface():
    """``<height>`` raises a lane's edges along the h-axis, normal to the superelevated surface (11.7.3); records hold
    from their sOffset (relative to the section) on, the centre takes the mean; the shared border lines stay."""
    phi, s = 0.1, np.array([5.0, 30.0])
    raised = Lane(id=-2, type=LaneType.SIDEWALK, widths=width(2.0), heights=(LaneHeight(20.0, 0.1, 0.2),))
    g = straight(
        [section(0.0, right=[lane(-1, width(3.0))]), section(10.0, right=[lane(-1, width(3.0)), raised])],
        superelevation=width(phi),
    )
    inner, outer = g.lane_height(1, -2, s)
    assert list(inner) == [0.0, 0.1] and list(outer) == [0.0, 0.2]  # 0 before the first record (s < 10 + 20)
    for where, t, h in (("inner", -3.0, 0.1), ("outer", -5.0, 0.2), ("centre", -4.0, 0.15)):
        p = g.lane_points(1, -2, [30.0], where=where, raised=True)
        assert p.y[0] == pytest.approx(t * math.cos(phi) - h * math.sin(phi))
        assert p.z[0] == pytest.approx(t * math.sin(phi) + h * math.cos(phi))
    plain = g.lane_points(1, -2, [30.0], where="outer")
    assert plain.z[0] == pytest.approx(-5.0 * math.sin(phi))  # without raised: the road surface
    level = straight(
        [section(0.0, right=[lane(-1, width(3.0)), replace(raised, level=True)])], superelevation=width(phi)
    )
    p = level.lane_points(0, -2, [30.0], where="outer", raised=True)
    assert p.y[0] == pytest.approx(-3.0 * math.cos(phi) - 2.0) and p.z[0] == pytest.approx(-3.0 * math.sin(phi) + 0.2)
    assert not g.has_height(1, -1) and g.lane_height(1, -1, s)[1].tolist() == [0.0, 0.0]


def test_changing_superelevation_enters_heading_and_curvature():
    g = straight([section(0.0, [lane(1, width(3.0))])], superelevation=width(0.0, 0.004))
    s = np.array([20.0, 50.0])
    p = g.lane_points(0, 1, s, where="outer")
    phi = 0.004 * s
    q, dq, ddq = 3 * np.cos(phi), -3 * np.sin(phi) * 0.004, -3 * np.cos(phi) * 0.004**2
    assert np.allclose(p.y, q) and np.allclose(p.hdg, np.arctan(dq))
    assert np.allclose(p.curvature, ddq / (1 + dq**2) ** 1.5, rtol=1e-10)


def test_bad_requests_are_reported():
    g = straight([section(0.0, [lane(1, width(3.0))])])
    with pytest.raises(KeyError):
        g.lane_points(0, -1, S)
    with pytest.raises(ValueError):
        g.lane_points(0, 1, S, where="middle")


def test_geometry_of_is_lazy_and_cached():
    roads = tuple(
        Road(
            id=str(i),
            length=10.0,
            plan_view=(Line(0.0, 0.0, float(i), 0.0, 10.0),),
            lane_sections=(section(0.0, [lane(1, width(3.0))]),),
        )
        for i in range(3)
    )
    document = Document(header=None, roads=roads)
    geometry = geometry_of(document)
    assert geometry is geometry_of(document)
    assert len(geometry) == 3 and list(geometry) == ["0", "1", "2"]
    assert not geometry.built()
    assert geometry["1"] is geometry["1"] and geometry["1"].road is roads[1]
    assert geometry.built() == ["1"]
    with pytest.raises(KeyError):
        geometry["nope"]
