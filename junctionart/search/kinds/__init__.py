"""The kinds of structure ``junctionart search --kind`` searches: each brings its genome, its builder and its measures.

A kind is a module (:data:`MODULES`, named after a kind of :mod:`xodrcheck.structures`) that provides

* ``DIM``: the genome's length (every gene in [0, 1]);
* ``METRICS``: name -> (low, high, default cells) of every value measured on a candidate: the names ``--descriptors``
  and ``--where`` may use;
* ``DEFAULT_DESCRIPTORS``: two or three of them;
* ``decode(x) -> spec`` (a pure function: a vector stands for exactly one description) and ``to_dict(spec)`` (the
  description written beside an elite's map);
* ``map_bytes(spec) -> bytes``: the map the description builds, as written;
* ``measure(document) -> dict | None``: ``METRICS``' values of the map's one structure of the kind, read back by
  xodrcheck (None when the map holds no such structure);
* ``objective(metrics) -> float``: the quality an elite maximises within its cell, in (0, 1].
"""

from __future__ import annotations

import importlib
from types import ModuleType

from ...errors import ParamsError

#: kind -> module.
MODULES = {
    "junction": "junctionart.search.kinds.junction",
    "fork": "junctionart.search.kinds.fork",
    "ramp": "junctionart.search.kinds.ramp",
    "roundabout": "junctionart.search.kinds.roundabout",
}


def get(name: str) -> ModuleType:
    """The module of kind ``name``; :class:`ParamsError` naming the kinds when there is none."""
    if name not in MODULES:
        raise ParamsError(f"--kind {name!r}: choose from {', '.join(MODULES)}")
    return importlib.import_module(MODULES[name])
