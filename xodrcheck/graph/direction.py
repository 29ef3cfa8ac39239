"""Which way traffic drives on a lane (11.3.1).

A lane's side and its road's traffic rule give its standard direction: with ``RHT`` the right lanes (negative ids)
drive along the reference line (increasing s) and the left lanes against it; ``LHT`` the other way round. The 1.8
``@direction`` reverses it (``reversed``) or allows both (``both``, as does the deprecated lane type
``bidirectional``). Directions are ``+1`` (along s) and ``-1`` (against s).
"""

from __future__ import annotations

from xodrcheck.model import ContactPoint, Lane, Road
from xodrcheck.rules.shared.context import travel_direction

__all__ = ["entering", "leaving", "travels"]

ALONG, AGAINST = 1, -1


def travels(road: Road, lane: Lane) -> tuple[int, ...]:
    """The directions traffic may drive on ``lane`` of ``road``: ``(1,)``, ``(-1,)``, ``(1, -1)`` for both ways;
    ``()`` for the centre lane 0. The one direction is :func:`xodrcheck.rules.shared.context.travel_direction`'s (side,
    traffic rule, ``reversed``); a lane open both ways (``both``, type ``bidirectional``) or of a type that carries no
    directed traffic (a sidewalk, say, in a graph asked to hold one) is driven both ways."""
    if lane.id == 0:
        return ()
    one = travel_direction(road, lane)
    return (ALONG, AGAINST) if one is None else (one,)


def leaving(travel: int) -> ContactPoint:
    """The end of a lane section (or road) that traffic driving ``travel`` leaves by."""
    return ContactPoint.END if travel > 0 else ContactPoint.START


def entering(end: ContactPoint) -> int:
    """The direction of traffic that enters a road (or lane section) at ``end``: away from it."""
    return ALONG if end is ContactPoint.START else AGAINST
