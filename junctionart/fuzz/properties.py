"""The properties the fuzzers check, as plain functions (used by ``tests/fuzz`` and by ``python -m junctionart.fuzz``).

Each raises :class:`AssertionError` with a readable message when the property fails and counts what it checked in
:data:`STATS`. Maps are judged by the checker's ``generator`` profile: every rule at its own severity, so what the
generator guarantees (the JunctionArt paper's junction rules, the minimum radius, ...) stays an error.
"""

from __future__ import annotations

import math
import time
from collections import Counter
from itertools import pairwise

import numpy as np
from scipy.integrate import quad

import junctionart as ja
from junctionart import curves
from xodrcheck.check import Report, check
from xodrcheck.config import Config, Tolerances
from xodrcheck.findings import ReadError, Severity
from xodrcheck.geometry.planview import ReferenceLine
from xodrcheck.reader import read

__all__ = [
    "GENERATOR",
    "HANG_SECONDS",
    "ROUND_TRIP_TOLERANCE",
    "STATS",
    "checked",
    "checker_survives",
    "defect_is_found",
    "document_is_valid",
    "errors",
    "finding_keys",
    "generated_map_is_connected",
    "generated_map_is_valid",
    "invalid_input_refused",
    "round_trip_exact",
]


#: Counters of the inputs each property saw (``maps``, ``documents``, ``damaged``, ``refused``...).
STATS: Counter = Counter()
#: A check of one small document that takes longer than this (s) is treated as hanging.
HANG_SECONDS = 60.0
#: Largest distance (m) between the generator's curve and the reader's at the same s.
ROUND_TRIP_TOLERANCE = 1e-9
_ENGINE = ("X900", "X901")
#: How the checker judges what the fuzzers give it (see the module docstring).
GENERATOR = Config(profile="generator")


def errors(report: Report) -> list[str]:
    return [f"{f.code} {f.name}: {f.message}" for f in report.findings if f.severity >= Severity.ERROR]


def checked(data: bytes, config: Config | None = None, tolerated: frozenset[str] = frozenset()) -> Report:
    """Check ``data`` (by ``config``, the :data:`GENERATOR` profile unless given) and assert the checker itself
    behaved: no exception, no rule crashed, bounded time. A crash whose message contains one of ``tolerated`` (open
    known faults) is counted in ``STATS["tolerated"]`` instead."""
    started = time.monotonic()
    try:
        report = check(data, config or GENERATOR)
    except ReadError:  # the one clear error check() may raise (input cannot be opened at all)
        STATS["read-errors"] += 1
        raise
    elapsed = time.monotonic() - started
    assert elapsed < HANG_SECONDS, f"check took {elapsed:.1f} s on a {len(data)}-byte document"
    crashed = [f"{f.code}: {f.message}" for f in report.findings if f.code in _ENGINE]
    known = [c for c in crashed if any(t in c for t in tolerated)]
    STATS["tolerated"] += len(known)
    crashed = [c for c in crashed if c not in known]
    assert not crashed, "the checker failed on this input:\n" + "\n".join(crashed)
    return report


def checker_survives(data: bytes, tolerated: frozenset[str] = frozenset()) -> Report | None:
    """Any document, however damaged: findings or a clear error (``None``), never a crash (but the ``tolerated``
    known ones, see :func:`checked`)."""
    STATS["damaged"] += 1
    try:
        return checked(data, tolerated=tolerated)
    except ReadError:
        return None


def document_is_valid(data: bytes) -> Report:
    """A document of :func:`fuzz.opendrive_documents`: the checker finds no error in it."""
    STATS["documents"] += 1
    report = checked(data)
    assert report.ok, "a valid document was reported:\n" + "\n".join(errors(report))
    return report


def defect_is_found(data: bytes, expected: frozenset[str]) -> Report:
    """A document with one known defect: at least one of the ``expected`` codes is reported."""
    STATS["defects"] += 1
    report = checked(data)
    found = {f.code for f in report.findings}
    assert found & expected, f"none of {sorted(expected)} reported; found {sorted(found)}"
    return report


