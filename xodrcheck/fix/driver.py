"""The fix loop: check -> fixable findings -> repairs -> edits -> check again, until nothing changes.

Each fix (:mod:`xodrcheck.fix.registry`) plans repairs for its rule's findings on the current bytes; repairs that
touch the same bytes as an earlier one wait for the next round. The batch is applied and the file checked again: the
batch stays when every finding it claims is gone and no finding is new (:mod:`xodrcheck.fix.verify`). Otherwise the
repairs that left their finding are rolled back, so are those a new finding lies on (on a line they edit or in their
scope), and the rest is tried again; a new finding no repair is so blamed for splits the batch (the repairs whose
findings name its road apart, else in halves) until the repair that brought it is found. Rounds repeat while something
was fixed or waited, at most :data:`MAX_ROUNDS` times; a rolled-back repair is tried again only after another batch has
changed the file. So a file with nothing to fix comes out byte-identical, and fixing a fixed file changes nothing.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from xodrcheck.check import Report, Selection, check
from xodrcheck.config import Config
from xodrcheck.findings import Finding
from xodrcheck.fix.edits import Edit, LineMap, apply, overlaps
from xodrcheck.fix.registry import Fixer, Repair, Skip, load_fixers
from xodrcheck.fix.verify import Verdict, place_key, verify
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import ScanError, XmlText, scan
from xodrcheck.model import Document

__all__ = ["MAX_ROUNDS", "Applied", "RolledBack", "Session"]

#: Rounds of the loop at most (a round applies what every fix planned; the next sees the file they left).
MAX_ROUNDS = 5


@dataclass(frozen=True, slots=True)
class Applied:
    """A repair that stayed: the fix, the repair, and the round it landed in."""

    fixer: Fixer
    repair: Repair
    round: int


@dataclass(frozen=True, slots=True)
class RolledBack:
    """A repair taken back, and why (its finding remained, or it brought a new one)."""

    fixer: Fixer
    repair: Repair
    reason: str


@dataclass
class Session:
    """One file's fixing: the bytes as they go, the latest full check, and what was done and left."""

    data: bytes
    config: Config
    selection: Selection
    unsafe: bool = False
    report: Report | None = None
    applied: list[Applied] = field(default_factory=list)
    rolled_back: list[RolledBack] = field(default_factory=list)
    #: Why a fix left a finding alone, by the finding's rule and place.
    skipped: dict[tuple, str] = field(default_factory=dict)
    _document: Document | None = None
    #: Repairs tried (fix, action) -> how many batches had stayed then: one rolled back is tried again only once
    #: another batch has changed the file since.
    _tried: dict[tuple[str, str], int] = field(default_factory=dict)
    _landed: int = 0

    def run(self) -> None:
        self.report = self._check(self.data)
        fixers = [fx for group in load_fixers().values() for fx in group if fx.safe or self.unsafe]
        codes = {fx.code for fx in fixers}
        if not any(f.code in codes and self.selection.wants_finding(f) for f in self.report.findings):
            return  # nothing to fix: the bytes are not even scanned
        try:
            scan(self.data)
        except ScanError as exc:
            self.skipped[("*",)] = f"the file cannot be edited safely: {exc}"
            return
        for number in range(1, MAX_ROUNDS + 1):
            again = False
            for fx in fixers:  # every fix, each round (not only until one progresses)
                again = self._one_fix(fx, number) or again
            if not again:
                break

    # ---------------------------------------------------------------------------------------------------- steps
    def _check(self, data: bytes) -> Report:
        return check(data, self.config)

    def _workspace(self) -> Workspace | None:
        if self._document is None:
            from xodrcheck.reader import read

            self._document = read(self.data, max_bytes=self.config.tolerances.max_file_bytes).document
        if self._document is None or self.report is None:
            return None
        return Workspace(self.data, self._document, self.report.findings, self.config.tolerances)

    def _one_fix(self, fx: Fixer, number: int) -> bool:
        """Plan and try one fix's repairs; whether another round is wanted (a repair stayed, or some waited)."""
        assert self.report is not None
        targets = [f for f in self.report.findings if f.code == fx.code and self.selection.wants_finding(f)]
        if not targets:
            return False
        ws = self._workspace()
        if ws is None:
            return False
        repairs: list[Repair] = []
        for item in fx.plan(ws, targets):
            if isinstance(item, Skip):
                self.skipped.setdefault(place_key(item.finding), item.reason)
            elif self._tried.get((fx.name, item.action), -1) < self._landed and item.findings and item.edits:
                repairs.append(item)
        ready = _disjoint(repairs)
        if not ready:
            return False
        self._tried.update(((fx.name, r.action), self._landed) for r in ready)
        kept = self._attempt(fx, ready, number)
        return kept > 0 or len(ready) < len(repairs)  # repairs that waited go on to the next round

    def _attempt(self, fx: Fixer, repairs: Sequence[Repair], number: int) -> int:
        """Keep the largest part of ``repairs`` found to hold (see the module's docstring); how many stayed. Every
        trial applies the repairs kept so far plus those tried to the same bytes, and is judged against one check."""
        assert self.report is not None
        base, before, lines = self.data, self.report, scan(self.data)
        kept: list[Repair] = []
        best: tuple[bytes, Report] | None = None

        def trial(group: Sequence[Repair]) -> None:
            nonlocal best
            tried = [*kept, *group]
            edits = [e for r in tried for e in r.edits]
            data = apply(base, edits)
            after = self._check(data)
            verdict = verify(before.findings, after.findings, LineMap(lines, edits), tried)
            if verdict.ok:
                kept.extend(group)
                best = (data, after)
            elif len(group) == 1:
                self._roll_back(RolledBack(fx, group[0], _why(verdict.unresolved, verdict.new)))
            elif not verdict.new:  # some claims failed: take those back, try the rest once more
                failed = [r for r in group if r in verdict.unresolved] or list(group)
                for r in failed:
                    self._roll_back(RolledBack(fx, r, _why((r,), ())))
                rest = [r for r in group if r not in failed]
                if rest:
                    trial(rest)
            else:
                guilty = _on_their_lines(group, verdict, lines)
                if guilty:  # new findings on lines these repairs edit: take them back, try the rest
                    for r in guilty:
                        self._roll_back(RolledBack(fx, r, _why((), _on(verdict, r, lines))))
                    rest = [r for r in group if r not in guilty]
                    if rest:
                        trial(rest)
                    return
                suspects = _on_their_roads(group, verdict)  # a coarser guess: tried apart from the others
                parts = (
                    [[r for r in group if r not in suspects], suspects]
                    if 0 < len(suspects) < len(group)
                    else [group[: len(group) // 2], group[len(group) // 2 :]]
                )
                for part in parts:
                    trial(part)

        trial(repairs)
        if best is not None:
            self.data, self.report, self._document = best[0], best[1], None
            self.applied.extend(Applied(fx, r, number) for r in kept)
            self._landed += 1
            done = {(fx.name, r.action) for r in kept}  # tried again and stayed: no longer rolled back
            self.rolled_back = [b for b in self.rolled_back if (b.fixer.name, b.repair.action) not in done]
        return len(kept)

    def _roll_back(self, back: RolledBack) -> None:
        """Record a rolled-back repair (once: a repair tried again replaces its earlier record)."""
        key = (back.fixer.name, back.repair.action)
        self.rolled_back = [b for b in self.rolled_back if (b.fixer.name, b.repair.action) != key] + [back]

    def remaining(self, findings: Sequence[Finding]) -> list[tuple[Finding, str]]:
        """Each finding left with why it is left (see :meth:`reason`)."""
        return [(f, self.reason(f)) for f in findings]

    def reason(self, finding: Finding) -> str:
        """Why a finding is still there: a fix's own words, a repair that was rolled back, an unsafe fix not asked
        for, or no fix for its rule."""
        whole = self.skipped.get(("*",))
        if whole is not None:
            return whole
        place = place_key(finding)
        for back in self.rolled_back:
            if any(place_key(f) == place for f in back.repair.findings):
                return f"a repair was rolled back: {back.reason}"
        if place in self.skipped:
            return self.skipped[place]
        fixers = load_fixers().get(finding.code, ())
        if not fixers:
            return "no fix for this rule"
        if not self.unsafe and all(not fx.safe for fx in fixers):
            return f"only an unsafe fix exists ({fixers[0].name}; --unsafe applies it)"
        if not self.selection.wants_finding(finding):
            return "not selected"
        return "the fixes of this rule found nothing they could do safely here"


def _edited_lines(repair: Repair, lines: XmlText) -> set[int]:
    out: set[int] = set()
    spans = [(e.start, e.end) for e in repair.edits]
    if repair.scope is not None:
        spans.append(repair.scope)
    for start, end in spans:
        out.update(range(lines.line_of(start), lines.line_of(max(start, end - 1)) + 1))
    return out


def _on_their_lines(group: Sequence[Repair], verdict: Verdict, lines: XmlText) -> list[Repair]:
    """The repairs of ``group`` a new finding lies on: on a line they edit or in their scope."""
    found = {line for line in verdict.new_lines if line is not None}
    return [r for r in group if _edited_lines(r, lines) & found]


def _on_their_roads(group: Sequence[Repair], verdict: Verdict) -> list[Repair]:
    """The repairs of ``group`` whose findings name a road a new finding names."""
    roads = {f.road for f in verdict.new if f.road is not None}
    return [r for r in group if roads & {f.road for f in r.findings}]


def _on(verdict: Verdict, repair: Repair, lines: XmlText) -> list[Finding]:
    """The new findings on the lines ``repair`` edits or has in its scope."""
    mine = _edited_lines(repair, lines)
    return [f for f, line in zip(verdict.new, verdict.new_lines) if line in mine]


def _disjoint(repairs: list[Repair]) -> list[Repair]:
    """The repairs whose edits overlap no earlier repair's (the others wait for the next round)."""
    taken: list[Edit] = []
    out = []
    for r in repairs:
        if any(overlaps(e, t) for e in r.edits for t in taken):
            continue
        if any(overlaps(a, b) for i, a in enumerate(r.edits) for b in r.edits[i + 1 :]):
            continue
        taken.extend(r.edits)
        out.append(r)
    return out


def _why(unresolved: Sequence[Repair], new: Sequence[Finding]) -> str:
    if new:
        f = new[0]
        more = f" and {len(new) - 1} more" if len(new) > 1 else ""
        return f"it brought a new finding: {f.code} {f.name}: {f.message}{more}"
    return "its finding remained after the edit"
