"""Where road marks let traffic change between two neighbouring lanes of a lane section (11.9).

The line between two lanes of one side is the ``<roadMark>`` of the inner one (the one nearer lane 0: a mark describes
its lane's outer border); between lane 1 and lane -1 it is lane 0's. A record holds from its ``sOffset`` until the
next record or the section's end; where no record holds there is no line. What a line allows:

* its ``laneChange`` when the file gives one (``increase``: towards the higher lane id, ``decrease``: towards the
  lower, ``both``, ``none``);
* otherwise its ``type``: ``none``, ``broken``, ``broken broken`` and ``botts dots`` let traffic cross both ways;
  ``solid``, ``solid solid``, ``curb``, ``grass`` and ``edge`` do not (a line, a kerb, a verge, the usable space's
  limit); ``solid broken`` and ``broken solid`` only from their broken side (they are named from inside to outside, the
  centre line from left to right: ``solid broken`` of lane -1 lets lane -2 cross into lane -1, not back);
  ``custom`` (its lines are not read) and unknown types do not.

The standard's default for a missing ``laneChange`` is ``both``, whatever the type; read literally it would let traffic
cross every solid line of a file that leaves the attribute out, so the type decides then.
"""

from __future__ import annotations

from xodrcheck.model import LaneSection, RoadMark

__all__ = ["crossable", "line_owner"]

_BOTH_WAYS = frozenset({"none", "broken", "broken broken", "botts dots"})
_LANE_CHANGE = {"both": (True, True), "none": (False, False), "increase": (True, False), "decrease": (False, True)}


def line_owner(a: int, b: int) -> int:
    """The lane whose road mark is the line between neighbouring lanes ``a`` and ``b``."""
    if (a > 0) != (b > 0):
        return 0
    return a if abs(a) < abs(b) else b


def _allows(mark: RoadMark, owner: int) -> tuple[bool, bool]:
    """(towards the higher id, towards the lower id) across the line ``mark`` draws beside lane ``owner``."""
    if mark.lane_change is not None:
        found = _LANE_CHANGE.get(mark.lane_change.strip().lower())
        if found is not None:
            return found
    kind = " ".join(mark.type.strip().lower().split())
    if kind in _BOTH_WAYS:
        return True, True
    # "from inside to outside" (centre: left to right); the broken side may cross. On the right and in the centre the
    # first-named line is on the higher id's side, on the left on the lower id's.
    if kind in ("solid broken", "broken solid"):
        upward = (kind == "solid broken") == (owner <= 0)
        return upward, not upward
    return False, False


def crossable(section: LaneSection, length: float, a: int, b: int) -> list[tuple[float, float]]:
    """The stretches ``(start, end)`` of the section (s from the section's start, within ``[0, length]``) where traffic
    may cross from lane ``a`` into its neighbour ``b``."""
    owner = line_owner(a, b)
    lane = section.lane(owner)
    marks = sorted(lane.road_marks, key=lambda m: m.s) if lane is not None else []
    upward = b > a
    out: list[tuple[float, float]] = []
    starts = [m.s for m in marks]
    if not marks or starts[0] > 0:
        out.append((0.0, min(starts[0], length) if marks else length))
    for k, mark in enumerate(marks):
        start = min(mark.s, length)
        stop = min(starts[k + 1], length) if k + 1 < len(marks) else length
        if stop <= start and not (stop == start == length == 0):
            continue
        if _allows(mark, owner)[0 if upward else 1]:
            out.append((start, stop))
    return out
