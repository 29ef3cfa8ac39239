"""``xodrcheck check FILE...``: run the conformance rules and report what they find.

Exit codes: 0 no error-level finding, 1 an error-level finding (``--strict``: a warning too), 2 a usage error (an
unknown rule selector, a bad ``--tolerance``, an unwritable ``-o``) or a file that cannot be opened at all (then no
``-o`` file is written), 3 the check is incomplete: a rule crashed (X900) or a time bound set with ``time_budget``
stopped rules (X901), and nothing else failed. A file whose content cannot be read (empty, not XML, truncated) is not
exit 2 here: that is what the check reports (X101, exit 1).

Configuration comes from ``xodrcheck.toml`` or ``[tool.xodrcheck]`` in the nearest ``pyproject.toml`` (keys
``select``, ``ignore``, ``strict``, ``profile``, ``min_severity`` and a ``tolerances`` table); ``--select``/``--ignore``
replace the configured lists, ``--profile`` the profile (``default``: the standard's verdicts; ``strict``,
``generator``: every rule's own severity, see :data:`xodrcheck.config.PROFILES`), ``--tolerance`` overrides single
tolerances. A directory argument stands for the ``*.xodr`` files under it.

``--min-severity`` limits what the report shows (text and github: warnings and errors by default, with one line per
code of the infos left out; json, sarif, junit, xqar: everything). Findings that fail the check are always shown; the
exit code does not depend on what is shown.

The text report starts with the verdict (``FAIL: 3 errors of 2 rules in 1 of 4 files; 12 warnings``, see
:mod:`xodrcheck.report.verdict`) and ends with a tally per rule (``--statistics``; by default when more than 20
findings are shown) and, over several files, the files that fail. The verdict is also printed on stderr, last, unless
the text report is on a terminal and fits it (its first line is in sight); with ``-o FILE`` stderr says ``wrote FILE
(N findings, SIZE)``.
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path

from xodrcheck.cli.common import error, target_ok, written
from xodrcheck.config import PROFILES, SEVERITY_NAMES, Config, ConfigError, load_config
from xodrcheck.findings import ReadError, Severity
from xodrcheck.report import FORMATS, least_severity, render, shown
from xodrcheck.report.verdict import count, verdict
from xodrcheck.rules.internal import ENGINE_CODES

NAME = "check"
HELP = "Check OpenDRIVE files against the conformance rules (exit 1 when an error is found)."


def split_selectors(values: list[str] | None, flag: str) -> tuple[str, ...] | None:
    if values is None:
        return None
    parts = tuple(part.strip() for value in values for part in value.split(",") if part.strip())
    if not parts:
        raise ConfigError(f"{flag} needs at least one rule code, prefix, name or category")
    return parts


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE", help="OpenDRIVE files or folders of them")
    parser.add_argument(
        "--select",
        action="append",
        metavar="RULES",
        help="only these rules: codes, code prefixes, names, categories, UIDs, or severities (info, warning, error: "
        "findings of that severity), comma-separated (repeatable)",
    )
    parser.add_argument("--ignore", action="append", metavar="RULES", help="leave these rules out (same forms)")
    parser.add_argument(
        "--min-severity",
        choices=SEVERITY_NAMES,
        help="least severity the report shows (default: warning for text and github, info for the other formats); "
        "the exit code counts every finding",
    )
    parser.add_argument(
        "--profile",
        choices=tuple(PROFILES),
        help="how findings are judged: default (the standard's verdicts: errors only for Annex F 'shall' rules, "
        "the schema and unreadable content; 'should' rules and the checker's own plausibility checks are warnings, "
        "gaps from 1 cm and kinks from 0.01 rad), strict (every rule's own severity, errors from 1 mm and 1 mrad) or "
        "generator (every rule's own severity with the default tolerances: what junctionart guarantees); "
        "`xodrcheck rules --tolerances` lists the values",
    )
    parser.add_argument("--strict", action="store_true", default=None, help="warnings fail the check too")
    parser.add_argument("--format", choices=FORMATS, default="text", help="report format (default: text)")
    parser.add_argument(
        "--statistics",
        action=argparse.BooleanOptionalAction,
        default=None,
        help="end the text report with the findings shown counted per rule (count, code, severity, name, basis); "
        "by default when more than 20 findings are shown",
    )
    parser.add_argument(
        "-o", "--output", metavar="FILE", help="write the report to FILE (atomically) instead of stdout"
    )
    parser.add_argument(
        "--tolerance",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="override a tolerance, e.g. --tolerance gap=0.005 (repeatable; `xodrcheck rules --tolerances` lists them)",
    )
    parser.add_argument(
        "-j",
        "--jobs",
        type=_jobs,
        metavar="N",
        help="check N files at a time in worker processes (default: all cores); the report is the same as with -j 1",
    )
    parser.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="check the files on a Dask cluster (e.g. tcp://host:8786; needs the dask extra and the paths on its "
        "workers)",
    )


def _jobs(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {text!r}")
    return value


def tolerance_overrides(items: list[str]) -> dict[str, str]:
    out: dict[str, str] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise ConfigError(f"--tolerance expects NAME=VALUE, got {item!r}")
        out[name.strip()] = value.strip()
    return out


def _expand(files: list[str]) -> list[str]:
    out: list[str] = []
    for name in files:
        p = Path(name)
        if p.is_dir():
            found = sorted(str(f) for f in p.rglob("*.xodr") if f.is_file())
            if not found:
                raise ReadError("a folder without .xodr files", name)
            out.extend(found)
        else:
            out.append(name)
    return out


def run(args: argparse.Namespace) -> int:
    from xodrcheck.support.batch import BatchError, check_files

    config = _config(args)
    if config is None or not target_ok(args.output):
        return 2
    try:
        files = _expand(args.files)
    except ReadError as exc:
        error(str(exc))
        return 2
    try:
        outcomes = check_files(
            files, config, jobs=args.jobs, scheduler=args.scheduler, progress=len(files) > 1 and sys.stderr.isatty()
        )
    except BatchError as exc:
        error(f"check: {exc}")
        return 2
    reports = []
    unreadable: list[str] = []  # files that could not be checked: exit 2
    for outcome in outcomes:  # in the order given, however the files were checked
        if outcome.report is not None:
            reports.append(outcome.report)
        else:
            error(outcome.error or f"cannot check {outcome.path}")
            unreadable.append(outcome.path)
    if unreadable and args.output not in (None, "-"):
        if reports:  # the others could be: say why their findings are not in the file either
            error(f"nothing written to {args.output}: a file could not be checked")
        return 2
    if not _write_report(args, config, reports, unreadable):
        return 2
    return exit_code(reports, bool(unreadable))


def _config(args: argparse.Namespace) -> Config | None:
    """The configuration the options and the configuration file give (``None``, said on stderr, when it is bad)."""
    from xodrcheck.check import Selection

    try:
        config = load_config(overrides=tolerance_overrides(args.tolerance), profile=args.profile)
        select, ignore = split_selectors(args.select, "--select"), split_selectors(args.ignore, "--ignore")
        config = dataclasses.replace(
            config,
            select=config.select if select is None else select,
            ignore=config.ignore if ignore is None else ignore,
            strict=config.strict if args.strict is None else True,
            min_severity=args.min_severity or config.min_severity,
        )
        Selection(config.select, config.ignore)  # validates the selectors before any file is read
    except ConfigError as exc:
        error(f"check: {exc}")
        return None
    except (OSError, ValueError) as exc:  # an unreadable or malformed configuration file
        error(f"check: configuration: {exc}")
        return None
    return config


def _write_report(args: argparse.Namespace, config: Config, reports: list, unreadable: list[str]) -> bool:
    """Render the reports in the asked format to the output, and the verdict to stderr; ``False`` when the output
    cannot be written (said on stderr)."""
    to_file = args.output not in (None, "-")
    least = least_severity(config.min_severity, args.format)
    visible = shown(reports, least)[0]
    if args.format == "text":  # shows its own verdict, what it left out and the failing files: it takes every report
        text = render("text", reports, least=least, statistics=args.statistics, unreadable=unreadable)
    else:
        text = render(args.format, visible)
    if not written(args.output, lambda stream: stream.write(text)):
        return False
    if not (args.format == "text" and not to_file and _in_sight(text)):
        print(verdict(reports, len(unreadable)), file=sys.stderr)
    if to_file:
        found = count(sum(len(r.findings) for r in visible), "finding")
        print(f"wrote {args.output} ({found}, {_size(Path(args.output))})", file=sys.stderr)
    return True


def exit_code(reports: list, unreadable: bool = False) -> int:
    """2 when a file could not be checked, else 1 when a file fails for a finding of its own, else 3 when a check is
    incomplete (a rule crashed or ran out of time, and nothing else failed), else 0."""
    if unreadable:
        return 2
    if any(not r.ok and not _fails_only_for_incompleteness(r) for r in reports):
        return 1
    if any(not r.complete for r in reports):
        return 3
    return 0


def _fails_only_for_incompleteness(report) -> bool:
    worst = Severity.WARNING if report.strict else Severity.ERROR
    return all(f.code in ENGINE_CODES for f in report.findings if f.severity >= worst)


def _in_sight(text: str) -> bool:
    """Whether ``text``, printed on a terminal, leaves its first line in sight (it fits the window)."""
    import shutil

    return sys.stdout.isatty() and text.count("\n") < shutil.get_terminal_size().lines


def _size(path: Path) -> str:
    size = path.stat().st_size
    if size < 1024:
        return f"{size} B"
    return f"{size / 1024:.1f} KiB" if size < 1024**2 else f"{size / 1024**2:.1f} MiB"
