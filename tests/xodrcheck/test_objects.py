"""Road objects of the document (the reader's records) and where xodrcheck.objects shapes them, with OpenDRIVE 1.9's
additions: curveLocal outlines evaluated by the plan-view evaluators, repeats along a cubic t, the outer default,
invalidated/temporary, lane-validity layers."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from tests.xodrcheck import schemadocs as D
from xodrcheck.geometry.object_shape import curve_end, curve_points, outline_uv, repeat_t
from xodrcheck.model import LaneLayer, Orientation, RoadObject
from xodrcheck.reader import read
from xodrcheck.rules.shared.context import Context

FEATURES = Path(__file__).parent / "opendrive19" / "features.xodr"


def _read(data: bytes) -> dict[str, tuple[RoadObject, ...]]:
    """Road id -> the road's objects (roads without any left out)."""
    document = read(data).document
    assert document is not None
    return {road.id: road.objects for road in document.roads if road.objects}


def _objects(minor: int, objects: str) -> list[RoadObject]:
    return list(_read(D.doc(minor, road=f"<objects>{objects}</objects>")).get("1", ()))


def _features() -> dict[str, tuple[RoadObject, ...]]:
    return _read(FEATURES.read_bytes())


def test_features_objects_through_the_rule_context():
    data = FEATURES.read_bytes()
    ctx = Context(read(data).document, path=str(FEATURES), data=data)
    island, barrier = ctx.road_objects()
    assert (island.id, island.type, island.s, island.t, island.length, island.width) == (
        "1000",
        "trafficIsland",
        20.0,
        -12.0,
        14.0,
        4.0,
    )
    (outline,) = island.outlines
    assert outline.outer is True and outline.closed is True and outline.fill_type == "grass"
    assert [type(c.shape).__name__ for c in outline.curves] == ["Line", "ParamPoly3", "Line", "Arc"]
    assert (barrier.invalidated, barrier.temporary) == (False, True)
    assert barrier.validities[0].layer is LaneLayer.PERMANENT
    assert {obj.road for obj in ctx.road_objects()} == {"1"}


def test_the_island_outline_is_continuous_and_closed():
    (outline,) = _features()["1"][0].outlines
    curves = outline.curves
    for k, curve in enumerate(curves):
        following = curves[(k + 1) % len(curves)]
        u, v, hdg = curve_end(curve)
        assert math.hypot(u - following.u, v - following.v) < 1e-9, curve.id
        assert math.remainder(hdg - following.hdg, 2 * math.pi) == pytest.approx(0.0, abs=1e-9), curve.id


def test_curve_points_of_each_shape():
    (outline,) = _features()["1"][0].outlines
    line, poly, _, arc = outline.curves
    u, v, hdg = curve_points(line, [0.0, 4.0, 99.0])  # clamped to the curve's length
    np.testing.assert_allclose(u, [-5.0, -1.0, 5.0])
    np.testing.assert_allclose(v, -2.0)
    u, v, _ = curve_points(poly, [poly.length / 2])  # symmetric curve: half its length is p = 0.5
    np.testing.assert_allclose([u[0], v[0]], [5.0 + 6 * 0.5 - 6 * 0.25, -2.0 + 12 * 0.25 - 8 * 0.125], atol=1e-9)
    u, v, hdg = curve_points(arc, [math.pi])  # radius 2: half way (pi m) round the half circle
    np.testing.assert_allclose([u[0], v[0], hdg[0]], [-7.0, 0.0, 1.5 * math.pi], atol=1e-9)


def test_outline_uv_samples_the_curves_within_the_bounding_box():
    (outline,) = _features()["1"][0].outlines
    u, v = outline_uv(outline, step=0.05)
    assert len(u) > 600
    assert u.min() == pytest.approx(-7.0, abs=1e-3) and u.max() == pytest.approx(6.5, abs=1e-3)
    assert v.min() == pytest.approx(-2.0) and v.max() == pytest.approx(2.0)
    assert np.all(np.abs(u) <= 7.0 + 1e-9) and np.all(np.abs(v) <= 2.0 + 1e-9)  # inside length 14 x width 4


def test_param_poly3_with_arc_length_range():
    (obj,) = _objects(
        9,
        '<object id="o" s="1" t="-5" zOffset="0"><outlines><outline>'
        '<curveLocal u="1" v="2" z="0" height="1" hdg="1.5707963267948966" length="3">'
        '<paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="arcLength"/></curveLocal>'
        "</outline></outlines></object>",
    )
    u, v, hdg = curve_end(obj.outlines[0].curves[0])
    assert (u, v, hdg) == pytest.approx((1.0, 5.0, math.pi / 2))


