"""Properties of xodrcheck on documents built independently of the generator, valid and damaged (runs of
:mod:`fuzz.campaign` under the ``ci`` profile)."""

from __future__ import annotations

import pytest

from fuzz import campaign
from fuzz import properties as P
from fuzz.documents import opendrive_documents
from fuzz.mutations import DEFECTS
from fuzz.profiles import budget, regressions
from fuzz.transform import move_and_rotate, renumber_roads, road_ids
from xodrcheck.rules import load_rules


def _run(name: str) -> int:
    """Run one campaign run with its ``ci`` budget; the number of examples it checked."""
    before = campaign.TRIED[name]
    campaign.hypothesis_test(name, budget(campaign.RUNS[name].budget))()
    return campaign.TRIED[name] - before


def test_valid_documents_have_no_error():
    assert _run("documents") >= budget("documents").max_examples


def test_damaged_documents_never_crash_the_checker():
    tried = _run("damaged")
    assert tried >= min(2000, budget("damaged").max_examples)


@pytest.mark.parametrize("entry", [e for e in regressions() if e["property"] == "damaged"], ids=lambda e: e["note"])
def test_damaged_regressions(entry):
    report = P.checker_survives(entry["document"].encode())
    assert report is None or report.findings


def test_every_defect_kind_has_its_rule():
    rules = set(load_rules())
    assert {kind for kind, codes in DEFECTS.items() if not codes <= rules} == set()


def test_defects_are_found():
    before = dict(campaign.DEFECT_KINDS)
    assert _run("defects") >= budget("defects").max_examples
    drawn = {kind for kind, n in campaign.DEFECT_KINDS.items() if n > before.get(kind, 0)}
    assert drawn == set(DEFECTS)


def test_moving_and_rotating_changes_no_finding():
    assert _run("move-rotate") >= budget("metamorphic").max_examples


def test_renumbering_roads_changes_no_finding_but_ids():
    assert _run("renumber") >= budget("metamorphic").max_examples


def test_metamorphic_transforms_are_not_identities():
    from hypothesis import given, settings

    @settings(max_examples=5, database=None)
    @given(opendrive_documents(max_roads_per_chain=1))
    def prop(doc):
        moved = move_and_rotate(doc, 10.0, -5.0, 0.5)
        assert moved != doc
        ids = road_ids(doc)
        renamed = renumber_roads(doc, {i: f"r{i}" for i in ids})
        assert road_ids(renamed) == [f"r{i}" for i in ids]

    prop()
