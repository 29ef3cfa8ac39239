"""Which way traffic drives on a lane (11.3.1).

A lane's side and its road's traffic rule give its standard direction: with ``RHT`` the right lanes (negative ids)
drive along the reference line (increasing s) and the left lanes against it; ``LHT`` the other way round. The 1.8
``@direction`` reverses it (``reversed``) or allows both (``both``, as does the deprecated lane type
``bidirectional``). Directions are ``+1`` (along s) and ``-1`` (against s).
"""

from __future__ import annotations

from xodrcheck.model import ContactPoint, Lane, LaneDirection, LaneType, Road, TrafficRule

__all__ = ["entering", "leaving", "travels"]

ALONG, AGAINST = 1, -1


def travels(road: Road, lane: Lane) -> tuple[int, ...]:
    """The directions traffic may drive on ``lane`` of ``road``: ``(1,)``, ``(-1,)``, ``(1, -1)`` for both ways;
    ``()`` for the centre lane 0."""
    if lane.id == 0:
        return ()
    if lane.direction is LaneDirection.BOTH or lane.type is LaneType.BIDIRECTIONAL:
        return (ALONG, AGAINST)
    along = (lane.id < 0) == (road.rule is TrafficRule.RHT)
    if lane.direction is LaneDirection.REVERSED:
        along = not along
    return (ALONG,) if along else (AGAINST,)


def leaving(travel: int) -> ContactPoint:
    """The end of a lane section (or road) that traffic driving ``travel`` leaves by."""
    return ContactPoint.END if travel > 0 else ContactPoint.START


def entering(end: ContactPoint) -> int:
    """The direction of traffic that enters a road (or lane section) at ``end``: away from it."""
    return ALONG if end is ContactPoint.START else AGAINST
