"""``xodrcheck fix FILE... [-o OUT | --in-place] [--unsafe] [--select/--ignore R] [--diff]``: repair what can be
repaired, safely, and check the result.

Every repair edits the file's bytes (everything it does not touch stays byte for byte) and is kept only when the
check of the result shows its finding gone and no new one (:mod:`xodrcheck.fix`). ``-o OUT`` writes the fixed file
to OUT, ``--in-place`` over each FILE, atomically either way. Without them nothing is written: the command prints
the diff it would apply (a dry run, so that a first try never changes a file the user has not asked to change).
Standard output: the diff (``--diff``, or a dry run), else the check of the fixed file as ``check`` prints it.
Standard error: per file, what was fixed and what is left by rule, with why.

Exit codes as ``check``'s, for the fixed file: 0 no error left, 1 an error left (``--strict``: a warning too), 2 a
usage error or a file that cannot be read or written (nothing written for it), 3 the check is incomplete.
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from typing import TYPE_CHECKING

from xodrcheck.cli.check import exit_code, split_selectors, tolerance_overrides
from xodrcheck.cli.common import error, guarded, target_ok
from xodrcheck.config import PROFILES, ConfigError, load_config
from xodrcheck.findings import ReadError
from xodrcheck.report import FORMATS, least_severity, render, shown
from xodrcheck.report.text import not_shown
from xodrcheck.support.atomic import OutputError, write_bytes

if TYPE_CHECKING:
    from xodrcheck.check import Report

NAME = "fix"
HELP = "Repair what can be repaired, safely, and check the result (-o OUT or --in-place writes it; else a diff)."


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE", help="OpenDRIVE files")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("-o", "--output", metavar="OUT", help="write the fixed file to OUT (one FILE only)")
    where.add_argument("--in-place", action="store_true", help="write each fixed file over its FILE")
    parser.add_argument(
        "--unsafe",
        action="store_true",
        help="also apply the unsafe fixes (they may move geometry up to their stated bound, or drop references); "
        "each says what it moved and by how much",
    )
    parser.add_argument("--select", action="append", metavar="RULES", help="fix and report only these rules (as check)")
    parser.add_argument("--ignore", action="append", metavar="RULES", help="leave these rules out (as check)")
    parser.add_argument("--diff", action="store_true", help="print a unified diff of the changes instead of the report")
    parser.add_argument("--profile", choices=tuple(PROFILES), help="tolerance profile (as check)")
    parser.add_argument("--strict", action="store_true", default=None, help="warnings fail the check too")
    parser.add_argument("--format", choices=FORMATS, default="text", help="format of the report (default: text)")
    parser.add_argument(
        "--tolerance", action="append", default=[], metavar="NAME=VALUE", help="override a tolerance (as check)"
    )


def preload() -> None:
    """Import what :func:`run` needs: the engine, every rule and every fix."""
    from xodrcheck.fix.registry import load_fixers
    from xodrcheck.rules import load_rules

    load_rules()
    load_fixers()


def _config(args: argparse.Namespace):
    config = load_config(overrides=tolerance_overrides(args.tolerance), profile=args.profile)
    return dataclasses.replace(config, strict=config.strict if args.strict is None else True)


def run(args: argparse.Namespace) -> int:
    from xodrcheck.check import Selection

    if args.output is not None and len(args.files) > 1:
        error("fix: -o takes one FILE; use --in-place for several")
        return 2
    try:
        config = _config(args)
        select, ignore = split_selectors(args.select, "--select") or (), split_selectors(args.ignore, "--ignore") or ()
        Selection(select or config.select, ignore or config.ignore)  # validates the selectors before any work
    except ConfigError as exc:
        error(f"fix: {exc}")
        return 2
    except (OSError, ValueError) as exc:
        error(f"fix: configuration: {exc}")
        return 2
    if args.output is not None and not target_ok(args.output):
        return 2
    codes: list[int] = []
    reports: list[Report] = []
    for path in args.files:
        code, report = _one(args, path, config, select, ignore)
        codes.append(code)
        if report is not None:
            reports.append(report)
    if not (args.diff or _dry(args)) and reports:
        visible, hidden = shown(reports, least_severity(config.min_severity, args.format))
        sys.stdout.write(render(args.format, visible))
        if args.format == "text":
            sys.stdout.write(not_shown(hidden))
    if 2 in codes:
        return 2
    return exit_code(reports)


def _dry(args: argparse.Namespace) -> bool:
    return args.output is None and not args.in_place


def _one(args: argparse.Namespace, path: str, config, select, ignore) -> tuple[int, Report | None]:
    """Fix one file: write it where asked, print its diff when asked, its summary on stderr. Returns an exit code
    (2 or 0: the report decides the rest) and the report of the fixed file."""
    from xodrcheck.fix.result import fix
    from xodrcheck.fix.summary import summary_lines

    holder: list = []

    def work() -> int:
        holder.append(fix(path, config, select=select, ignore=ignore, unsafe=args.unsafe))
        return 0

    try:
        if guarded(path, work) != 0:
            return 2, None
    except ReadError as exc:
        error(str(exc))
        return 2, None
    result = holder[0]
    target = args.output if args.output is not None else path if args.in_place else None
    if target is not None and (result.changed or target != path):
        try:
            write_bytes(target, result.data)
        except OutputError as exc:
            error(str(exc))
            return 2, None
    if args.diff or _dry(args):
        sys.stdout.write(result.diff())
    for line in summary_lines(result, path, least_severity(config.min_severity, "text")):
        print(line, file=sys.stderr)
    if _dry(args) and result.changed:
        print(f"{path}: nothing written (a dry run): -o OUT or --in-place writes the fixed file", file=sys.stderr)
    elif target is not None:
        print(f"{path}: wrote {target}" + ("" if result.changed else " (nothing to fix: unchanged)"), file=sys.stderr)
    # the report is of the file written (an HTML report draws its map from there); a dry run's, of the input
    return 0, result.report if target is None else dataclasses.replace(result.report, path=target)
