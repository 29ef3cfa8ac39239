"""Where an object is: road ``s``/``t`` to inertial ``x``/``y``, the object's local frame and its bounding volume.

Positions along a road come from the road's exact reference line (:class:`xodrcheck.geometry.lanes.RoadGeometry`, the
checker's one evaluator of plan views and profiles). A point at lateral ``t`` lies ``t cos(phi)`` beside the
reference line in plan view, ``phi`` the superelevation there (``t`` is measured along the road surface, 13.1 and
:mod:`xodrcheck.geometry.lanes`).

The local frame of an object (8.4, 13.1): origin at the object's ``s``/``t``, ``u`` along the road's heading there
turned by the object's ``hdg``, then pitched and rolled by ``pitch`` and ``roll`` (none with ``perpToRoad="true"``,
which replaces them). Heights are measured from the road reference line: a ``<cornerRoad>``'s ``dz`` and an object's
``zOffset`` are both "relative to the road reference line" (13.1, 13.2.1), so a corner's local height before pitch and
roll is ``dz - zOffset``; an object that follows the road's elevation over its length is not tilted out of its own
bounding volume by a slope (Figure 112: objects small enough not to "cut or float above the road surface").

The bounding volume (13.1) is a box of ``length`` (along ``u``) by ``width`` (along ``v``), centred on the origin, or a
cylinder of ``radius`` around it, both from the origin up to ``height`` (13.14's examples: the outline of a
crosswalk of length 10 at ``s`` = 10 runs from ``s`` = 5 to 15; a tree's crown tops out at its object's height).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.geometry.lanes import RoadGeometry
    from xodrcheck.model import RoadObject

#: Most instances one ``<repeat>`` places (a repeat placing more is taken as its first ones).
MAX_INSTANCES = 10_000


def road_xy(geometry: RoadGeometry, s, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Plan-view ``x``, ``y`` of road points at ``s``/``t``, and the reference line's heading there."""
    s = np.atleast_1d(np.asarray(s, dtype=float))
    t = np.broadcast_to(np.asarray(t, dtype=float), s.shape)
    pose = geometry.reference(s)
    lateral = t * np.cos(geometry.superelevation(s))
    return pose.x - lateral * np.sin(pose.hdg), pose.y + lateral * np.cos(pose.hdg), pose.hdg


@dataclass(frozen=True, slots=True)
class Frame:
    """An object's local frame: origin ``x``, ``y`` (plan view), ``heading`` (inertial), ``pitch``, ``roll``, and the
    origin's height ``z_offset`` above the road reference line."""

    x: float
    y: float
    heading: float
    pitch: float = 0.0
    roll: float = 0.0
    z_offset: float = 0.0

    def to_local(self, x, y, dz) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Local ``u``, ``v``, ``z`` of points at plan-view ``x``, ``y`` and ``dz`` above the road reference line."""
        dx, dy = np.asarray(x, dtype=float) - self.x, np.asarray(y, dtype=float) - self.y
        c, s = math.cos(self.heading), math.sin(self.heading)
        u, v, w = c * dx + s * dy, -s * dx + c * dy, np.asarray(dz, dtype=float) - self.z_offset
        if self.pitch == 0.0 and self.roll == 0.0:
            return u, v, w
        # p = Ry(pitch) Rx(roll) p_local  ->  p_local = Rx(-roll) Ry(-pitch) p
        cp, sp, cr, sr = math.cos(self.pitch), math.sin(self.pitch), math.cos(self.roll), math.sin(self.roll)
        u1, w1 = cp * u - sp * w, sp * u + cp * w
        return u1, cr * v + sr * w1, -sr * v + cr * w1

    def to_plan(self, u, v) -> tuple[np.ndarray, np.ndarray]:
        """Plan-view ``x``, ``y`` of local points on the frame's ground (pitch and roll left out)."""
        c, s = math.cos(self.heading), math.sin(self.heading)
        u, v = np.asarray(u, dtype=float), np.asarray(v, dtype=float)
        return self.x + c * u - s * v, self.y + s * u + c * v


def frame_at(
    geometry: RoadGeometry,
    s: float,
    t: float,
    hdg: float = 0.0,
    pitch: float = 0.0,
    roll: float = 0.0,
    z_offset: float = 0.0,
) -> Frame | None:
    """The local frame at road ``s``/``t`` (``None`` when the road has no reference line there)."""
    x, y, road_hdg = road_xy(geometry, [s], [t])
    if not (math.isfinite(x[0]) and math.isfinite(y[0])):
        return None
    return Frame(float(x[0]), float(y[0]), float(road_hdg[0]) + hdg, pitch, roll, z_offset)


def frame_of(obj: RoadObject, geometry: RoadGeometry) -> Frame | None:
    """The object's local frame (``None`` without ``s``/``t`` or reference line)."""
    if obj.s is None or obj.t is None:
        return None
    tilt = (0.0, 0.0) if obj.perp_to_road else (obj.pitch or 0.0, obj.roll or 0.0)
    return frame_at(geometry, obj.s, obj.t, obj.hdg or 0.0, *tilt, obj.z_offset or 0.0)


