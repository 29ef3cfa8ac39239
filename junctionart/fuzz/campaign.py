"""The fuzzing campaign: every property paired with the strategy that feeds it, as named runs.

The test suite (``tests/fuzz``) and ``python -m junctionart.fuzz`` run the same :data:`RUNS`, so a failing example one
of them stores in the example database (:data:`fuzz.profiles.DATABASE_DIR`) is replayed first by the other.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from junctionart.fuzz import properties as P
from junctionart.fuzz.mutations import DEFECTS, damaged_documents, defective_documents
from junctionart.fuzz.profiles import tolerated
from junctionart.fuzz.transform import move_and_rotate, renumber_roads, road_ids

#: Examples each run has checked in this process.
TRIED: Counter = Counter()
#: Defect kinds the ``defects`` run has checked in this process.
DEFECT_KINDS: Counter = Counter()
SEEDS = st.integers(0, 2**32 - 1)
_NAMES = st.from_regex(r"[a-z][a-z0-9_]{0,6}", fullmatch=True)


@dataclass(frozen=True)
class Run:
    """One property and its inputs: ``strategy()`` builds the strategy (lazily: the generator's strategies import
    junctionart), ``check(example)`` asserts the property; ``budget`` names its example budget
    (:data:`fuzz.profiles.BUDGETS`)."""

    name: str
    budget: str
    strategy: Callable[[], st.SearchStrategy]
    check: Callable[[Any], object]  # asserts; what it returns is not used
    doc: str
    #: The check hands Hypothesis targets to climb (``hypothesis.target``): the run adds the target phase and
    #: neither stores examples (the committed database keeps open failures only) nor shrinks (each step re-checks a
    #: slow document).
    climbs: bool = False


# ------------------------------------------------------------------------------------------------ checker runs
def _documents() -> st.SearchStrategy:
    from junctionart.fuzz.documents import opendrive_documents

    return opendrive_documents()


def _metamorphic_inputs() -> st.SearchStrategy[bytes]:
    return st.one_of(_documents(), defective_documents().map(lambda case: case[0]))


def _check_defect(case) -> None:
    data, kind = case
    DEFECT_KINDS[kind] += 1
    P.defect_is_found(data, DEFECTS[kind])


def _moves() -> st.SearchStrategy:
    return st.tuples(
        _metamorphic_inputs(),
        st.floats(-5e4, 5e4, allow_nan=False, allow_infinity=False),
        st.floats(-5e4, 5e4, allow_nan=False, allow_infinity=False),
        st.floats(-math.pi, math.pi, allow_nan=False, allow_infinity=False),
    )


#: Rules about where a map lies in its frame, which moving it changes by definition: H001 (coordinates off (0, 0)).
_ABOUT_POSITION = frozenset({"H001"})


def _check_move(case) -> None:
    data, dx, dy, angle = case
    before = P.checked(data)
    after = P.checked(move_and_rotate(data, dx, dy, angle))
    keys = [
        Counter({k: n for k, n in P.finding_keys(r).items() if k[0] not in _ABOUT_POSITION}) for r in (before, after)
    ]
    assert keys[1] == keys[0], "moving and rotating the map changed its findings"


@st.composite
def _renumberings(draw) -> tuple[bytes, dict[str, str]]:
    data = draw(_metamorphic_inputs())
    ids = sorted(set(road_ids(data)))
    new = draw(st.lists(_NAMES.filter(lambda v: v not in ids), min_size=len(ids), max_size=len(ids), unique=True))
    return data, dict(zip(ids, new))


def _check_renumbering(case) -> None:
    data, mapping = case
    before = P.checked(data)
    after = P.checked(renumber_roads(data, mapping))
    assert P.finding_keys(after) == P.finding_keys(before, mapping), "renumbering roads changed more than ids"


def _hostile() -> st.SearchStrategy:
    from junctionart.fuzz.hostile import hostile_documents

    return hostile_documents()


def _check_hostile(data: bytes) -> None:
    from junctionart.fuzz.hunt import check_is_bounded

    check_is_bounded(data)


# ------------------------------------------------------------------------------------------------ generator runs
def _maps() -> st.SearchStrategy:
    from junctionart.fuzz.generator import control_line_groups, generator_params

    return st.tuples(generator_params(max_size=450), st.one_of(st.none(), control_line_groups(extent=300.0)), SEEDS)


def _check_map(case) -> None:
    params, lines, seed = case
    P.generated_map_is_valid(params, seed, lines, tolerated("generated-map"))


def _invalid_lines() -> st.SearchStrategy:
    from junctionart.fuzz.generator import invalid_control_line_files

    return st.tuples(invalid_control_line_files(), SEEDS)


def _check_invalid_lines(case) -> None:
    import junctionart as ja
    from junctionart.controllines import parse

    (data, _what), seed = case
    P.invalid_input_refused(lambda: ja.generate(ja.Params(), seed % 1000, parse(data)))


def _invalid_params() -> st.SearchStrategy:
    from junctionart.fuzz.generator import invalid_generator_params

    return invalid_generator_params()


def _check_invalid_params(case) -> None:
    import junctionart as ja

    values, name = case
    message = P.invalid_input_refused(lambda: ja.Params.create(**values))
    assert name in message, f"the error does not name {name!r}: {message}"


def _round_trips() -> st.SearchStrategy:
    from junctionart.fuzz.generator import generator_params

    return st.tuples(generator_params(max_size=400), SEEDS)


def _check_round_trip(case) -> None:
    import junctionart as ja

    params, seed = case
    P.round_trip_exact(ja.generate(params, seed))


RUNS: dict[str, Run] = {
    run.name: run
    for run in (
        Run(
            "documents",
            "documents",
            _documents,
            P.document_is_valid,
            "valid documents built without the generator: no error",
        ),
        Run(
            "damaged",
            "damaged",
            damaged_documents,
            lambda data: P.checker_survives(data, tolerated("damaged")),
            "damaged documents: findings or a clear error, never a crash, in bounded time",
        ),
        Run(
            "defects",
            "defects",
            defective_documents,
            _check_defect,
            "documents with one known defect: the defect is reported",
        ),
        Run(
            "slow",
            "slow",
            _hostile,
            _check_hostile,
            "hostile documents (huge lengths, tiny radii, thousands of records): bounded cost, the slowest kept",
            climbs=True,
        ),
        Run("move-rotate", "metamorphic", _moves, _check_move, "moving and rotating a map changes no finding"),
        Run(
            "renumber",
            "metamorphic",
            _renumberings,
            _check_renumbering,
            "renumbering roads changes no finding except ids",
        ),
        Run("maps", "maps", _maps, _check_map, "valid generator input: a map without error"),
        Run("invalid-lines", "invalid", _invalid_lines, _check_invalid_lines, "invalid control lines: one clear error"),
        Run(
            "invalid-params",
            "invalid",
            _invalid_params,
            _check_invalid_params,
            "invalid parameters: one clear error naming the parameter",
        ),
        Run(
            "round-trip",
            "round-trip",
            _round_trips,
            _check_round_trip,
            "generator model -> .xodr -> reader: the same geometry within 1e-9 m",
        ),
    )
}


def hypothesis_test(
    name: str, config: settings, strategy: st.SearchStrategy | None = None, key: str | None = None
) -> Callable[[], None]:
    """The Hypothesis test of run ``name`` under ``config`` (``strategy``: a narrower strategy than the run's own,
    e.g. one defect kind, stored under ``key``). Its database key is the run's own (the same for the test suite and
    ``python -m junctionart.fuzz``), so stored failures are replayed wherever the run goes next."""
    run = RUNS[name]

    def example(case) -> None:
        TRIED[name] += 1
        run.check(case)

    example.__name__ = example.__qualname__ = f"fuzz_{name.replace('-', '_')}"
    # Every run shares this function's source, which Hypothesis hashes into the database key; the run's name keeps
    # the keys apart (the attribute Hypothesis itself uses to separate parametrized tests).
    example.__dict__["_hypothesis_internal_add_digest"] = (key or name).encode()
    if run.climbs:
        config = settings(config, database=None, phases=(Phase.explicit, Phase.generate, Phase.target))
    return config(given(strategy if strategy is not None else run.strategy())(example))
