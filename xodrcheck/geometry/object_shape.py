"""Shapes of object outlines in the object's local ``u``/``v`` frame (13.2.2, 13.2.3), and repeat ``t`` (13.4).

* a ``<cornerLocal>`` outline is its corners, joined by straight lines;
* a ``<curveLocal>`` starts at ``(u, v)`` with heading ``hdg`` and runs ``length`` along a line, an arc or a
  paramPoly3 (``pRange`` normalized: ``p`` in [0, 1]; arcLength: ``p`` in [0, length]), exactly as the plan-view
  element of the same kind (:func:`xodrcheck.geometry.planview.evaluate_element`, the one evaluator of those shapes);
* a ``<cornerRoad>`` outline is in road ``s``/``t``: :mod:`.object_place` puts it into the local frame;
* a ``<repeat>``'s ``t`` is :attr:`~xodrcheck.model.Repeat.t_profile`, evaluated by
  :mod:`xodrcheck.geometry.profile`.
"""

from __future__ import annotations

import math

import numpy as np

from xodrcheck.model.objects import CornerLocal, CurveLocal, Outline, Repeat


def curve_points(curve: CurveLocal, ds) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``u``, ``v`` and heading of a ``<curveLocal>`` at distances ``ds`` along it (clamped to ``[0, length]``);
    ``None`` when its shape or length is unknown."""
    if curve.shape is None or curve.length is None:
        return None
    from xodrcheck.geometry.planview import evaluate_element

    pose = evaluate_element(curve.shape, np.clip(np.asarray(ds, dtype=float), 0.0, curve.length))
    return pose.x, pose.y, pose.hdg


def curve_end(curve: CurveLocal) -> tuple[float, float, float] | None:
    """``u``, ``v`` and heading where a ``<curveLocal>`` ends (``None``: shape or length unknown): the next curve of a
    continuous outline starts there (13.2.3)."""
    found = curve_points(curve, [curve.length if curve.length is not None else 0.0])
    return None if found is None else (float(found[0][0]), float(found[1][0]), float(found[2][0]))


def outline_uv(outline: Outline, step: float = 0.1) -> tuple[np.ndarray, np.ndarray] | None:
    """The outline as a polyline in the object's ``u``/``v`` frame: its ``<cornerLocal>`` points, or its
    ``<curveLocal>`` curves sampled at most ``step`` metres apart (each curve's end included); ``None`` for a
    ``<cornerRoad>`` outline or a curve whose shape or length is unknown."""
    if outline.curves:
        us, vs = [], []
        for curve in outline.curves:
            length = curve.length or 0.0
            n = max(math.ceil(length / step), 1) + 1
            found = curve_points(curve, np.linspace(0.0, length, n))
            if found is None:
                return None
            us.append(found[0])
            vs.append(found[1])
        return np.concatenate(us), np.concatenate(vs)
    local = [c for c in outline.corners if isinstance(c, CornerLocal)]
    if local and len(local) == len(outline.corners):
        return np.array([c.u for c in local]), np.array([c.v for c in local])
    return None


def repeat_t(repeat: Repeat, s) -> np.ndarray:
    """``t`` of a repeat at road ``s`` (within ``[s, s + length]``), from :attr:`Repeat.t_profile`."""
    from xodrcheck.geometry import profile

    return profile.evaluate((repeat.t_profile,), np.asarray(s, dtype=float))