@dataclass(frozen=True, slots=True)
class Volume:
    """A bounding volume in the local frame: a box (``radius`` ``None``) of ``length`` by ``width`` centred on the
    origin, or a cylinder of ``radius``; both from height 0 up to ``height`` (``None``: not given, unbounded)."""

    length: float = 0.0
    width: float = 0.0
    radius: float | None = None
    height: float | None = None

    def describe(self) -> str:
        shape = (
            f"cylinder of radius {metres(self.radius)} m"
            if self.radius is not None
            else f"box of length {metres(self.length)} m and width {metres(self.width)} m"
        )
        return shape + (f", height {metres(self.height)} m" if self.height is not None else "")

    def excess(self, u, v, bottom=None, top=None) -> np.ndarray:
        """How far each local point lies outside the volume (0 inside): in plan view, and in height for points with
        a ``bottom`` (and ``top``) height when the volume has a height."""
        u, v = np.asarray(u, dtype=float), np.asarray(v, dtype=float)
        if self.radius is not None:
            out = np.maximum(np.hypot(u, v) - self.radius, 0.0)
        else:
            out = np.maximum(np.maximum(np.abs(u) - self.length / 2, np.abs(v) - self.width / 2), 0.0)
        if self.height is not None and bottom is not None:
            low = np.asarray(bottom, dtype=float)
            high = low if top is None else np.asarray(top, dtype=float)
            out = np.maximum(out, np.maximum(-low, 0.0))
            out = np.maximum(out, np.maximum(high - self.height, 0.0))
        return out

    def corners(self) -> np.ndarray:
        """Plan-view outline ``(N, 2)`` in the local frame: the box's four corners, or 64 points on the cylinder."""
        if self.radius is not None:
            a = np.linspace(0.0, 2 * math.pi, 64, endpoint=False)
            return np.column_stack((self.radius * np.cos(a), self.radius * np.sin(a)))
        lo, wo = self.length / 2, self.width / 2
        return np.array([(-lo, -wo), (lo, -wo), (lo, wo), (-lo, wo)])


def volume_of(obj: RoadObject) -> Volume | None:
    """The object's bounding volume: a box with ``length`` and ``width``, a cylinder with ``radius``; ``None`` when it
    has neither, or both (``object-shape-ambiguous`` reports that), or a size that is not positive."""
    return _volume(obj.length, obj.width, obj.radius, obj.height)


def _volume(length: float | None, width: float | None, radius: float | None, height: float | None) -> Volume | None:
    top = height if height is not None and height >= 0 else None
    if radius is not None:
        if length is not None or width is not None or not radius > 0:
            return None
        return Volume(radius=radius, height=top)
    if length is None or width is None or not length > 0 or width == 0:
        return None
    return Volume(length, abs(width), None, top)


@dataclass(frozen=True, slots=True)
class Instance:
    """One placement of an object: itself, or an instance a discrete ``<repeat>`` places (13.4), with the sizes
    in force there (the repeat's ``*Start``/``*End`` interpolated, else the object's)."""

    s: float
    t: float
    z_offset: float
    volume: Volume | None
    line: int


def _lerp(start: float | None, end: float | None, fallback: float | None, f: np.ndarray) -> np.ndarray | None:
    if start is None and end is None:
        return None if fallback is None else np.full(len(f), fallback)
    a = start if start is not None else end
    b = end if end is not None else start
    if a is None or b is None:  # not both None (above), so each falls back on the other
        return None
    return a + (b - a) * f


def instances(obj: RoadObject) -> list[Instance]:
    """Where the object stands: the object itself when it has no ``<repeat>``, else every instance its discrete
    repeats place (``distance`` > 0: at ``s``, ``s + distance``, ... up to ``s + length``, at most
    :data:`MAX_INSTANCES` each); continuous repeats (``distance`` 0) place no instance."""
    from xodrcheck.geometry.object_shape import repeat_t

    if not obj.repeats:
        if obj.s is None or obj.t is None:
            return []
        return [Instance(obj.s, obj.t, obj.z_offset or 0.0, volume_of(obj), obj.line)]
    out: list[Instance] = []
    for r in obj.repeats:
        if not r.distance > 0 or not r.length >= 0:
            continue
        ratio = r.length / r.distance  # inf when a huge length meets a tiny distance
        count = MAX_INSTANCES if not ratio < MAX_INSTANCES else math.floor(ratio + 1e-9) + 1
        ds = np.arange(count) * r.distance
        f = ds / r.length if r.length > 0 else np.zeros(count)
        t = repeat_t(r, r.s + ds)
        z = _lerp(r.z_offset_start, r.z_offset_end, obj.z_offset or 0.0, f)
        if z is None:  # never: the fallback is a number
            continue
        sizes = [
            _lerp(r.length_start, r.length_end, obj.length, f),
            _lerp(r.width_start, r.width_end, obj.width, f),
            _lerp(r.radius_start, r.radius_end, obj.radius, f),
            _lerp(r.height_start, r.height_end, obj.height, f),
        ]
        circular = obj.radius is not None or r.radius_start is not None or r.radius_end is not None
        for k in range(count):
            length, width, radius, height = (None if a is None else float(a[k]) for a in sizes)
            volume = _volume(None, None, radius, height) if circular else _volume(length, width, None, height)
            out.append(Instance(float(r.s + ds[k]), float(t[k]), float(z[k]), volume, r.line))
    return out
