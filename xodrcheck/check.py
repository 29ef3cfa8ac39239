"""The checking engine: read a file, run the selected rules, collect their findings in a :class:`Report`.

>>> report = check("map.xodr")                       # doctest: +SKIP
>>> report.ok, [f.code for f in report.findings]     # doctest: +SKIP

Rules are selected by code (``R010``), code prefix (``R``, ``R01``), name (``link-not-reciprocal``), category
(``reference``), or the UID of a rule of the standard, exact or as a UNIX-style pattern
(``asam.net:xodr:*:road.lane.*``). A rule that raises is reported as an ``X900 rule-crashed`` finding naming the
rule and the exception; ``check`` itself raises only :class:`~xodrcheck.findings.ReadError` (the input cannot be
opened at all) and :class:`~xodrcheck.config.ConfigError` (a selector names no rule).
"""

from __future__ import annotations

import io
import re
import time
import zlib
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from xodrcheck.config import Config, ConfigError
from xodrcheck.findings import Category, Finding, OutOfTime, Severity
from xodrcheck.rules import load_rules
from xodrcheck.rules.internal import ENGINE_CODES as _ENGINE_CODES
from xodrcheck.rules.internal import RULE_CRASHED, RULE_OUT_OF_TIME
from xodrcheck.rules.registry import Rule
from xodrcheck.rules.shared.context import Context
from xodrcheck.standard import annex_rules, is_uid, uid_matches
from xodrcheck.support import memory
from xodrcheck.verdict import judge

__all__ = ["Report", "Selection", "check", "is_valid", "is_valid_reason", "run_rules", "validate_selectors"]


@dataclass(frozen=True)
class Report:
    """What :func:`check` found in one file."""

    path: str | None
    #: The declared OpenDRIVE version as ``"1.7"`` (``None`` when the header does not say).
    version: str | None
    #: Sorted by line, then code.
    findings: tuple[Finding, ...]
    #: Codes of the rules applied (reader rules included), in the order they ran.
    rules_run: tuple[str, ...]
    strict: bool = False
    #: The profile that judged the findings (:data:`xodrcheck.config.PROFILES`).
    profile: str = "default"

    @property
    def complete(self) -> bool:
        """Every selected rule ran to its end: no ``X900 rule-crashed``, no ``X901 rule-out-of-time``. An incomplete
        report is never :attr:`ok` (both findings are errors): what was not checked is not known to be right."""
        return not any(f.code in _ENGINE_CODES for f in self.findings)

    @property
    def ok(self) -> bool:
        """No error-level finding (with ``strict``: no warning either); so also :attr:`complete`."""
        worst = Severity.WARNING if self.strict else Severity.ERROR
        return not any(f.severity >= worst for f in self.findings)

    def count(self, severity: Severity) -> int:
        return sum(1 for f in self.findings if f.severity is severity)

    @property
    def errors(self) -> int:
        return self.count(Severity.ERROR)

    @property
    def warnings(self) -> int:
        return self.count(Severity.WARNING)


# ------------------------------------------------------------------------------------------------------ selection
_CODE_PREFIX = re.compile(r"^[A-Za-z][0-9]{0,3}$")
_SEVERITIES = {str(s): s for s in Severity}


def _severity_token(token: str) -> Severity | None:
    """A selector naming a severity (``info``, ``warning``, ``error``): it filters findings by severity."""
    return _SEVERITIES.get(token.strip().lower())


def _matches(token: str, code: str, name: str, category: str) -> bool:
    """A selector matches a rule by its name, its category, or as a prefix of its code (``R``, ``R0``, ``R010``)."""
    token = token.strip()
    if token in (name, category):
        return True
    return _CODE_PREFIX.match(token) is not None and code.startswith(token.upper())


def _rule_matches(token: str, rule: Rule) -> bool:
    """Also by Annex F UID or UID pattern (``asam.net:xodr:*:road.lane.*``): a rule enforcing a matching UID."""
    if is_uid(token.strip()):
        return any(uid_matches(token.strip(), uid) for uid in rule.uids)
    return _matches(token, rule.code, rule.name, rule.category.value)


def _finding_matches(token: str, finding: Finding) -> bool:
    """A UID selector matches the findings that enforce a matching UID; other selectors match by rule."""
    if is_uid(token.strip()):
        return finding.rule_uid is not None and uid_matches(token.strip(), finding.rule_uid)
    return _matches(token, finding.code, finding.name, finding.category.value)


def validate_selectors(tokens: Iterable[str], rules: dict[str, Rule] | None = None) -> None:
    """Raise :class:`ConfigError` for a selector that names no rule (a typo would otherwise select nothing)."""
    rules = load_rules() if rules is None else rules
    for token in tokens:
        if not isinstance(token, str):
            raise ConfigError(f"rule selectors are strings (codes, prefixes, names, categories), got {token!r}")
        if not token.strip():
            raise ConfigError("empty rule selector")
        if _severity_token(token) is not None:
            continue
        if is_uid(token.strip()):
            if not any(uid_matches(token.strip(), uid) for uid in annex_rules()):
                raise ConfigError(f"no rule of the standard matches {token!r} (see `xodrcheck rules --standard`)")
        elif not any(_rule_matches(token, r) for r in rules.values()):
            raise ConfigError(f"unknown rule, code prefix or category {token!r} (see `xodrcheck rules`)")


