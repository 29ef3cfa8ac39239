"""``xodrcheck rules [CODE]``: list the rules, or print one rule's documentation with its examples.

``CODE`` may be a code (``R010``) or a name (``road-link-target-missing``). JSON (``--format json``) gives a list of
``{"code", "name", "category", "severity", "summary"}`` objects, or for one rule that object plus ``"doc"``.
"""

from __future__ import annotations

import argparse
import json

from xodrcheck.cli._common import error
from xodrcheck.rules import load_rules
from xodrcheck.rules.registry import Rule

NAME = "rules"
HELP = "List the checker's rules (code, name, category, severity, summary), or show one rule in full."


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("code", nargs="?", metavar="CODE", help="a rule code or name: print its full documentation")
    parser.add_argument("--format", choices=("text", "json"), default="text", help="output format (default: text)")


def _as_dict(rule: Rule, full: bool = False) -> dict:
    d = {
        "code": rule.code,
        "name": rule.name,
        "category": rule.category.value,
        "severity": str(rule.severity),
        "summary": rule.summary,
    }
    if full:
        d["doc"] = rule.doc
    return d


def run(args: argparse.Namespace) -> int:
    rules = sorted(load_rules().values(), key=lambda r: r.code)
    if args.code:
        wanted = args.code.strip()
        found = [r for r in rules if r.code == wanted.upper() or r.name == wanted]
        if not found:
            error(f"rules: no rule {wanted!r} (run `xodrcheck rules` for the list)")
            return 2
        rule = found[0]
        if args.format == "json":
            print(json.dumps(_as_dict(rule, full=True), indent=2))
        else:
            print(f"{rule.code} {rule.name} ({rule.category.value}, {rule.severity})\n")
            print(rule.doc)
        return 0
    if args.format == "json":
        print(json.dumps([_as_dict(r) for r in rules], indent=2))
        return 0
    width = max((len(r.name) for r in rules), default=0)
    for r in rules:
        print(f"{r.code}  {r.name:<{width}}  {r.category.value:<9}  {r.severity!s:<7}  {r.summary}")
    return 0
