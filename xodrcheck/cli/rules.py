"""``xodrcheck rules [CODE]``: list the rules, or print one rule's documentation with its examples.

``CODE`` may be a code (``R010``) or a name (``road-link-target-missing``). JSON (``--format json``) gives a list of
``{"code", "name", "category", "severity", "default_severity", "basis", "summary", "uids", "fix"}`` objects, or for
one rule that object plus ``"doc"``, ``"tolerances"``, ``"standard"`` (per UID: uid, section, level and the annex's
description) and ``"fixes"``. Text is plain (the docstrings' reStructuredText markup taken out); ``summary`` is the
documentation's first sentence, whole. ``basis`` says what the rule's findings rest on: ``annex-f`` (each names the
Annex F rule it enforces), ``schema``, ``reading``, ``plausibility`` (the checker's own judgement), ``incomplete``, or
``annex-f`` and one of these for a rule whose findings do not all name a UID; ``default_severity`` is the most severe a
finding of the rule is under the default profile (the standard's words bound it).

A rule whose findings ``xodrcheck fix`` can repair is marked ``fix:safe``, ``fix:unsafe`` or ``fix:safe+unsafe`` in
the list (JSON: ``"fix"``); one rule's page describes each fix, what it may move, and whether it needs ``--unsafe``.

``xodrcheck rules --tolerances`` lists every tolerance: name, default, the ``strict`` profile's value, unit, the rules
it bounds, and what it bounds (JSON: a list of objects with those keys).

``xodrcheck rules --standard`` lists every checker rule of ASAM OpenDRIVE 1.9.0 (Annex F) by UID with its status,
computed from the registry: enforced (by which codes), enforced in part (and what is left out) or not enforced (and
why). ``--format md`` gives the same as a Markdown table.
"""

from __future__ import annotations

import argparse
import json

from xodrcheck.cli.common import error
from xodrcheck.findings import Severity
from xodrcheck.rules import load_rules
from xodrcheck.rules.registry import Rule
from xodrcheck.rules.shared.plaintext import plain

