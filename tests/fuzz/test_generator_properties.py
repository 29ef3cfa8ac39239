"""Properties of junctionart checked by xodrcheck (runs of :mod:`junctionart.fuzz.campaign` under the ``ci`` profile):
valid input -> a map without error; invalid input -> one clear error and no file; the written file reads back to the
same geometry; a broken generator is caught."""

from __future__ import annotations

import dataclasses
import json
import re

import pytest
from hypothesis import Phase, settings

from junctionart import cleanup, controllines
from junctionart.cli import main as junctionart_main
from junctionart.fuzz import campaign
from junctionart.fuzz.profiles import budget, regressions

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"


def _run(name: str, config: settings | None = None) -> int:
    before = campaign.TRIED[name]
    campaign.hypothesis_test(name, config or budget(campaign.RUNS[name].budget))()
    return campaign.TRIED[name] - before


def test_valid_input_gives_a_map_without_error():
    assert _run("maps") >= min(200, budget("maps").max_examples)


def test_invalid_control_lines_are_refused():
    assert _run("invalid-lines") >= budget("invalid").max_examples


def test_invalid_params_are_refused():
    assert _run("invalid-params") >= 1  # a small space: Hypothesis may exhaust it before the budget


def _known_fault(entry: dict, still_there: bool) -> None:
    """A strict expected failure: xfail while the known fault is there, fail once it is fixed (so that the entry, and
    the tolerance it grants the maps property, are updated)."""
    if still_there:
        pytest.xfail(entry["note"])
    pytest.fail(f"known fault {entry['what']!r} is fixed: set known_fault to false in fuzz/regressions.json")


@pytest.mark.parametrize(
    "entry", [e for e in regressions() if e["property"] == "invalid-input"], ids=lambda e: e["what"]
)
def test_invalid_input_regressions(entry, tmp_path, capsys):
    """On the command line: exit 2, one line on stderr, no file."""
    source = tmp_path / "lines.json"
    source.write_text(json.dumps(entry["control_lines"]))
    out = tmp_path / "map.xodr"
    code = junctionart_main(["generate", "--control-lines", str(source), "-o", str(out), "-q"])
    if entry.get("known_fault"):
        _known_fault(entry, still_there=code == 0)
    assert code == 2
    assert not out.exists()
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_round_trip_geometry_is_exact():
    assert _run("round-trip") >= budget("round-trip").max_examples


# ------------------------------------------------------------------------------------------------ fault injection
def _replace_road(doc, i, road):
    return dataclasses.replace(doc, roads=(*doc.roads[:i], road, *doc.roads[i + 1 :]))


def _drop_lane_link(doc):
    """Drop the first lane predecessor of a connecting road."""
    for i, road in enumerate(doc.roads):
        if road.junction == "-1":
            continue
        for k, sec in enumerate(road.sections):
            for side in ("left", "right"):
                lanes = getattr(sec, side)
                for j, lane in enumerate(lanes):
                    if lane.predecessor is not None:
                        lanes = (*lanes[:j], dataclasses.replace(lane, predecessor=None), *lanes[j + 1 :])
                        sec = dataclasses.replace(sec, **{side: lanes})
                        road = dataclasses.replace(road, sections=(*road.sections[:k], sec, *road.sections[k + 1 :]))
                        return _replace_road(doc, i, road)
    return doc


def _gap_at_junction(doc):
    """Move the first connecting road 0.3 m along x."""
    for i, road in enumerate(doc.roads):
        if road.junction != "-1":
            geometry = tuple(dataclasses.replace(g, x=g.x + 0.3) for g in road.geometry)
            return _replace_road(doc, i, dataclasses.replace(road, geometry=geometry))
    return doc


@pytest.mark.parametrize("breakage", [_drop_lane_link, _gap_at_junction], ids=["dropped-lane-link", "junction-gap"])
def test_fuzzing_catches_a_broken_generator(monkeypatch, breakage):
    """The ``maps`` run, with the generator patched to break its output, fails within the CI budget (without
    shrinking, and without touching the example database)."""
    real = cleanup.document
    broken: list[int] = []

    def document(*args, **kwargs):
        doc = real(*args, **kwargs)
        out = breakage(doc)
        broken.append(out is not doc)
        return out

    monkeypatch.setattr(cleanup, "document", document)
    config = settings(budget("faults"), database=None, phases=(Phase.generate,), print_blob=False)
    with pytest.raises(AssertionError, match="has errors"):
        _run("maps", config)
    assert broken[-1], "the run failed on a map the breakage left alone"


@pytest.mark.parametrize(
    "entry", [e for e in regressions() if e["property"] == "min-turn-radius"], ids=lambda e: e["what"]
)
def test_min_turn_radius_regressions(entry):
    """Params promise that no lane centre is written tighter than ``min_turn_radius``."""
    import junctionart as ja
    from xodrcheck.check import check
    from xodrcheck.config import Config, Tolerances

    params = ja.Params.create(**{k: tuple(v) if isinstance(v, list) else v for k, v in entry["params"].items()})
    data = ja.to_bytes(ja.generate(params, entry["seed"]), params.version)
    report = check(data, Config(tolerances=Tolerances(min_radius=params.min_turn_radius), profile="generator"))
    tight = [f.message for f in report.findings if f.code in ("C001", "C002")]
    if entry.get("known_fault"):
        _known_fault(entry, still_there=bool(tight))
    assert tight == []


@pytest.mark.parametrize(
    "entry", [e for e in regressions() if e["property"] == "generated-map"], ids=lambda e: e["what"]
)
def test_generated_map_regressions(entry):
    """Maps the fuzzer found errors in: no error any more (known faults: xfail while the error is there)."""
    import junctionart as ja
    from junctionart.fuzz import properties as P

    params = ja.Params.create(**{k: tuple(v) if isinstance(v, list) else v for k, v in entry["params"].items()})
    lines = controllines.parse(entry["control_lines"]) if "control_lines" in entry else None
    if entry.get("known_fault"):
        try:
            P.generated_map_is_valid(params, entry["seed"], lines)
        except AssertionError as exc:
            if any(re.search(rf"^\s*{code} ", str(exc), re.MULTILINE) for code in entry["tolerate"]):
                pytest.xfail(entry["note"])
            raise
        _known_fault(entry, still_there=False)
    P.generated_map_is_valid(params, entry["seed"], lines)
