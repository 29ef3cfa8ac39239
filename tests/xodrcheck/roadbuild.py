"""Small builders of model roads for the geometry and lane tests."""

from __future__ import annotations

from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.model import Cubic, Lane, LaneSection, LaneType, Line, Road


def width(a, b=0.0, c=0.0, d=0.0, s=0.0):
    return (Cubic(s, a, b, c, d),)


def lane(lane_id, widths=(), borders=(), level=False):
    return Lane(id=lane_id, type=LaneType.DRIVING, widths=widths, borders=borders, level=level)


def section(s, left=(), right=(), single_side=None):
    return LaneSection(s=s, single_side=single_side, left=tuple(left), center=(lane(0),), right=tuple(right))


def straight(sections, length=100.0, **road):
    """A road along the x axis from the origin."""
    return RoadGeometry(
        Road(
            id="r", length=length, plan_view=(Line(0.0, 0.0, 0.0, 0.0, length),), lane_sections=tuple(sections), **road
        )
    )