def test_repeat_t_cubic_in_1_9_and_linear_without_coefficients():
    _, barrier = _features()["1"]
    (repeat,) = barrier.repeats
    ds = np.array([0.0, 50.0, 100.0])
    np.testing.assert_allclose(repeat_t(repeat, 50.0 + ds), -3.4 + 1e-5 * ds**2 + 5e-8 * ds**3)
    assert repeat_t(repeat, [150.0])[0] == pytest.approx(repeat.t_end)
    (obj,) = _objects(
        8,
        '<object id="o" s="0" t="-5" zOffset="0"><repeat s="10" length="20" distance="5" tStart="-5" tEnd="-7" '
        'heightStart="1" heightEnd="1" zOffsetStart="0" zOffsetEnd="0"/></object>',
    )
    np.testing.assert_allclose(repeat_t(obj.repeats[0], [10.0, 20.0, 30.0]), [-5.0, -6.0, -7.0])


@pytest.mark.parametrize(("minor", "expected"), [(9, True), (8, None)])
def test_outer_defaults_to_true_from_1_9(minor, expected):
    (obj,) = _objects(minor, f'<object id="o" s="1" t="-5" zOffset="0"><outlines>{D.outline(0)}</outlines></object>')
    assert obj.outlines[0].outer is expected
    inner = D.outline(0).replace(">", ' outer="false">', 1)
    (obj,) = _objects(minor, f'<object id="o" s="1" t="-5" zOffset="0"><outlines>{inner}</outlines></object>')
    assert obj.outlines[0].outer is False


def test_1_9_flags_and_validity_layer_are_not_read_before_1_9():
    text = (
        '<object id="o" s="1" t="-5" zOffset="0" invalidated="true" temporary="1">'
        '<validity fromLane="-1" toLane="-1" layer="temporary"/></object>'
    )
    (new,) = _objects(9, text)
    assert (new.invalidated, new.temporary, new.validities[0].layer) == (True, True, LaneLayer.TEMPORARY)
    (old,) = _objects(8, text)
    assert (old.invalidated, old.temporary, old.validities[0].layer) == (None, None, LaneLayer.PERMANENT)


def test_unparsable_values_give_none_or_are_left_out():
    objects = _objects(
        9,
        '<object s="1" t="0" zOffset="0"/>'  # no id: left out
        '<object id="o" s="x" t="0" zOffset="nan"><outlines><outline>'
        '<curveLocal u="x" v="0" z="0" height="1" hdg="0" length="1"><line/></curveLocal>'
        '<curveLocal u="0" v="0" z="0" height="1" hdg="0"><line/></curveLocal>'
        '<curveLocal u="0" v="0" z="0" height="1" hdg="0" length="1"><arc curvature="?"/></curveLocal>'
        "</outline></outlines></object>",
    )
    (obj,) = objects
    assert obj.s is None and obj.z_offset is None and obj.t == 0.0
    no_length, bad_arc = obj.outlines[0].curves
    assert no_length.length is None and curve_points(no_length, [0.0]) is None
    assert bad_arc.shape is None and curve_end(bad_arc) is None
    assert outline_uv(obj.outlines[0]) is None


def test_objects_of_a_file_with_a_default_namespace():
    data = D.doc(9, road='<objects><object id="o" s="1" t="-5" zOffset="0"/></objects>')
    data = data.replace(b"<OpenDRIVE>", b'<OpenDRIVE xmlns="http://example.com/opendrive">')
    assert [o.id for o in _read(data)["1"]] == ["o"]


def test_corner_local_outline_is_its_corners():
    (obj,) = _objects(9, f'<object id="o" s="1" t="-5" zOffset="0"><outlines>{D.outline(3)}</outlines></object>')
    u, v = outline_uv(obj.outlines[0])
    assert u.tolist() == [0.0, 1.0, 1.0] and v.tolist() == [0.0, 0.0, 1.0]


def test_what_the_object_rules_read_of_the_xml_itself():
    # the rules tell a given attribute from an absent one, and show an invalid value as the file wrote it
    (bad, good) = _objects(
        9,
        '<object id="o" s="1" t="-5" zOffset="0" orientation="up" radius="0.1"><validity fromLane="x" toLane="-1"/>'
        '<outlines><outline id="01"><cornerLocal u="0" v="0" z="0" height="1" id="a"/>'
        '<cornerLocal u="1" v="0" z="0" height="1"/></outline></outlines></object>'
        '<object id="p" s="1" t="-5" zOffset="0" orientation="-"/>',
    )
    assert bad.orientation is None and bad.xml.text("orientation") == "up"
    assert good.orientation is Orientation.MINUS and good.xml.text("orientation") is None
    assert bad.xml.given("radius") and not bad.xml.given("length")
    (validity,) = bad.validities  # kept with the lane that is not an integer as None
    assert (validity.from_lane, validity.to_lane, validity.xml.text("fromLane")) == (None, -1, "x")
    (outline,) = bad.outlines
    assert outline.id == 1 and outline.xml.given("id") and outline.xml.text("id") is None
    named, unnamed = outline.points
    assert named.id is None and named.xml.text("id") == "a"
    assert unnamed.id is None and not unnamed.xml.given("id")
