"""Lane lines of one lane section at an array of ``s``, from one evaluation of its profiles (for
:class:`xodrcheck.lanes.RoadGeometry`, whose module docstring states the conventions).

An :class:`Evaluation` holds what every line at those ``s`` needs (the border jets of ``t``, the superelevation's
cosine and sine, the elevation, the reference pose on first use). From it: the outer border jets of each lane
accumulated outward from lane 0 (:func:`border_jets`), the plan-view lateral offset and height of lane 0's line and of
every lane's borders and centre across rolled and level lanes (:func:`border_lines`, :func:`projected`), and their
plan-view points with heading, curvature and speed along the offset curve (:func:`place`, :func:`bend`).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from xodrcheck.budget import array_bytes
from xodrcheck.geometry import profile
from xodrcheck.geometry.jet import Jet
from xodrcheck.geometry.planview import ReferenceLine
from xodrcheck.geometry.pose import Pose
from xodrcheck.model import Lane


@dataclass(frozen=True, slots=True)
class LanePoints:
    """Points on a lane line (centre or a border): inertial x, y, z, plan-view heading and curvature, and ``speed``,
    the plan-view length of the line per metre of reference-line ``s`` (``integral speed ds`` is the line's length)."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    hdg: np.ndarray
    curvature: np.ndarray
    speed: np.ndarray


@dataclass(frozen=True, slots=True)
class SideLanes:
    """The lanes of one side in effect in a section, inner to outer, with the ``s`` their records are relative to.

    ``laws[i]`` is lane ``i``'s compiled width profile (``is_width[i]``) or border profile, ``None`` for neither."""

    lanes: tuple[Lane, ...]
    origin: float
    laws: tuple[profile.Piecewise | None, ...]
    is_width: tuple[bool, ...]


class Evaluation:
    """Everything lane points at one array of ``s`` in one section need, computed once. ``cos``/``sin`` are the jets
    of the superelevation's cosine and sine, ``None`` on a road without superelevation (no roll anywhere). The
    reference pose is evaluated on first use (lateral ``t`` alone does not need it)."""

    __slots__ = ("_heading", "_pose", "_reference", "borders", "cos", "elevation", "s", "sin")

    def __init__(
        self,
        reference: ReferenceLine,
        s: np.ndarray,
        borders: dict[int, Jet],
        cos: Jet | None,
        sin: Jet | None,
        elevation: np.ndarray,
    ):
        self._reference = reference
        self.s = s
        self.borders = borders
        self.cos = cos
        self.sin = sin
        self.elevation = elevation
        self._pose: Pose | None = None
        self._heading: tuple[np.ndarray, np.ndarray] | None = None

    @property
    def pose(self) -> Pose:
        if self._pose is None:
            self._pose = self._reference.evaluate(self.s)
        return self._pose

    def heading(self) -> tuple[np.ndarray, np.ndarray]:
        """``sin`` and ``cos`` of the reference line's heading (computed once, shared by every lane line)."""
        if self._heading is None:
            self._heading = (np.sin(self.pose.hdg), np.cos(self.pose.hdg))
        return self._heading


def evaluation_size(evaluation: Evaluation) -> int:
    """Bytes an evaluation holds once its pose is computed, about: ``s`` and its key, every border's jet, elevation,
    the roll's jets and the pose with its heading (about 160 bytes of Python per array)."""
    return array_bytes(3 * len(evaluation.borders) + 16, evaluation.s.size)


def border_jets(sides: tuple[SideLanes, SideLanes], offset: tuple, laws: list[tuple]) -> dict[int, Jet]:
    """``t`` of every lane's outer border as a jet (lane 0: the laneOffset line), from the laneOffset's jet and the
    lanes' width or border jets (``laws``: those of the lanes that have one, left lanes inner to outer, then right
    lanes)."""
    centre = Jet(*offset)
    jets = {0: centre}
    values = iter(laws)
    for sign, side in zip((+1, -1), sides):
        inner = centre
        for lane, law, is_width in zip(side.lanes, side.laws, side.is_width):
            if law is None:
                outer = inner
            elif is_width:
                width = Jet(*next(values))
                outer = inner + width if sign > 0 else inner - width
            else:
                outer = Jet(*next(values))
            jets[lane.id] = outer
            inner = outer
    return jets


def stacked_border_lines(
    sides: tuple[SideLanes, SideLanes], evaluation: Evaluation
) -> tuple[list[int], Jet, np.ndarray | float]:
    """:func:`border_lines` as one jet and one height of 2-D arrays, a row per line."""
    ids, laterals, heights = zip(*border_lines(sides, evaluation))
    lateral = Jet(
        np.array([jet.v for jet in laterals]),
        np.array([jet.d1 for jet in laterals]),
        np.array([jet.d2 for jet in laterals]),
    )
    if all(isinstance(h, float) and h == 0.0 for h in heights):
        return list(ids), lateral, 0.0
    n = len(lateral.v[0])
    return list(ids), lateral, np.array([np.broadcast_to(h, n) for h in heights])


def border_lines(
    sides: tuple[SideLanes, SideLanes], evaluation: Evaluation
) -> Iterator[tuple[int, Jet, np.ndarray | float]]:
    """Lane id, plan-view lateral offset and height of lane 0's line, then of every lane's outer border, in the
    order of ``evaluation.borders``: one walk outward per side, lane k's line continuing lane k-1's (as
    :func:`projected` computes them one at a time)."""
    jets = evaluation.borders
    start = centre_line(evaluation)
    yield 0, *start
    seen = {0}
    for side in sides:
        lateral, height = start
        inner = jets[0]
        for lane in side.lanes:
            outer = jets[lane.id]
            lateral, height = rolled(evaluation, lane, lateral, height, outer - inner)
            if lane.id not in seen:  # a duplicated id: the first lane with it, as lane_points gives
                seen.add(lane.id)
                yield lane.id, lateral, height
            inner = outer


def centre_line(evaluation: Evaluation) -> tuple[Jet, np.ndarray | float]:
    """Plan-view lateral offset (jet) and height above the reference line of lane 0's line."""
    centre = evaluation.borders[0]
    if evaluation.cos is None or evaluation.sin is None:  # no superelevation (both or neither)
        return centre, 0.0
    return centre * evaluation.cos, centre.v * evaluation.sin.v


def rolled(
    evaluation: Evaluation, lane: Lane, lateral: Jet, height: np.ndarray | float, step: Jet
) -> tuple[Jet, np.ndarray | float]:
    """Lateral offset and height after moving ``step`` (in ``t``) across ``lane``: rolled by the superelevation
    unless the lane is level or the road has none."""
    if lane.level or evaluation.cos is None or evaluation.sin is None:
        return lateral + step, height
    return lateral + step * evaluation.cos, height + step.v * evaluation.sin.v


def projected(
    sides: tuple[SideLanes, SideLanes], evaluation: Evaluation, lane_id: int, where: str
) -> tuple[Jet, np.ndarray | float]:
    """Plan-view lateral offset (jet) and height above the reference line of a lane line (one the evaluation has),
    superelevation applied."""
    jets = evaluation.borders
    lateral, height = centre_line(evaluation)
    if lane_id == 0:
        return lateral, height
    side = sides[0 if lane_id > 0 else 1]
    inner = jets[0]
    for lane in side.lanes:
        outer = jets[lane.id]
        if lane.id == lane_id:
            target = inner if where == "inner" else outer if where == "outer" else (inner + outer).scale(0.5)
            return rolled(evaluation, lane, lateral, height, target - inner)
        lateral, height = rolled(evaluation, lane, lateral, height, outer - inner)
        inner = outer
    return lateral, height


def bend(pose: Pose, lateral: Jet) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``A = 1 - q k``, the plan-view speed and the curvature of the offset curve at lateral offset ``lateral``."""
    q, dq, ddq = lateral.v, lateral.d1, lateral.d2
    k, dk = pose.curvature, pose.dcurvature
    a = 1.0 - q * k
    speed = np.hypot(a, dq)
    if (speed > 0).all():  # the usual case, without the cost of np.errstate
        return a, speed, (a * a * k + a * ddq + 2.0 * dq * dq * k + q * dq * dk) / speed**3
    with np.errstate(divide="ignore", invalid="ignore"):
        return a, speed, (a * a * k + a * ddq + 2.0 * dq * dq * k + q * dq * dk) / speed**3


def place(evaluation: Evaluation, lateral: Jet, height: np.ndarray | float) -> LanePoints:
    """The plan-view points, height, heading, curvature and speed of a line at lateral offset ``lateral`` (a row per
    line when 2-D) and ``height`` above the reference line."""
    pose = evaluation.pose
    a, speed, curvature = bend(pose, lateral)
    q, dq = lateral.v, lateral.d1
    sin_hdg, cos_hdg = evaluation.heading()
    return LanePoints(
        pose.x - q * sin_hdg,
        pose.y + q * cos_hdg,
        evaluation.elevation + height,
        pose.hdg + np.arctan2(dq, a),
        curvature,
        speed,
    )
