"""junctionart: procedural OpenDRIVE road networks after the JunctionArt paper.

``generate(params, seed)`` runs the four stages (control lines -> graph -> lanes -> intersections -> cleanup) and
returns the generator's own document model; ``write(document, path, version)`` writes it atomically.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from xodrcheck.classcache import dataclass

from . import cleanup, controllines, intersections, lanes, network
from .controllines import ControlLines
from .errors import InputError, JunctionArtError, ParamsError
from .opendrive import Document
from .params import Params
from .writer import to_bytes
from .writer import write as _write

__all__ = [
    "STAGES",
    "ControlLines",
    "Document",
    "InputError",
    "JunctionArtError",
    "Params",
    "ParamsError",
    "Result",
    "generate",
    "generate_layout",
    "to_bytes",
    "write",
]


@dataclass(frozen=True)
class Result:
    """Every stage's value of one run (for tests, metrics and debugging)."""

    control_lines: ControlLines
    network: network.Network
    laned: lanes.LanedNetwork
    layout: intersections.Layout
    document: Document


#: Names of the stages, in order, as passed to ``on_stage``.
STAGES = ("control lines", "network", "lanes", "intersections", "cleanup")


def generate_layout(
    params: Params | None = None,
    seed: int = 0,
    control_lines: ControlLines | None = None,
    on_stage: Callable[[str], None] | None = None,
) -> Result:
    """Run all stages; randomness comes from one ``numpy.random.Generator`` seeded with ``seed``.

    ``on_stage`` (for progress bars) is called with each name of :data:`STAGES` as that stage starts.
    """
    params = params if params is not None else Params()
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ParamsError(f"seed={seed!r}: must be a non-negative integer")
    step = on_stage or (lambda name: None)
    rng = np.random.default_rng(int(seed))
    step(STAGES[0])
    lines = control_lines if control_lines is not None else controllines.automatic(params, rng)
    step(STAGES[1])
    net = network.build(lines, params, rng)
    step(STAGES[2])
    laned = lanes.assign(net, lines, params, rng)
    step(STAGES[3])
    layout = intersections.build(laned, params, rng)
    step(STAGES[4])
    doc = cleanup.document(layout, params, name=f"junctionart seed {int(seed)}")
    if params.scenario:
        from .scenario.dress import dress

        doc = dress(doc, layout, params, int(seed))
    return Result(lines, net, laned, layout, doc)


def generate(params: Params | None = None, seed: int = 0, control_lines: ControlLines | None = None) -> Document:
    """A road network as the generator's document model."""
    return generate_layout(params, seed, control_lines).document


def write(document: Document, path: str | Path, version: str = "1.8") -> Path:
    """Write ``document`` as OpenDRIVE ``version`` ("1.8", "1.9" or "1.7") to ``path``, atomically."""
    return _write(document, path, version)