def generated_map_is_valid(params: ja.Params, seed: int, lines=None, tolerated: frozenset[str] = frozenset()) -> bytes:
    """Valid generator input: a map on which the checker finds no error (returned as bytes).

    The checker's default curvature bound applies, relaxed to ``params.min_turn_radius`` when the user asked the
    generator for tighter turns than that (a map drawn for 3 m turns is right to have a 4 m curve). That the generator
    keeps every lane centre above a *larger* ``min_turn_radius`` is checked on the ``min-turn-radius`` regressions
    (:data:`fuzz.profiles.REGRESSIONS`). Errors with a code in ``tolerated`` (open known faults,
    :func:`fuzz.profiles.tolerated`) are counted in ``STATS["tolerated"]`` instead of failing."""
    doc = ja.generate(params, seed, lines)
    data = ja.to_bytes(doc, params.version)
    STATS["maps"] += 1
    bound = min(Tolerances().min_radius, params.min_turn_radius)
    report = checked(data, Config(tolerances=Tolerances(min_radius=bound), profile="generator"))
    found = errors(report)
    left = [e for e in found if e.split(" ", 1)[0] not in tolerated]
    STATS["tolerated"] += len(found) - len(left)
    assert not left, f"generated map (seed {seed}) has errors:\n" + "\n".join(left[:20])
    generated_map_is_connected(data, report, seed, tolerated)
    return data


#: The checker's rules over the lane graph (:mod:`xodrcheck.rules.reach`): warnings, which a generated map has none of.
REACH_RULES = ("L040", "L041", "L042", "J040")


def generated_map_is_connected(
    data: bytes, report: Report | None = None, seed: int | None = None, tolerated: frozenset[str] = frozenset()
) -> None:
    """A generated map is strongly connected at lane level through its open edges: every drivable lane (driven
    each way it may be) is reached from a lane where traffic enters the map and reaches one where it leaves (on a
    map without open edges: from and to every other lane), and the lane-graph rules find nothing (no dead end, no
    lane nothing enters, no trap, no junction approach without a way through). No parameter allows a dead end: the
    generator links every lane it draws, marks a line crossable beside every lane that opens or closes, gives a
    one-way road a lane back where the network would otherwise have a part without a way in or out (also after the
    layout's repairs), and lets a road that loops back to its junction be entered from, and turn off into, its other
    roads. A finding with a code in ``tolerated`` (an open known fault of
    :data:`fuzz.profiles.REGRESSIONS`) is counted in ``STATS["tolerated"]``, and the lanes it strands are not held
    against the map."""
    from xodrcheck.graph import lane_graph
    from xodrcheck.graph.reach import entries, exits, reached

    STATS["connected"] += 1
    where = "" if seed is None else f" (seed {seed})"
    report = report if report is not None else checked(data)
    found = [f"{f.code} {f.name}: {f.message}" for f in report.findings if f.code in REACH_RULES]
    known = [f for f in found if f.split(" ", 1)[0] in tolerated]
    STATS["tolerated"] += len(known)
    found = [f for f in found if f not in known]
    assert not found, f"generated map{where} is not connected:\n" + "\n".join(found[:20])
    if known:
        return
    result = read(data)
    assert result.document is not None
    graph = lane_graph(result.document)
    if not graph.nodes:
        return
    ins, outs = entries(graph), exits(graph)
    for label, sources, reverse in (("reached from an entry", ins, False), ("leading to an exit", outs, True)):
        hit = reached(graph, sources if len(sources) else [0], reverse=reverse)
        missed = [graph.nodes[i].describe() for i in np.flatnonzero(~hit)]
        assert not missed, f"generated map{where}: lanes not {label}: {', '.join(missed[:10])}"


