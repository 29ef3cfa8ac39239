"""junctionart: procedural OpenDRIVE road networks after the JunctionArt paper.

``generate(params, seed)`` runs the four stages (control lines -> graph -> lanes -> intersections -> cleanup) and
returns the generator's own document model; ``write(document, path, version)`` writes it atomically.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .errors import InputError, JunctionArtError, ParamsError

if TYPE_CHECKING:
    from . import intersections, lanes, network
    from .controllines import ControlLines
    from .opendrive import Document
    from .params import Params
    from .writer import to_bytes

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

#: Public names that load their module on first use (PEP 562), so ``junctionart --help`` and the command line's
#: argument parsing import no stage of the generator (nor numpy).
_LAZY = {
    "ControlLines": "controllines",
    "Document": "opendrive",
    "Params": "params",
    "to_bytes": "writer",
}
#: The stage modules (any submodule is an attribute of the package on first use: ``junctionart.network``, ...).
_STAGE_MODULES = frozenset({"cleanup", "controllines", "intersections", "lanes", "network"})


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    elif name.startswith("__"):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    else:  # a submodule, as when the package imported every stage itself
        try:
            value = importlib.import_module(f"{__name__}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__name__}.{name}":
                raise
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY) | _STAGE_MODULES)


@dataclass(frozen=True)
class Result:
    """Every stage's value of one run (for tests, metrics and debugging)."""

    control_lines: ControlLines
    network: network.Network
    laned: lanes.LanedNetwork
    layout: intersections.Layout
    document: Document
    #: requests of the control-line file (forks, ramps) that could not be met, each with its reason
    notes: tuple[str, ...] = ()


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
    import numpy as np

    from . import cleanup, controllines, intersections, lanes, network
    from .params import Params

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
    notes: list[str] = []
    requests = () if control_lines is None else control_lines.requests
    if params.structures or requests:
        from .splits.network import add

        doc, notes = add(doc, params, int(seed), requests)
    return Result(lines, net, laned, layout, doc, tuple(notes))


def generate(params: Params | None = None, seed: int = 0, control_lines: ControlLines | None = None) -> Document:
    """A road network as the generator's document model."""
    return generate_layout(params, seed, control_lines).document


def write(document: Document, path: str | Path, version: str = "1.8") -> Path:
    """Write ``document`` as OpenDRIVE ``version`` ("1.8", "1.9" or "1.7") to ``path``, atomically."""
    from .writer import write as _write

    return _write(document, path, version)
