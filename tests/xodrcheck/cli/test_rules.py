"""``xodrcheck rules``: the list of rules and one rule's documentation."""

from __future__ import annotations

import json

import pytest

from xodrcheck.cli import main
from xodrcheck.cli.rules import default_severity
from xodrcheck.rules import load_rules
from xodrcheck.standard import annex_rules


def test_lists_every_rule_with_code_name_category_severity_basis_summary(capsys):
    assert main(["rules"]) == 0
    lines = capsys.readouterr().out.splitlines()
    rules = load_rules()
    assert len(lines) == len(rules)
    for line in lines:
        code, name, category, severity, basis, *summary = line.split()
        rule = rules[code]
        assert (name, category, severity) == (rule.name, rule.category.value, str(default_severity(rule))) and summary
        assert basis.rstrip(",") == ("annex-f" if rule.uids else rule.basis)
    by_code = {line.split()[0]: line for line in lines}
    assert "  plausibility  " in by_code["C001"] and "  annex-f  " in by_code["R010"]
    assert "  annex-f, plausibility  " in by_code["K101"] and "  schema  " in by_code["S001"]


def test_json_list(capsys):
    assert main(["rules", "--format", "json"]) == 0
    items = json.loads(capsys.readouterr().out)
    assert {i["code"] for i in items} == set(load_rules())
    keys = {"code", "name", "category", "severity", "default_severity", "basis", "summary", "uids", "fix"}
    assert all(set(i) == keys for i in items)
    by_code = {i["code"]: i for i in items}
    assert (by_code["C001"]["severity"], by_code["C001"]["default_severity"]) == ("error", "warning")
    assert (by_code["G002"]["default_severity"], by_code["R010"]["default_severity"]) == ("warning", "error")


@pytest.mark.parametrize("which", ["R010", "r010", "road-link-target-missing"])
def test_one_rule_prints_its_full_doc_with_examples(capsys, which):
    assert main(["rules", which]) == 0
    out = capsys.readouterr().out
    assert out.startswith("R010 road-link-target-missing (reference, error)")
    assert "Passes" in out and "Fails" in out and "<successor" in out
    assert "::" not in out and "``" not in out  # plain text, not reStructuredText


def test_list_is_plain_text_with_whole_sentences(capsys):
    """Summaries were the docstring's first line: markup (``min_radius``) and sentences cut at the line end (X203
    ended in "a ``<laneSection>``")."""
    assert main(["rules"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines and not any("``" in line or ":class:" in line for line in lines)
    assert all(line.rstrip().endswith((".", "!", "?", ")")) for line in lines), [
        line for line in lines if not line.rstrip().endswith((".", "!", "?", ")"))
    ]
    (x203,) = [line for line in lines if line.startswith("X203")]
    assert x203.endswith("An element the model needs is missing.")


def test_plain_text_conversion():
    from xodrcheck.rules.shared.plaintext import plain, summary

    assert plain("a ``min_radius`` and :class:`~xodrcheck.config.Tolerances` and `x`") == (
        "a min_radius and Tolerances and x"
    )
    assert plain("Passes (an arc)::\n\n    <arc/>") == "Passes (an arc):\n\n    <arc/>"
    assert summary("One sentence that goes on\n   over two lines, e.g. this. Another.") == (
        "One sentence that goes on over two lines, e.g. this."
    )


def test_one_rule_as_json(capsys):
    assert main(["rules", "J006", "--format", "json"]) == 0
    item = json.loads(capsys.readouterr().out)
    assert item["name"] == "junction-merge" and "Fails" in item["doc"]
    assert (item["basis"], item["standard"]) == ("plausibility", [])
    assert main(["rules", "G001", "--format", "json"]) == 0
    (row,) = json.loads(capsys.readouterr().out)["standard"]
    assert row == {
        "uid": "asam.net:xodr:1.4.0:road.geometry.refline_no_gaps",
        "section": annex_rules()[row["uid"]].section,
        "level": "shall",
        "description": "A road reference line shall have no gaps.",
    }


def test_one_rule_quotes_the_standard_for_each_uid(capsys):
    assert main(["rules", "K001"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("K001 link-not-reciprocal (link, error)\n")
    assert "enforces asam.net:xodr:1.9.0:road.linkage.both_sides_consistency (F.6.15.1, shall)" in out
    assert (
        "\n  <predecessor> and/or <successor> shall be defined at both sides of the road linkage and shall be " in out
    )
    assert main(["rules", "G002"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("G002 plan-view-kink (geometry, error; default profile: warning)")
    assert "(F.6.11.7, should)\n  A road reference line should have no kinks.\n" in out
    assert "findings naming no UID rest on plausibility" in out


def test_one_plausibility_rule_says_so_and_which_profile_makes_it_an_error(capsys):
    assert main(["rules", "J101"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(
        "J101 connection-lanes-cross (junction, error; default profile: warning)\n\nbasis: plausibility"
    )
    assert "enforces" not in out and "--profile generator" in out and "JunctionArt paper" in out


@pytest.mark.parametrize("rule", [r for r in load_rules().values() if r.basis == "plausibility" and not r.uids])
def test_every_plausibility_rule_says_why_in_its_doc(rule):
    assert "Plausibility:" in rule.doc or "plausibility" in rule.doc, rule.code


def test_unknown_rule_exits_2(capsys):
    assert main(["rules", "Q999"]) == 2
    assert "no rule 'Q999'" in capsys.readouterr().err


@pytest.mark.parametrize("rule", sorted(load_rules().values(), key=lambda r: r.code), ids=lambda r: r.code)
def test_every_rule_documents_a_passing_and_a_failing_example(rule):
    doc = rule.doc
    assert rule.summary and len(rule.summary) <= 140 and rule.summary.endswith((".", "!", "?", ")")), rule.summary
    assert "Pass" in doc and "Fail" in doc, rule.code


def test_tolerances_lists_every_tolerance_with_default_unit_rules_and_meaning(capsys):
    import dataclasses

    from xodrcheck.config import Tolerances

    assert main(["rules", "--tolerances"]) == 0
    lines = capsys.readouterr().out.splitlines()
    names = [f.name for f in dataclasses.fields(Tolerances)]
    assert [line.split()[0] for line in lines[1 : len(names) + 1]] == names
    gap = next(line for line in lines if line.startswith("gap "))
    assert gap.split()[1:4] == ["0.01", "0.001", "m"] and "K103" in gap and "1 cm" in gap
    assert main(["rules", "--tolerances", "--format", "json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert {r["name"]: r["default"] for r in rows} == {n: getattr(Tolerances, n) for n in names}


@pytest.mark.parametrize("field", __import__("dataclasses").fields(__import__("xodrcheck.config").config.Tolerances))
def test_every_tolerance_is_documented_with_a_unit_and_known_rules(field):
    assert field.metadata["doc"] and field.metadata["unit"]
    assert set(field.metadata["rules"]) <= set(load_rules())


def test_a_rule_names_its_tolerances(capsys):
    assert main(["rules", "K103"]) == 0
    assert "tolerances (xodrcheck rules --tolerances): position = 0.001 m; gap = 0.01 m" in capsys.readouterr().out
    assert main(["rules", "K103", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["tolerances"] == ["position = 0.001 m", "gap = 0.01 m"]
