"""Interoperability acceptance of ``xodrcheck fix``: corpus maps fixed by the safe fixes load in CARLA, SUMO and ASAM's
checker with no more errors than the originals.

Eight corpus files that between them take every family of safe fix (empty and junction lane links, lane links at
unlinked ends, returned lane and road links, contact points, schema fixes and a raised header version, centre-lane
widths, sorted lane records, renamed ids). For each, original and fixed:

* CARLA's parser: loads the fixed map wherever it loaded the original, crashes on none it did not crash on (it
  segfaults on ika's ``junction_m2a`` either way), with as many waypoints and topology edges;
* SUMO ``netconvert``: exits 0 wherever it did, with no more error or warning lines;
* ASAM ``asam-qc-opendrive``: no checker that ran on the original finds more errors in the fixed map, and none ends
  in error there. ASAM runs its semantic checkers only on files valid against the schema, so a fixed file often gets
  checkers the original never did: their verdict is compared with that on the original with only its schema errors
  fixed (``--select S001``), which shows what the original's content gives them (a checker crashing on ika's maps
  once they validate is ASAM's, not the fix's).

A missing tool fails the test (never skips it).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from tests.interop.asam_harness import AsamRun
from tests.interop.tools import carla, run_netconvert, start_asam
from xodrcheck.fix.result import fix

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"

FILES = (
    "carla-towns/OpenDrive/Town03.xodr",
    "esmini/resources/xodr/multi_intersections.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/mixed_roads.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/straight_highway_500m.xodr",
    "ika-roadgeneration/test/gt/4a_fixed.xodr",
    "ika-roadgeneration/test/gt/junction_m2a.xodr",
    "scenariogeneration-examples/direct_junction_creator0.xodr",
    "scenariogeneration-examples/road_with_speed_signs0.xodr",
)


@pytest.fixture(scope="module")
def fixed_maps(corpus_dir, tmp_path_factory) -> list[tuple[Path, Path, Path]]:
    """(original, with only its schema errors fixed, fixed) for each of :data:`FILES`."""
    folder = tmp_path_factory.mktemp("fixed")
    out = []
    for name in FILES:
        original = corpus_dir / name
        result = fix(original)
        assert result.changed and result.applied, name
        fixed, valid = folder / name.replace("/", "__"), folder / ("schema-only__" + name.replace("/", "__"))
        fixed.write_bytes(result.data)
        valid.write_bytes(fix(original, select=["S001"]).data)
        out.append((original, valid, fixed))
    return out


@pytest.fixture(scope="module")
def pairs(fixed_maps) -> list[tuple[Path, Path]]:
    return [(original, fixed) for original, _, fixed in fixed_maps]


@pytest.fixture(scope="module")
def asam_run(fixed_maps, tmp_path_factory) -> AsamRun:
    """ASAM started in the background on every map (the slowest tool: the others run meanwhile)."""
    return start_asam([p for maps in fixed_maps for p in maps], tmp_path_factory.mktemp("asam"))


def test_the_fixes_cover_every_safe_family(pairs, asam_run):
    """(Requests ``asam_run`` so that ASAM starts before the other tools' tests run.)"""
    names = {a.fixer.name for original, _ in pairs for a in fix(original).applied}
    assert names >= {
        "remove-empty-lane-link",
        "remove-lane-link-into-junction",
        "remove-lane-link-to-nothing",
        "return-lane-link",
        "return-road-link",
        "set-connection-contact-point",
        "remove-empty-element",
        "move-georeference-into-header",
        "raise-header-version",
        "remove-centre-lane-width",
        "sort-lane-records",
        "rename-duplicate-id",
    }


def test_carla_reads_the_fixed_maps_as_well(pairs):
    worse = []
    for original, fixed in pairs:
        before, after = carla(original), carla(fixed)
        if (before.loaded and not after.loaded) or (after.crashed and not before.crashed):
            worse.append(f"{original.name}: {after.error}")
        elif len(after.waypoints) < len(before.waypoints) or len(after.topology) < len(before.topology):
            worse.append(f"{original.name}: {len(before.waypoints)} -> {len(after.waypoints)} waypoints")
    assert worse == []


def _lines(proc, word: str) -> int:
    return sum(1 for line in (proc.stdout + proc.stderr).splitlines() if line.startswith(word))


def test_sumo_converts_the_fixed_maps_as_well(pairs, tmp_path):
    worse = []
    for original, fixed in pairs:
        (before, _), (after, _) = run_netconvert(original, tmp_path), run_netconvert(fixed, tmp_path)
        if before.returncode == 0 and after.returncode != 0:
            worse.append(f"{original.name}: exit {after.returncode}")
        for word in ("Error", "Warning"):
            if _lines(after, word) > _lines(before, word):
                worse.append(f"{original.name}: {_lines(before, word)} -> {_lines(after, word)} {word} lines")
    assert worse == []


def _checkers(result: Path) -> dict[str, tuple[str, int]]:
    """Each ASAM checker's status and number of error-level issues in a result file."""
    tree = etree.parse(str(result), etree.XMLParser(resolve_entities=False, no_network=True))
    return {
        c.get("checkerId", ""): (c.get("status", ""), sum(1 for i in c.iter("Issue") if i.get("level") == "1"))
        for c in tree.iter("Checker")
    }


def test_asam_finds_no_more_errors_in_the_fixed_maps(fixed_maps, asam_run):
    asam_run.reports()  # waits for the workers
    result = dict(zip(asam_run.paths, asam_run.results))
    worse, errors = [], [0, 0]
    for original, valid, fixed in fixed_maps:
        before, content, after = (_checkers(result[p]) for p in (original, valid, fixed))
        errors[0] += sum(n for _, n in before.values())
        errors[1] += sum(n for _, n in after.values())
        for checker, (status, n) in after.items():
            was = before.get(checker, ("skipped", 0))
            if was[0] == "skipped":  # run on the fixed map only: judged against the original's content
                was = content.get(checker, ("skipped", 0))
            if was[0] == "skipped":
                continue
            if n > was[1] or (status == "error" and was[0] != "error"):
                worse.append(f"{original.name}: {checker} {was} -> {(status, n)}")
    assert worse == []
    assert errors[1] < errors[0]
