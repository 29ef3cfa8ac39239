"""Properties of xodrcheck on documents built independently of the generator, valid and damaged (runs of
:mod:`junctionart.fuzz.campaign` under the ``ci`` profile)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings

from junctionart.fuzz import campaign
from junctionart.fuzz import properties as P
from junctionart.fuzz.documents import opendrive_documents
from junctionart.fuzz.mutations import DEFECTS, defective_documents
from junctionart.fuzz.profiles import budget, regressions
from junctionart.fuzz.transform import move_and_rotate, renumber_roads, road_ids
from xodrcheck.rules import load_rules

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"


def _run(name: str) -> int:
    """Run one campaign run with its ``ci`` budget; the number of examples it checked."""
    before = campaign.TRIED[name]
    campaign.hypothesis_test(name, budget(campaign.RUNS[name].budget))()
    return campaign.TRIED[name] - before


def test_valid_documents_have_no_error():
    assert _run("documents") >= budget("documents").max_examples


# Numbers like 1e308 and NaN in damaged files overflow inside numpy (RuntimeWarning); the checker turns them into
# findings, which is what is asserted here, so the warnings are noise for this property.
@pytest.mark.filterwarnings("ignore::RuntimeWarning")
def test_damaged_documents_never_crash_the_checker():
    tried = _run("damaged")
    assert tried >= min(2000, budget("damaged").max_examples)


@pytest.mark.parametrize("entry", [e for e in regressions() if e["property"] == "damaged"], ids=lambda e: e["note"])
def test_damaged_regressions(entry):
    if entry.get("known_fault"):
        with pytest.raises(AssertionError) as crash:
            P.checker_survives(entry["document"].encode())
        if any(t in str(crash.value) for t in entry["tolerate"]):
            pytest.xfail(entry["note"])  # strict: fails below once the crash is gone
        pytest.fail(f"known fault fixed or changed ({crash.value}): set known_fault to false in fuzz/regressions.json")
    report = P.checker_survives(entry["document"].encode())
    assert report is None or report.findings


def test_every_defect_kind_has_its_rule():
    rules = set(load_rules())
    assert {kind for kind, codes in DEFECTS.items() if not codes <= rules} == set()


@pytest.mark.parametrize("kind", sorted(DEFECTS))
def test_defects_are_found(kind):
    """Each defect kind is reported on its share of the ``defects`` budget (one kind at a time, so every kind gets
    its share whatever order Hypothesis draws kinds in)."""
    share = -(-budget("defects").max_examples // len(DEFECTS))
    before = campaign.DEFECT_KINDS[kind]
    config = settings(budget("defects"), max_examples=share)
    campaign.hypothesis_test("defects", config, defective_documents(defects=(kind,)), key=f"defects:{kind}")()
    assert campaign.DEFECT_KINDS[kind] - before >= share


def test_moving_and_rotating_changes_no_finding():
    assert _run("move-rotate") >= budget("metamorphic").max_examples


def test_renumbering_roads_changes_no_finding_but_ids():
    assert _run("renumber") >= budget("metamorphic").max_examples


def test_metamorphic_transforms_are_not_identities():
    @settings(max_examples=5, database=None)
    @given(opendrive_documents(max_roads_per_chain=1))
    def prop(doc):
        moved = move_and_rotate(doc, 10.0, -5.0, 0.5)
        assert moved != doc
        ids = road_ids(doc)
        renamed = renumber_roads(doc, {i: f"r{i}" for i in ids})
        assert road_ids(renamed) == [f"r{i}" for i in ids]

    prop()
