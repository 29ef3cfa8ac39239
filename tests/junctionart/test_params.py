import pytest

from junctionart.errors import ParamsError
from junctionart.params import Params, SplitStrategy, TrafficRule


def test_defaults_are_the_originals():
    p = Params()
    assert (p.snap_distance, p.min_distance, p.max_distance) == (60.0, 100.0, 150.0)
    assert p.transition_table()["parallel"] == {"orthogonal": 0.4, "parallel": 0.3, "random": 0.2, "commonEnd": 0.1}
    assert p.lane_distribution_side == (0.15, 0.6, 0.2, 0.05)
    assert p.version == "1.8" and p.traffic_rule is TrafficRule.RHT


@pytest.mark.parametrize(
    "changes, words",
    [
        ({"width": 10}, ["width=10", "[50, 100000]"]),
        ({"height": float("nan")}, ["height", "finite"]),
        ({"lane_width": 9.0}, ["lane_width=9.0", "[2, 6]"]),
        ({"min_distance": 200.0, "max_distance": 150.0}, ["min_distance=200.0", "max_distance=150.0"]),
        ({"lane_distribution_side": (0.5, 0.5, 0.5, 0.0)}, ["lane_distribution_side", "sum to 1"]),
        ({"lane_distribution_side": (1.0, 0.0, 0.0, 0.0)}, ["at least one of 1, 2, 3"]),
        ({"lane_distribution_control_lines": (0.5, 0.5)}, ["4 probabilities"]),
        ({"median_probability": 1.5}, ["median_probability=1.5", "[0, 1]"]),
        ({"min_turn_radius": 0.1}, ["min_turn_radius=0.1", "[1, 50]"]),
        ({"min_leg_angle": 60.0}, ["min_leg_angle=60.0", "[0, 50]"]),
        ({"min_leg_angle": float("nan")}, ["min_leg_angle=nan"]),
        ({"version": "1.4"}, ["version='1.4'", "1.8, 1.9, 1.7"]),
        ({"n_lines": 1}, ["n_lines=1", "[2, 1000]"]),
        ({"line_spacing": (10.0, 20.0)}, ["line_spacing", "40 m"]),
        ({"gap_scale": (2.0, 1.0)}, ["gap_scale", "must not exceed"]),
        ({"randomize_lanes": "yes"}, ["randomize_lanes='yes'"]),
    ],
)
def test_bad_values_are_named_with_their_range(changes, words):
    with pytest.raises(ParamsError) as err:
        Params(**changes)
    for w in words:
        assert w in str(err.value)


def test_create_from_plain_values():
    p = Params.create(split_strategy="split-last", traffic_rule="LHT", lane_distribution_side=[0.1, 0.4, 0.4, 0.1])
    assert p.split_strategy is SplitStrategy.SPLIT_LAST and p.traffic_rule is TrafficRule.LHT
    with pytest.raises(ParamsError, match=r"split_strategy='middle'.*split-first, split-last, random"):
        Params.create(split_strategy="middle")
    with pytest.raises(ParamsError, match="unknown parameter 'lanes'"):
        Params.create(lanes=3)


def test_transition_table_validated():
    bad = {k: dict(v) for k, v in Params().transition_table().items()}
    bad["orthogonal"]["parallel"] = 0.9
    with pytest.raises(ParamsError, match=r"transitions\['orthogonal'\].*sum to 1"):
        Params.create(transitions=bad)
    bad = {k: dict(v) for k, v in Params().transition_table().items()}
    bad["random"] = {"sideways": 1.0}
    with pytest.raises(ParamsError, match="unknown next state 'sideways'"):
        Params.create(transitions=bad)
    ok = {k: dict(v) for k, v in Params().transition_table().items()}
    ok["start"] = {"parallel": 1.0}
    assert Params.create(transitions=ok).transition_table()["start"] == {"parallel": 1.0}


def test_params_are_checked_before_drawing():
    # the error comes from the constructor: no Params value (hence no map) can exist with a bad field
    with pytest.raises(ParamsError):
        Params().with_(taper_length=1.0)


def test_control_line_lanes_validated():
    assert Params.create(control_line_lanes=[[2, 1], [0, 3]]).control_line_lanes == ((2, 1), (0, 3))
    with pytest.raises(ParamsError, match=r"control_line_lanes\[1\]=\(0, 0\)"):
        Params(control_line_lanes=((1, 1), (0, 0)))
    with pytest.raises(ParamsError, match=r"control_line_lanes\[0\]=\(4, 1\).*\[0, 3\]"):
        Params(control_line_lanes=((4, 1),))
