"""The ``junction`` kind: every junction no other kind's recogniser claimed, measured by its legs."""

from __future__ import annotations

import math
from collections.abc import Sequence

from xodrcheck.analysis.metrics import junction_legs, smallest_leg_angle
from xodrcheck.model import Document, Junction

from . import Kind, Measure, Structure

KIND = Kind(
    "junction",
    "an ordinary junction: roads meet and traffic may turn from any leg into others",
    (
        Measure("legs", "", 2.5, 7.5, 5, "legs (road ends touching the junction)"),
        Measure("min_angle", "deg", 0.0, 120.0, 12, "smallest angle between neighbouring legs"),
    ),
)


def recognise(document: Document, free: Sequence[Junction]) -> list[Structure]:
    out = []
    for junction in free:
        legs = junction_legs(document, junction)
        angle = smallest_leg_angle(legs)
        values = (("legs", float(len(legs))), ("min_angle", math.nan if angle is None else angle))
        out.append(Structure(KIND.name, (junction.id,), values))
    return out
