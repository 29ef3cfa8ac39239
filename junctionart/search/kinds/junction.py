"""The ``junction`` kind of the search: one intersection of 3 to 7 legs (:mod:`..genome`, :mod:`..measure`)."""

from __future__ import annotations

from typing import Any

from ...intersection import IntersectionSpec, to_dict
from ..genome import DIM, decode
from ..measure import DEFAULT_DESCRIPTORS, METRICS, measure_document
from ..measure import objective as _compactness

__all__ = ["DEFAULT_DESCRIPTORS", "DIM", "METRICS", "decode", "map_bytes", "measure", "objective", "to_dict"]


def map_bytes(spec: IntersectionSpec) -> bytes:
    from ... import to_bytes
    from ...intersection import build

    return to_bytes(build(spec).document, spec.version)


def measure(document: Any) -> dict[str, float] | None:
    if len(document.junctions) != 1:
        return None
    return measure_document(document)


def objective(metrics: dict[str, float]) -> float:
    """compactness 1 / (1 + area / 1000 m^2)"""
    return _compactness(metrics["area"])
