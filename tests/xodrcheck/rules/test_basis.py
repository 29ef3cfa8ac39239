"""Every finding states its basis: the Annex F UID it enforces, else the basis its rule declares.

The registry test reads the rules' source: a rule that can give a finding without a UID (it declares none, a
``finding`` call passes ``NO_UID`` or a value that is not a UID constant, or it runs on files older than its UIDs)
declares a basis; one whose every finding names a UID needs none.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
from pathlib import Path

import pytest

import xodrcheck
from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.check import check
from xodrcheck.findings import Basis, Category, Finding, Severity
from xodrcheck.rules import load_rules
from xodrcheck.rules.registry import NO_UID, Rule, declare, rule

RULES = load_rules()
PACKAGE = Path(xodrcheck.__file__).parent


def _value(node: ast.expr, scope: dict):
    """The value of a constant expression of a module (a name, an attribute, a subscript of them); ``...`` when it
    cannot be told without running the rule."""
    try:
        return eval(compile(ast.Expression(node), "<finding>", "eval"), dict(scope))  # the rules' own source
    except Exception:
        return ...


def _may_be_unnamed(uid: ast.expr | None, owner: Rule, scope: dict, around: str) -> bool:
    """Whether a ``finding(uid=...)`` call may give a finding without a UID. ``around`` is the source of the function
    making the call: a value computed there (a variable, a call) may be unnamed only where :data:`NO_UID` is used (in
    that function or the one it calls)."""
    if uid is None:
        return len(owner.uids) != 1
    if isinstance(uid, ast.IfExp):
        return any(_may_be_unnamed(branch, owner, scope, around) for branch in (uid.body, uid.orelse))
    value = _value(uid, scope)
    if value is None:
        return len(owner.uids) != 1
    if value is not ...:
        return not isinstance(value, str) or value == NO_UID
    called = _value(uid.func, scope) if isinstance(uid, ast.Call) else None
    source = inspect.getsource(called) if inspect.isfunction(called) else ""
    return "NO_UID" in around or "NO_UID" in source


def _unnamed_calls() -> tuple[dict[str, list[str]], list[str]]:
    """Rule code -> the ``finding`` calls (file:line) that may give a finding without a UID; and the calls of helpers
    that are handed their rule (``rule_.finding(...)``), which the test lists by name."""
    out: dict[str, list[str]] = {}
    handed: list[str] = []
    names = ["xodrcheck.check"] + [
        info.name
        for package in ("rules", "reader")
        for info in pkgutil.iter_modules([str(PACKAGE / package)], f"xodrcheck.{package}.")
    ]
    for name in names:
        module = importlib.import_module(name)
        path = Path(module.__file__ or "")
        if path.suffix != ".py" or ".finding(" not in (source := path.read_text(encoding="utf-8")):
            continue
        scope = vars(module)
        functions = [f for f in ast.walk(ast.parse(source)) if isinstance(f, ast.FunctionDef)]
        for function in functions:
            around = ast.get_source_segment(source, function) or ""
            for node in ast.walk(function):
                call = isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                if not (call and node.func.attr == "finding"):
                    continue
                owner = _value(node.func.value, scope)
                uid = next((k.value for k in node.keywords if k.arg == "uid"), None)
                if not isinstance(owner, Rule):
                    handed.append(f"{path.stem}.{function.name}")
                elif _may_be_unnamed(uid, owner, scope, around):
                    out.setdefault(owner.code, []).append(f"{path.name}:{node.lineno}")
    return out, sorted(set(handed))


def _needs_basis(r: Rule, unnamed: dict[str, list[str]]) -> bool:
    """Reader rules report many kinds of defect and name a UID for only some. (A rule running on files older than its
    UIDs needs no declaration: such findings rest on ``plausibility`` unless it declares otherwise.)"""
    return r.check is None or not r.uids or r.code in unnamed


def test_every_rule_that_can_give_a_finding_without_a_uid_declares_its_basis():
    unnamed, handed = _unnamed_calls()
    assert {"J101", "K101", "K103", "J027", "R011"} <= set(unnamed)  # the scan sees calls without a UID
    assert "B016" in unnamed and "B020" not in unnamed  # NO_UID there; a loop over UID constants here
    missing = sorted(code for code, r in RULES.items() if _needs_basis(r, unnamed) and r.basis is None)
    assert missing == [], f"rules giving findings without a UID and no basis: {missing}"
    # helpers handed their rule: each is called with rules of one UID or with a UID (looked at by hand)
    assert handed == [
        "context.report",  # the reader's: reader rules all declare a basis
        "junction_usage._each",  # one finding per UID given
        "lane_layer_width._compare",  # G016: one UID
        "overlap._findings",  # O001-O005: one UID each, O004 declares plausibility
        "reference._duplicates",  # R001, R002, R004: one UID each
    ]


def test_declared_bases_are_known_values():
    assert {r.basis for r in RULES.values()} <= {None, *Basis.ALL}
    with pytest.raises(ValueError, match="basis"):
        Rule("Z999", "z", Category.XML, Severity.ERROR, "", basis="opinion")


def test_the_project_s_own_checks_are_plausibility():
    for code in ("C001", "C002", "C003", "J101", "J102", "J005", "J006", "L010", "O004", "V001"):
        assert RULES[code].basis == Basis.PLAUSIBILITY, code
        assert not RULES[code].uids, code
    assert RULES["S001"].basis == Basis.SCHEMA and RULES["X101"].basis == Basis.READING
    assert RULES["X900"].basis == RULES["X901"].basis == Basis.INCOMPLETE


def test_a_finding_with_a_uid_rests_on_it_and_one_without_on_its_rule_s_basis():
    uid = "asam.net:xodr:1.4.0:road.geometry.refline_no_gaps"
    assert Finding("G001", "g", Category.GEOMETRY, Severity.ERROR, "m", rule_uid=uid).basis == uid
    assert Finding("G001", "g", Category.GEOMETRY, Severity.ERROR, "m").basis == Basis.PLAUSIBILITY
    with pytest.raises(ValueError, match="rests on"):
        Finding("G001", "g", Category.GEOMETRY, Severity.ERROR, "m", basis="a hunch")
    assert RULES["G001"].finding("m").basis == uid
    assert RULES["G001"].finding("m", uid=NO_UID).basis == Basis.PLAUSIBILITY


def test_a_rule_without_a_basis_cannot_give_a_finding_without_a_uid():
    orphan = Rule("Z998", "orphan", Category.XML, Severity.ERROR, "")
    with pytest.raises(ValueError, match="declares no basis"):
        orphan.finding("m")


def test_declare_and_rule_take_a_basis():
    from xodrcheck.rules import registry

    try:
        reader = declare("Z901", "basis-reader-probe", Category.XML, Severity.ERROR, "Probe.", basis=Basis.READING)

        @rule("Z902", "basis-check-probe", Category.GEOMETRY, Severity.ERROR, basis=Basis.PLAUSIBILITY)
        def probe(ctx):
            """Probe."""
            return ()

        assert (reader.basis, probe.basis) == (Basis.READING, Basis.PLAUSIBILITY)
    finally:
        for code, name in (("Z901", "basis-reader-probe"), ("Z902", "basis-check-probe")):
            registry.RULES.pop(code, None)
            registry.NAMES.pop(name, None)


# ------------------------------------------------------------------------------------------- each basis, by fixture
def test_uid_basis_from_a_fixture():
    (f,) = findings(fixture("road-link-target-missing", "fail.xodr"), "road-link-target-missing")
    assert f.rule_uid == f.basis == "asam.net:xodr:1.4.0:ids.only_ref_defined_ids"


def test_plausibility_basis_from_a_fixture():
    found = findings(fixture("connection-lanes-cross", "fail.xodr"), "connection-lanes-cross")
    assert found and {(f.rule_uid, f.basis) for f in found} == {(None, Basis.PLAUSIBILITY)}


def test_schema_basis_from_a_fixture():
    found = findings(fixture("border-corner-references", "fail.xodr"), "schema-invalid")
    assert found and {(f.rule_uid, f.basis) for f in found} == {(None, Basis.SCHEMA)}


def test_reading_basis_from_broken_bytes():
    report = check(b"<OpenDRIVE><header revMajor='1' revMinor='7'/><road id='1'")
    assert [(f.code, f.basis) for f in report.findings if f.code == "X101"] == [("X101", Basis.READING)]


def test_a_uid_the_file_predates_leaves_the_rule_s_basis():
    """K001 enforces a 1.9 rule; on a 1.7 file it keeps checking without claiming the UID: plausibility."""
    (f,) = [f for f in check(fixture("road-link-target-missing", "fail.xodr")).findings if f.code == "K001"]
    assert f.rule_uid is None and f.basis == Basis.PLAUSIBILITY


def test_incomplete_basis_from_a_fixture():
    """A check the budget made coarser says so; it is no judgement of the map, and no profile lowers it."""
    (f,) = findings(fixture("sampling-capped", "fail.xodr"), "sampling-capped")
    assert (f.rule_uid, f.basis, f.severity) == (None, Basis.INCOMPLETE, Severity.WARNING)