def invalid_input_refused(action, tmp_file=None) -> str:
    """Invalid generator input: ``action()`` raises the generator's error type with a message (and writes no file
    at ``tmp_file``). Returns the message."""
    STATS["invalid-inputs"] += 1
    try:
        action()
    except ja.JunctionArtError as exc:
        message = str(exc)
        assert message and "\n" not in message, f"unclear error message {message!r}"
        if tmp_file is not None:
            assert not tmp_file.exists(), f"{tmp_file} was written although the input was refused"
        STATS["refused"] += 1
        return message
    raise AssertionError("invalid input was accepted")


def finding_keys(report: Report, rename: dict[str, str] | None = None) -> Counter:
    """What the metamorphic properties compare: (code, road, lane) of every finding, roads renamed by ``rename``."""
    rename = rename or {}
    return Counter(
        (f.code, rename.get(f.road, f.road) if f.road is not None else None, f.lane) for f in report.findings
    )


def _arc_lengths(g, p: np.ndarray) -> np.ndarray:
    """Arc length of a generator paramPoly3 from its start to each ``p`` (adaptive quadrature to ~1e-12 m)."""

    def speed(q: float) -> float:
        return math.hypot(g.bu + q * (2.0 * g.cu + 3.0 * g.du * q), g.bv + q * (2.0 * g.cv + 3.0 * g.dv * q))

    steps = [quad(speed, a, b, epsabs=1e-13, epsrel=1e-13, limit=200)[0] for a, b in pairwise(p)]
    return np.concatenate(([0.0], np.cumsum(steps)))


def _positions(mine, n: int) -> tuple[np.ndarray, np.ndarray]:
    """``(ds, xy)``: ``n`` points of a generator element and their distance from its start along the curve.

    Lines and arcs: equal steps of arc length. paramPoly3 (``pRange="normalized"``): equal steps of ``p``, the
    generator's own polynomial evaluated there, and ``ds`` the true arc length up to ``p`` rescaled so that ``p = 1``
    falls at the declared ``@length`` (what the reader does, see :mod:`xodrcheck.geometry.parampoly3`); the comparison
    is then independent of how each side steps along the curve."""
    t = np.linspace(0.0, 1.0, n)
    xy = curves.sample(mine, n)
    if not isinstance(mine, ja.opendrive.ParamPoly3):
        return t * mine.length, xy
    sigma = _arc_lengths(mine, t)
    return sigma * (mine.length / sigma[-1]), xy


def round_trip_exact(doc, samples: int = 17) -> int:
    """Generator model -> .xodr -> xodrcheck reader: the same plan view, parameters exactly and positions within
    :data:`ROUND_TRIP_TOLERANCE` at ``samples`` points per element, ends and interior. Returns the number of
    elements compared."""
    result = read(ja.to_bytes(doc))
    assert result.document is not None, "the reader could not read a generated map"
    by_id = result.document.road_by_id
    compared = 0
    for road in doc.roads:
        other = by_id.get(road.id)
        assert other is not None, f"road {road.id} was not read back"
        assert other.length == road.length, f"road {road.id}: length {other.length!r} != {road.length!r}"
        assert len(other.plan_view) == len(road.geometry), f"road {road.id}: element count differs"
        ref = ReferenceLine(other.plan_view)
        for mine, theirs in zip(road.geometry, other.plan_view):
            for name in ("s", "x", "y", "hdg", "length"):
                assert getattr(mine, name) == getattr(theirs, name), f"road {road.id}: {name} differs"
            ds, expected = _positions(mine, samples)
            pose = ref.evaluate(np.minimum(mine.s + ds, np.nextafter(mine.s + mine.length, -np.inf)))
            gap = np.hypot(pose.x - expected[:, 0], pose.y - expected[:, 1])
            worst = int(np.argmax(gap))
            assert gap[worst] <= ROUND_TRIP_TOLERANCE, (
                f"road {road.id} {type(mine).__name__} at s={mine.s}: generator and reader differ by "
                f"{gap[worst]:.3g} m at ds={ds[worst]:.6g}"
            )
            compared += 1
    STATS["round-trips"] += 1
    assert compared > 0 or not doc.roads
    return compared
