import math

import numpy as np
import pytest

from xodrcheck.geometry import arc, line, spiral
from xodrcheck.geometry.planview import ReferenceLine, evaluate_element
from xodrcheck.model import Arc, Line, ParamPoly3, Poly3, PRange, Spiral


def _chain():
    """Line, spiral, arc, joined end to start (each element starts where the previous one ends)."""
    first = Line(s=0.0, x=0.0, y=0.0, hdg=0.0, length=10.0)
    end = line.evaluate(first, first.length)
    second = Spiral(s=10.0, x=end.x[0], y=end.y[0], hdg=end.hdg[0], length=20.0, curv_start=0.0, curv_end=0.05)
    end = spiral.evaluate(second, second.length)
    third = Arc(s=30.0, x=end.x[0], y=end.y[0], hdg=end.hdg[0], length=15.0, curvature=0.05)
    return [first, second, third]


def test_each_s_is_evaluated_on_its_own_element():
    elements = _chain()
    ref = ReferenceLine(elements)
    s = np.array([0.0, 4.0, 10.0, 17.5, 30.0, 44.0, 45.0])
    pose = ref.evaluate(s)
    expected = [(0, 0.0), (0, 4.0), (1, 0.0), (1, 7.5), (2, 0.0), (2, 14.0), (2, 15.0)]
    for i, (k, ds) in enumerate(expected):
        one = evaluate_element(elements[k], ds)
        assert (pose.x[i], pose.y[i], pose.hdg[i], pose.curvature[i]) == (
            one.x[0],
            one.y[0],
            one.hdg[0],
            one.curvature[0],
        )


def test_a_joint_belongs_to_the_element_starting_there():
    elements = _chain()
    pose = ReferenceLine(elements).evaluate([10.0, 30.0])
    assert pose.curvature[0] == 0.0 and pose.x[0] == elements[1].x  # the spiral at ds=0
    assert pose.curvature[1] == 0.05 and pose.x[1] == elements[2].x  # the arc at ds=0


def test_breakpoints_and_ends():
    ref = ReferenceLine(_chain())
    assert ref.breakpoints.tolist() == [0.0, 10.0, 30.0]
    assert (ref.start, ref.end) == (0.0, 45.0)
    assert ref.element_index([-5.0, 0.0, 9.99, 10.0, 100.0]).tolist() == [0, 0, 0, 1, 2]


def test_s_outside_the_plan_view_is_clamped_to_its_ends():
    elements = _chain()
    pose = ReferenceLine(elements).evaluate([-3.0, 50.0])
    end = arc.evaluate(elements[2], 15.0)
    assert (pose.x[0], pose.y[0]) == (0.0, 0.0)
    assert (pose.x[1], pose.y[1]) == (end.x[0], end.y[0])


def test_elements_out_of_order_are_sorted_by_s():
    elements = _chain()
    ref = ReferenceLine([elements[2], elements[0], elements[1]])
    assert ref.breakpoints.tolist() == [0.0, 10.0, 30.0]
    assert ref.evaluate([12.0]).x[0] == evaluate_element(elements[1], 2.0).x[0]


def test_many_s_at_once_equal_one_at_a_time():
    ref = ReferenceLine(_chain())
    s = np.random.default_rng(3).uniform(0.0, 45.0, 500)
    together = ref.evaluate(s)
    for i in range(0, 500, 50):
        alone = ref.evaluate(s[i])
        assert (alone.x[0], alone.y[0], alone.hdg[0]) == (together.x[i], together.y[i], together.hdg[i])


def test_every_kind_is_dispatched():
    kinds = [
        Line(0.0, 0.0, 0.0, 0.0, 5.0),
        Arc(5.0, 5.0, 0.0, 0.0, 5.0, 0.01),
        Spiral(10.0, 10.0, 0.0, 0.0, 5.0, 0.0, 0.01),
        Poly3(15.0, 15.0, 0.0, 0.0, 5.0, 0.0, 0.0, 0.001, 0.0),
        ParamPoly3(20.0, 20.0, 0.0, 0.0, 5.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.01, 0.0, p_range=PRange.NORMALIZED),
    ]
    pose = ReferenceLine(kinds).evaluate([1.0, 6.0, 11.0, 16.0, 21.0])
    assert np.all(np.isfinite(pose.x)) and np.all(pose.x > [0, 5, 10, 15, 20])


def test_empty_plan_view_gives_nan():
    pose = ReferenceLine([]).evaluate([0.0, 1.0])
    assert np.all(np.isnan(pose.x))


@pytest.mark.parametrize("s", [0.0, 12.5])
def test_scalar_s(s):
    assert len(ReferenceLine(_chain()).evaluate(s)) == 1
    assert math.isfinite(ReferenceLine(_chain()).evaluate(s).x[0])