NAME = "rules"
HELP = (
    "List the checker's rules (code, name, category, severity, basis, summary), or show one rule in full with the "
    "sentences of the standard it enforces."
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("code", nargs="?", metavar="CODE", help="a rule code or name: print its full documentation")
    parser.add_argument(
        "--standard",
        action="store_true",
        help="list the checker rules of ASAM OpenDRIVE 1.9.0 (Annex F) by UID, each with its status here",
    )
    parser.add_argument(
        "--tolerances",
        action="store_true",
        help="list every tolerance with its default, unit, the rules using it and what it bounds",
    )
    parser.add_argument(
        "--format", choices=("text", "json", "md"), default="text", help="output format (default: text; md: --standard)"
    )


def basis_label(rule: Rule) -> str:
    """What the rule's findings rest on, in a word or two (module docstring)."""
    if not rule.uids:
        return rule.basis or "-"
    return "annex-f" if rule.basis is None else f"annex-f, {rule.basis}"


def default_severity(rule: Rule) -> Severity:
    """The most severe a finding of ``rule`` is under the default profile: its severity, bounded by the level of each
    UID it names and by the basis of its findings without one."""
    from xodrcheck.findings import Finding
    from xodrcheck.verdict import bound

    kinds = [Finding(rule.code, rule.name, rule.category, rule.severity, "", rule_uid=uid) for uid in rule.uids]
    if rule.basis is not None or not rule.uids or rule.every_version:
        kinds.append(Finding(rule.code, rule.name, rule.category, rule.severity, "", basis=rule.basis or ""))
    return max(min(rule.severity, bound(f) or rule.severity) for f in kinds)


_BASIS_WORDS = {
    "schema": "the XSD schema of the file's declared OpenDRIVE version",
    "reading": "the file cannot be read as OpenDRIVE as it is written",
    "plausibility": (
        "the checker's own judgement, which the standard does not state: at most a warning under the default profile; "
        "--profile strict or generator gives the rule's own severity"
    ),
    "incomplete": "the check did not run to its end, so the file is not known to be right",
}


def _standard_rows(rule: Rule) -> list[dict]:
    from xodrcheck.standard import annex_rules

    annex = annex_rules()
    return [
        {"uid": uid, "section": annex[uid].section, "level": annex[uid].level, "description": annex[uid].description}
        for uid in rule.uids
    ]


def _as_dict(rule: Rule, full: bool = False) -> dict:
    from xodrcheck.fix.registry import fixable, fixers_for

    d: dict[str, object] = {
        "code": rule.code,
        "name": rule.name,
        "category": rule.category.value,
        "severity": str(rule.severity),
        "default_severity": str(default_severity(rule)),
        "basis": basis_label(rule),
        "summary": rule.summary,
        "uids": list(rule.uids),
        "fix": fixable(rule.code),
    }
    if full:
        d["doc"] = rule.doc
        d["tolerances"] = rule_tolerances(rule.code)
        d["standard"] = _standard_rows(rule)
        d["fixes"] = [
            {"name": f.name, "kind": f.kind, "bound": f.bound, "doc": plain(f.doc)} for f in fixers_for(rule.code)
        ]
    return d


def _fixes_text(code: str) -> str:
    """What ``xodrcheck fix`` does for the rule's findings, in plain text (empty without a fix)."""
    from xodrcheck.fix.registry import fixers_for

    parts = [
        f"fix {f.name} ({f.kind}; {f.bound}{'' if f.safe else '; with --unsafe'}):\n{plain(f.doc)}"
        for f in fixers_for(code)
    ]
    return "\n\n".join(parts)


def _describe(rule: Rule) -> str:
    """``xodrcheck rules CODE`` in text: the heading, the basis, each UID with the standard's words, the tolerances,
    then the documentation."""
    most = default_severity(rule)
    under = f"; default profile: {most}" if most != rule.severity else ""
    lines = [f"{rule.code} {rule.name} ({rule.category.value}, {rule.severity}{under})", ""]
    if rule.uids:
        lines.append("basis: Annex F (each finding names the rule of the standard it enforces)")
    if rule.basis is not None:
        lead = "findings naming no UID rest on" if rule.uids else "basis:"
        lines.append(f"{lead} {rule.basis} ({_BASIS_WORDS[rule.basis]})")
    for row in _standard_rows(rule):
        part = f"; in part: {rule.partial[row['uid']]}" if row["uid"] in rule.partial else ""
        lines.append(f"enforces {row['uid']} ({row['section']}, {row['level']}{part})")
        lines.append(f"  {row['description']}")
    tolerances = rule_tolerances(rule.code)
    if tolerances:
        lines.append(f"tolerances (xodrcheck rules --tolerances): {'; '.join(tolerances)}")
    fixes = _fixes_text(rule.code)
    repairs = f"\n\nxodrcheck fix repairs its findings:\n{fixes}" if fixes else ""
    return "\n".join(lines) + "\n\n" + plain(rule.doc) + repairs


def _standard(fmt: str) -> int:
    from xodrcheck.standard.status import statuses, summary_line

    table = statuses(load_rules())
    if fmt == "json":
        print(json.dumps({"summary": summary_line(table), "rules": [row.as_dict() for row in table]}, indent=2))
        return 0
    if fmt == "md":
        print(f"{summary_line(table)}\n")
        print("| UID | section | level | status | codes | note |\n|---|---|---|---|---|---|")
        for row in table:
            print(
                f"| `{row.uid}` | {row.section} | {row.level} | {row.status} | {', '.join(row.codes)} | "
                f"{row.note.replace('|', '/')} |"
            )
        return 0
    width = max(len(row.uid) for row in table)
    for row in table:
        codes = ",".join(row.codes) or "-"
        note = f"  ({row.note})" if row.note else ""
        print(f"{row.uid:<{width}}  {row.section:<10} {row.level:<6} {row.status:<12} {codes}{note}")
    print(summary_line(table))
    return 0


def tolerance_rows() -> list[dict]:
    """One row per tolerance: name, default, strict (the strict profile's value, or the default), unit, the codes of
    the rules it bounds, and its documentation."""
    import dataclasses

    from xodrcheck.config import PROFILES, Tolerances

    rows = []
    strict = PROFILES["strict"].tolerance_values()
    for f in dataclasses.fields(Tolerances):
        default = getattr(Tolerances, f.name)
        rows.append(
            {
                "name": f.name,
                "default": default,
                "strict": getattr(strict, f.name),
                "unit": f.metadata.get("unit", ""),
                "rules": list(f.metadata.get("rules", ())),
                "doc": f.metadata.get("doc", ""),
            }
        )
    return rows


def _number(value: float) -> str:
    return f"{value:,}" if isinstance(value, int) else f"{value:g}"


def rule_tolerances(code: str) -> list[str]:
    """``name = default unit`` of each tolerance that bounds the rule ``code``."""
    return [
        f"{row['name']} = {_number(row['default'])} {row['unit']}" for row in tolerance_rows() if code in row["rules"]
    ]


def _tolerances(fmt: str) -> int:
    rows = tolerance_rows()
    if fmt == "json":
        print(json.dumps(rows, indent=2))
        return 0
    width = max(len(row["name"]) for row in rows)
    print(f"{'tolerance':<{width}}  {'default':>11}  {'strict':>11}  unit  rules: meaning")
    for row in rows:
        used = f"{','.join(row['rules'])}: " if row["rules"] else ""
        print(
            f"{row['name']:<{width}}  {_number(row['default']):>11}  {_number(row['strict']):>11}  {row['unit']:<4}  "
            f"{used}{row['doc']}"
        )
    print(
        "Override in [tool.xodrcheck.tolerances] of pyproject.toml, in xodrcheck.toml or with --tolerance NAME=VALUE; "
        "--profile strict applies the strict column."
    )
    print(profiles_text())
    return 0


def profiles_text() -> str:
    """What each profile does, one paragraph each (``--profile``, key ``profile``)."""
    from xodrcheck.config import PROFILES

    lines = ["Profiles (--profile NAME, or profile = NAME in the configuration):"]
    lines += [f"  {p.name}: {p.doc}" for p in PROFILES.values()]
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    if args.tolerances:
        if args.code or args.standard or args.format == "md":
            error("rules: --tolerances lists every tolerance; it takes no CODE, --standard or --format md")
            return 2
        return _tolerances(args.format)
    if args.standard:
        if args.code:
            error("rules: --standard lists every rule of the standard; it takes no CODE")
            return 2
        return _standard(args.format)
    if args.format == "md":
        error("rules: --format md goes with --standard")
        return 2
    rules = sorted(load_rules().values(), key=lambda r: r.code)
    if args.code:
        wanted = args.code.strip()
        found = [r for r in rules if r.code == wanted.upper() or r.name == wanted]
        if not found:
            error(f"rules: no rule {wanted!r} (run `xodrcheck rules` for the list)")
            return 2
        rule = found[0]
        print(json.dumps(_as_dict(rule, full=True), indent=2) if args.format == "json" else _describe(rule))
        return 0
    if args.format == "json":
        print(json.dumps([_as_dict(r) for r in rules], indent=2))
        return 0
    from xodrcheck.fix.registry import fixable

    width = max((len(r.name) for r in rules), default=0)
    kind = max((len(r.category.value) for r in rules), default=0)
    bases = max((len(basis_label(r)) for r in rules), default=0)
    for r in rules:  # the severity a finding gets under the default profile (the rule's own: `rules CODE`)
        fix = fixable(r.code)
        mark = f"fix:{fix}" if fix else ""
        most = default_severity(r)
        print(
            f"{r.code}  {r.name:<{width}}  {r.category.value:<{kind}}  {most!s:<7}  {basis_label(r):<{bases}}  "
            f"{mark:<15} {r.summary}"
        )
    return 0