class Selection:
    """Which rules apply: those matching ``select`` (all when empty), minus those matching ``ignore``.

    A UID pattern selects the rules that enforce a matching UID and, of their findings, those that name one; ignored,
    it drops those findings, and the rules whose every UID matches. A severity (``info``, ``warning``, ``error``)
    selects or drops findings of that severity, whatever their rule: with rule selectors, both must match
    (``K1,error``: the errors of the K1xx rules).
    """

    def __init__(self, select: Sequence[str] = (), ignore: Sequence[str] = ()) -> None:
        self.rules = load_rules()
        validate_selectors((*select, *ignore), self.rules)
        self.select = tuple(t for t in select if _severity_token(t) is None)
        self.ignore = tuple(t for t in ignore if _severity_token(t) is None)
        self.severities = frozenset(s for t in select if (s := _severity_token(t)) is not None)
        self.ignored_severities = frozenset(s for t in ignore if (s := _severity_token(t)) is not None)

    def wants_rule(self, rule: Rule) -> bool:
        if self.select and not any(_rule_matches(t, rule) for t in self.select):
            return False
        for token in self.ignore:
            if is_uid(token.strip()):
                if rule.uids and all(uid_matches(token.strip(), uid) for uid in rule.uids):
                    return False
            elif _rule_matches(token, rule):
                return False
        return True

    def wants_finding(self, finding: Finding, severity: Severity | None = None) -> bool:
        """Whether the finding is selected; ``severity`` is the one it is judged to have (default: its own)."""
        severity = finding.severity if severity is None else severity
        if (self.severities and severity not in self.severities) or severity in self.ignored_severities:
            return False
        if self.select and not any(_finding_matches(t, finding) for t in self.select):
            return False
        return not any(_finding_matches(t, finding) for t in self.ignore)


# ------------------------------------------------------------------------------------------------------ running
def _sort_key(f: Finding):
    return (f.line or 0, f.code, f.road or "", f.lane if f.lane is not None else 0, f.s if f.s is not None else -1.0)


def _run_rule(rule: Rule, ctx: Context) -> list[Finding]:
    out: list[Finding] = []
    if rule.check is None:  # a reader rule: its findings come from reading (the caller runs check rules only)
        return out
    try:
        for finding in rule.check(ctx):
            out.append(finding)
    except OutOfTime as exc:
        out.append(
            RULE_OUT_OF_TIME.finding(
                f"rule {rule.code} {rule.name} stopped ({exc}): the time budget (tolerance time_budget) was spent; "
                f"the check is incomplete; {len(out)} finding(s) it gave before are kept"
            )
        )
    except Exception as exc:
        out.append(
            RULE_CRASHED.finding(
                f"rule {rule.code} {rule.name} crashed: {type(exc).__name__}: {exc}; "
                f"{len(out)} finding(s) it gave before are kept"
            )
        )
    return out


def run_rules(ctx: Context, selection: Selection) -> tuple[list[Finding], list[str]]:
    """Run every selected check rule on a context; return their findings and the codes run (in the registry's order).

    The schema rules, which validate the file's XML tree, run first; then the tree is dropped
    (:meth:`Context.release_tree`) and its memory handed back before the geometry rules build their caches; every
    other rule reads the document. Findings do not depend on the order: the report sorts them.
    """
    wanted = [
        rule
        for rule in selection.rules.values()
        if rule.check is not None and selection.wants_rule(rule) and rule.runs_on(ctx.version)
    ]
    findings: list[Finding] = []
    ran: set[str] = set()
    for schema in (True, False):
        for rule in wanted:
            if (rule.category is Category.SCHEMA) is schema:
                _run_timed(rule, ctx, findings, ran)
        if schema:
            ctx.release_tree()
            memory.release()
    return findings, [rule.code for rule in wanted if rule.code in ran]


def _run_timed(rule: Rule, ctx: Context, findings: list[Finding], ran: set[str]) -> None:
    if ctx.out_of_time():
        findings.append(
            RULE_OUT_OF_TIME.finding(
                f"rule {rule.code} {rule.name} not run: the time budget (tolerance time_budget) was spent; "
                "the check is incomplete"
            )
        )
        return
    started = time.monotonic()
    findings.extend(_run_rule(rule, ctx))
    ran.add(rule.code)
    if time.monotonic() - started > _RELEASE_AFTER:
        memory.release()  # a rule that ran long built and dropped much: give it back before the next


#: Seconds a rule runs before the memory it freed is handed back to the system
#: (:func:`xodrcheck.support.memory.release`); quick rules on small files skip it.
_RELEASE_AFTER = 0.2


