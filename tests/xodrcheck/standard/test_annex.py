"""The standard's rulebook (Annex F): the packaged list is the annex's, and the status table is computed from it."""

from __future__ import annotations

import dataclasses
import json
import re

import pytest

from tests.xodrcheck.standard.uidfixtures import FIXTURES
from xodrcheck.check import check
from xodrcheck.cli import main
from xodrcheck.findings import Severity
from xodrcheck.rules import load_rules
from xodrcheck.standard import annex_rules, applies, uid_matches, uid_version
from xodrcheck.standard.status import ENFORCED, MISSING, NOT_ENFORCED, PARTIAL, statuses


@pytest.fixture(scope="module")
def annex_uids(corpus_dir) -> set[str]:
    """The UIDs as the standard's Markdown lists them (``UID`` then ``: asam.net:...``)."""
    text = (corpus_dir.parent / "reference" / "opendrive-1.9" / "map-rules.md").read_text(encoding="utf-8")
    return set(re.findall(r"^UID\n:\s+(\S+)$", text.replace("\\_", "_"), re.M))


def test_packaged_list_is_the_annex(annex_uids):
    assert len(annex_uids) == 275
    assert set(annex_rules()) == annex_uids


def test_rules_standard_json_lists_exactly_the_annex(capsys, annex_uids):
    assert main(["rules", "--standard", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert {row["uid"] for row in doc["rules"]} == annex_uids
    assert len(doc["rules"]) == 275
    assert doc["summary"].startswith("275 checker rules")
    for row in doc["rules"]:
        assert row["status"] in (ENFORCED, PARTIAL, MISSING)
        assert bool(row["codes"]) == (row["status"] != MISSING)
        assert row["note"] or row["status"] == ENFORCED


def test_markdown_table_has_a_row_per_rule(capsys):
    assert main(["rules", "--standard", "--format", "md"]) == 0
    rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("| `asam.net")]
    assert len(rows) == 275


def test_every_declared_uid_is_in_the_annex():
    known = annex_rules()
    for rule in load_rules().values():
        unknown = [uid for uid in rule.uids if uid not in known]
        assert not unknown, f"{rule.code} declares UIDs the annex does not have: {unknown}"
        assert set(rule.partial) <= set(rule.uids)


def test_reasons_are_given_only_for_rules_not_enforced():
    enforced = {row.uid for row in statuses(load_rules()) if row.status != MISSING}
    assert not enforced & set(NOT_ENFORCED), "a UID with a reason for not being enforced is enforced"
    assert set(NOT_ENFORCED) <= set(annex_rules())


def test_levels_give_severities():
    rules = annex_rules()
    assert rules["asam.net:xodr:1.4.0:road.geometry.refline_no_gaps"].severity is Severity.ERROR
    assert rules["asam.net:xodr:1.4.0:road.geometry.refline_no_kinks"].severity is Severity.WARNING
    assert rules["asam.net:xodr:1.7.0:road.object.material.materials_may_differ"].severity is Severity.INFO


@pytest.mark.parametrize(
    ("uid", "version", "expected"),
    [
        ("asam.net:xodr:1.8.0:junctions.crossing.only_one_high_prio", (1, 7), False),
        ("asam.net:xodr:1.8.0:junctions.crossing.only_one_high_prio", (1, 8), True),
        ("asam.net:xodr:1.8.2:road.object.object_marking.colour", (1, 8), True),
        ("asam.net:xodr:1.4.0:road.geometry.refline_no_gaps", (1, 1), True),
        ("asam.net:xodr:1.9.0:header.proj.max_one_proj", (1, 8), False),
        ("asam.net:xodr:1.9.0:header.proj.max_one_proj", None, True),
        ("asam.net:xodr:1.x.0:road.corner_local.no_mixing_road_local", (1, 8), False),
        ("asam.net:xodr:1.x.0:road.corner_local.no_mixing_road_local", (1, 9), True),
    ],
)
def test_a_uid_applies_from_its_version_on(uid, version, expected):
    assert applies(uid, version) is expected


def test_uid_versions_and_patterns():
    assert uid_version("asam.net:xodr:1.7.0:road.lane.link.zero_width_at_start") == (1, 7)
    assert uid_matches("asam.net:xodr:*:road.lane.*", "asam.net:xodr:1.7.0:road.lane.link.zero_width_at_start")
    assert not uid_matches("asam.net:xodr:*:road.lane.*", "asam.net:xodr:1.4.0:road.lanes.lane_offset.elem_asc_order")


def test_unknown_uid_pattern_is_a_usage_error(capsys, tmp_path):
    path = tmp_path / "x.xodr"
    path.write_text('<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="7"/></OpenDRIVE>')
    assert main(["check", str(path), "--select", "asam.net:xodr:*:no.such.rule"]) == 2
    assert "no rule of the standard matches" in capsys.readouterr().err
    assert check(path).path == str(path)


def _rule(every_version: bool):
    from xodrcheck.findings import Category
    from xodrcheck.rules.registry import Rule

    uid = "asam.net:xodr:1.8.0:junctions.crossing.only_one_high_prio"
    return Rule(
        "T999", "test-rule", Category.JUNCTION, Severity.ERROR, "doc", None, (uid,), every_version=every_version
    )


@pytest.mark.parametrize("every_version", [False, True])
def test_findings_of_a_newer_rule_are_dropped_or_lose_their_uid(every_version):
    from xodrcheck.config import PROFILES
    from xodrcheck.verdict import judged

    rule = _rule(every_version)
    finding = rule.finding("two high-priority roads")
    assert finding.rule_uid == rule.uids[0]
    generator, default = PROFILES["generator"], PROFILES["default"]
    assert list(judged([finding], (1, 8), {"T999": rule}, generator)) == [finding]
    assert list(judged([finding], (1, 8), {"T999": rule}, default)) == [finding]  # a "shall" rule: still an error
    kept = list(judged([finding], (1, 7), {"T999": rule}, generator))
    assert kept == ([] if not every_version else [dataclasses.replace(finding, rule_uid=None, basis="plausibility")])
    bounded = list(judged([finding], (1, 7), {"T999": rule}, default))  # plausibility: at most a warning
    assert [(f.severity, f.basis) for f in bounded] == (
        [] if not every_version else [(Severity.WARNING, "plausibility")]
    )
    assert rule.runs_on((1, 7)) is every_version and rule.runs_on((1, 8)) and rule.runs_on(None)


def test_a_finding_cannot_claim_a_uid_its_rule_does_not_declare():
    with pytest.raises(ValueError, match="does not declare"):
        _rule(False).finding("x", uid="asam.net:xodr:1.4.0:road.geometry.refline_no_gaps")


def test_uid_selectors_pick_findings_by_uid(tmp_path):
    path = tmp_path / "centre.xodr"
    source = FIXTURES / "centre-lane-invalid" / "fail_lane_zero_on_a_side.xodr"
    path.write_bytes(source.read_bytes())
    by_pattern = check(path, select=("asam.net:xodr:*:road.lane.lanes_*",))
    assert {f.code for f in by_pattern.findings} == {"L001"}
    assert {f.rule_uid for f in by_pattern.findings} == {"asam.net:xodr:1.4.0:road.lane.lanes_numbered_correctly"}
    ignored = check(path, ignore=("asam.net:xodr:*:road.lane.lanes_numbered_correctly",))
    assert not [f for f in ignored.findings if f.rule_uid and f.rule_uid.endswith("lanes_numbered_correctly")]
    assert "L001" in ignored.rules_run  # the rule still runs for its other UIDs


def test_packaged_table_is_what_the_script_makes_of_the_annex(corpus_dir):
    """``annex_f.tsv`` is ``scripts/annex_uids.py``'s output (levels, the standard's words): regenerated, not edited."""
    import importlib.util
    from pathlib import Path

    script = Path(__file__).resolve().parents[3] / "scripts" / "annex_uids.py"
    spec = importlib.util.spec_from_file_location("annex_uids", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    markdown = (corpus_dir.parent / "reference" / "opendrive-1.9" / "map-rules.md").read_text(encoding="utf-8")
    rows = module.parse(markdown)
    assert [(r.uid, r.section, r.level, r.description) for r in annex_rules().values()] == rows
    by_uid = {r[0]: r[3] for r in rows}
    assert by_uid["asam.net:xodr:1.4.0:road.lane.link.no_link"] == (
        "The <link> element shall be omitted if the lane starts or ends in a junction or has no link."
    )
    assert all(description and "`" not in description and "](" not in description for description in by_uid.values())