def _version_text(ctx_version: tuple[int, int] | None) -> str | None:
    return None if ctx_version is None else f"{ctx_version[0]}.{ctx_version[1]}"


def check(
    source: str | Path | bytes,
    config: Config | None = None,
    select: Sequence[str] = (),
    ignore: Sequence[str] = (),
) -> Report:
    """Check one OpenDRIVE file (a path, or the file's bytes).

    ``select``/``ignore`` override the configuration's when given. ``config`` defaults to :class:`Config` defaults
    (the command line loads ``pyproject.toml``/``xodrcheck.toml``; call :func:`~xodrcheck.config.load_config` for
    that here).
    """
    import numpy as np  # here, not at the top: importing xodrcheck stays light

    from xodrcheck.reader import read_keeping_tree

    config = config or Config()
    selection = Selection(tuple(select) or config.select, tuple(ignore) or config.ignore)
    started = time.monotonic()
    # one parse: the reader's tree is schema validation's (when the file is well-formed), dropped after it
    result, tree = read_keeping_tree(source, max_bytes=config.tolerances.max_file_bytes)
    data = None if tree is not None else _raw(_source_bytes(source, result.path), config.tolerances.max_file_bytes)
    judging = _Judging(None if result.document is None else result.document.version, selection, config)
    findings = judging.kept(result.findings)
    run = [
        r.code
        for r in selection.rules.values()
        if r.check is None and r.code not in _ENGINE_CODES and selection.wants_rule(r)
    ]
    version = None
    if result.document is not None:
        # damaged numbers (1e308 widths, say) overflow to inf/nan inside the geometry; the rules report them as
        # findings, and numpy's floating-point warnings would only repeat that as noise (IEEE results are the same)
        with np.errstate(all="ignore"):
            ctx = Context(
                result.document,
                config,
                path=result.path,
                data=data,
                deadline=_deadline(started, config.tolerances.time_budget),
                tree=tree,
            )
            del tree  # the context holds it until the schema rules have run
            version = _version_text(ctx.version)
            more, ran = run_rules(ctx, selection)
            findings.extend(judging.kept(more))
            findings = ctx.locate_all(findings)  # x, y, z of every finding naming a road and an s
        run.extend(ran)
    return Report(
        path=result.path,
        version=version,
        findings=tuple(sorted(findings, key=_sort_key)),
        rules_run=tuple(run),
        strict=config.strict,
        profile=config.profile,
    )


class _Judging:
    """Each finding judged once (:func:`xodrcheck.verdict.judge`: the file's version, the profile's bounds), then
    selected: by rule and UID as the rule gave it, by severity as judged. The engine's own findings are always kept."""

    def __init__(self, version: tuple[int, int] | None, selection: Selection, config: Config) -> None:
        self.version, self.selection, self.profile = version, selection, config.profile_spec

    def kept(self, findings: Iterable[Finding]) -> list[Finding]:
        out = []
        for f in findings:
            judged = judge(f, self.version, self.selection.rules, self.profile)
            if judged is not None and (
                f.code in _ENGINE_CODES or self.selection.wants_finding(f, severity=judged.severity)
            ):
                out.append(judged)
        return out


def _deadline(started: float, budget: float) -> float | None:
    """The monotonic time past which rules stop; ``None`` (no bound) for a budget of 0, the default."""
    return started + budget if budget > 0 else None


def _source_bytes(source: str | Path | bytes, path: str | None) -> bytes | None:
    """The bytes checked: those given, or the file's."""
    return source if isinstance(source, bytes) else _read_bytes(path)


def _raw(data: bytes | None, limit: int) -> bytes | None:
    """The XML bytes the reader parsed: gzip-compressed files (``.xodrz``) are decompressed."""
    if data is None or not data.startswith(b"\x1f\x8b"):
        return data
    try:
        import gzip  # here: only compressed files need it

        with gzip.GzipFile(fileobj=io.BytesIO(data)) as stream:
            out = stream.read(limit + 1)
    except (OSError, EOFError, zlib.error):
        return None
    return out if len(out) <= limit else None


def _read_bytes(path: str | None) -> bytes | None:
    if path is None:
        return None
    try:
        return Path(path).read_bytes()
    except OSError:
        return None


def is_valid(source: str | Path | bytes, config: Config | None = None) -> bool:
    """True when :func:`check` finds no error and every rule ran to its end (shapely's ``is_valid``). Raises
    :class:`~xodrcheck.findings.ReadError`, naming the path, when the file cannot be opened at all."""
    return check(source, config).ok


def is_valid_reason(source: str | Path | bytes, config: Config | None = None) -> str:
    """``"Valid OpenDRIVE"`` or the first failing finding as ``"CODE name: message [where]"``."""
    report = check(source, config)
    if report.ok:
        return "Valid OpenDRIVE"
    worst = Severity.WARNING if report.strict else Severity.ERROR
    first = next(f for f in report.findings if f.severity >= worst)
    where = f" [line {first.line}]" if first.line else ""
    return f"{first.code} {first.name}: {first.message}{where}"
