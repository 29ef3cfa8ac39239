"""Where the builder is, what it found, attribute parsing, and the XML facts of each element.

Two ways of reading an attribute:

* reporting (:meth:`Context.number`, :meth:`~Context.integer`, :meth:`~Context.choice`...): for the values the
  geometry and topology depend on. Each returns ``None`` for a value that is missing or invalid, after recording a
  finding that names the element, its line, the attribute, the raw value and what the builder does about it
  (``then``). The fast paths convert a whole element's attributes in one go and fall back to the attribute-by-attribute
  path only when something is wrong;
* as given (:meth:`Context.opt_number`, :meth:`~Context.opt_integer`, :meth:`~Context.opt_enum`...): for the other
  records (objects, signals, road types, junction parts...), whose bad values the schema rule reports: ``None`` for a
  value that is absent or invalid, without a finding.

Either way an invalid value's text is kept for the element's :class:`~xodrcheck.model.facts.XmlFacts`, which
:meth:`Context.facts` builds (and shares between elements that say the same).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from itertools import pairwise
from typing import TypeVar

from lxml import etree

from xodrcheck import model
from xodrcheck.findings import Finding, Severity
from xodrcheck.model import NO_FACTS, Cubic, ElementDir, Profile, UnknownElement, XmlFacts
from xodrcheck.rules import xml as R
from xodrcheck.rules.registry import NO_UID, Rule
from xodrcheck.support.quantities import metres

T = TypeVar("T")

_SHOW = 40  # characters of a raw value shown in a message
_BOOLEANS = {"true": True, "false": False, "1": True, "0": False}
#: ``+`` and ``-`` of an ``elementDir`` (or a switch track's ``dir``) as the file spells them.
ELEMENT_DIRS = {"+": ElementDir.PLUS, "-": ElementDir.MINUS}
#: The standard's additional data (6.2), allowed in nearly every element: not unknown where the reader skips it.
ADDITIONAL_DATA = frozenset({"userData", "include", "dataQuality"})
#: Children a record without child elements of its own may have.
LEAF: frozenset[str] = frozenset()
#: Element nodes only (an entity reference a recovering parse kept is not a child element).
_ELEMENTS = etree.Element

SKIP_RECORD = "the record is skipped"


#: libxml2 keeps an element's line in 16 bits. Past this it knows the line only from a neighbouring text node (so
#: approximately: often the next line), and an element without one (a compact file) reads 65535.
SATURATED_LINE = 65535


def _anchor(el: etree._Element) -> etree._Element | None:
    """The nearest ancestor whose line is known and past :data:`SATURATED_LINE` (``None`` if there is none)."""
    parent = el.getparent()
    while parent is not None:
        line = parent.sourceline
        if line != SATURATED_LINE:
            return parent if line is not None and line > SATURATED_LINE else None
        parent = parent.getparent()
    return None


def line_of(el: etree._Element) -> int | None:
    """The element's line, or for an element whose line libxml2 lost (see :data:`SATURATED_LINE`) its nearest
    ancestor's line past that, which is where to start looking."""
    line = el.sourceline
    if line == SATURATED_LINE:
        anchor = _anchor(el)
        if anchor is not None:
            return anchor.sourceline
    return line


def describe(el: etree._Element) -> str:
    """``<tag> at line N``; past line 65535, where libxml2 knows lines only roughly, ``<tag> at about line N`` or
    ``<tag> after about line N (in <parent>)``."""
    line = el.sourceline
    if line == SATURATED_LINE:
        anchor = _anchor(el)
        if anchor is not None:
            return f"<{el.tag}> after about line {anchor.sourceline} (in <{anchor.tag}>)"
    elif line is not None and line > SATURATED_LINE:
        return f"<{el.tag}> at about line {line}"
    return f"<{el.tag}> at line {line}"


#: How many distinct values :class:`Numbers` remembers: a CARLA town has a few thousand, a 50 MB map far more, and
#: past this the rarer values are parsed each time instead of kept (the cache is dropped with the read's context).
REMEMBER = 1 << 16


class Numbers(dict[str | None, float]):
    """Attribute text -> its value as a float, for the finite values met so far in the read. ``numbers[raw]`` is
    ``float(raw)``, but raises :class:`ValueError` for an infinity or a NaN as well (and :class:`TypeError` for
    ``None``, an absent attribute). Most numbers of a map repeat (80 % of them on the CARLA towns, most often
    "0.0000000000000000e+0") and a 17-digit float takes ~250 ns to parse, a look-up here a fraction of that."""

    __slots__ = ()

    def __missing__(self, raw: str | None) -> float:
        value = float(raw)  # type: ignore[arg-type]  # TypeError for None, as wanted
        if value - value != 0.0:
            raise ValueError(raw)
        if len(self) < REMEMBER:
            self[raw] = value
        return value


def _show(raw: str) -> str:
    return raw if len(raw) <= _SHOW else raw[:_SHOW] + "..."


class Context:
    """Findings collected while building the model, and the road / junction / lane section / lane being built."""

    __slots__ = ("_facts", "findings", "junction", "lane", "numbers", "pending", "road", "section_s", "version")

    def __init__(self, findings: list[Finding] | None = None) -> None:
        self.findings: list[Finding] = [] if findings is None else findings
        self.version: tuple[int, int] | None = None
        self.road: str | None = None
        self.junction: str | None = None
        self.section_s: float | None = None
        self.lane: int | None = None
        self.numbers = Numbers()
        #: (element, attribute, text) of each invalid value met and not yet in an element's facts.
        self.pending: list[tuple[etree._Element, str, str]] = []
        #: Facts by (attributes, children, known tags): shared between the elements that say the same.
        self._facts: dict[tuple[tuple[str, ...], tuple[str, ...], frozenset[str] | None], XmlFacts] = {}

    # ---------------------------------------------------------------------------------------------------- facts
    def facts(
        self,
        el: etree._Element,
        known: frozenset[str] | None = None,
        keys: tuple[str, ...] | None = None,
        children: tuple[str, ...] | None = None,
    ) -> XmlFacts:
        """The XML facts of ``el``: its attributes, its children's tags, the children not in ``known`` (the tags the
        builder reads there; ``None``: every child is known) and the invalid values met on it. ``keys`` and
        ``children`` spare a second look at the element when the caller has them already. Call it after reading the
        element's attributes."""
        if keys is None:
            keys = tuple(el.keys())
        if children is None:
            children = tuple([child.tag for child in el.iterchildren(_ELEMENTS)]) if len(el) else ()
        invalid = self._take_invalid(el) if self.pending else ()
        key = (keys, children, known)
        found = self._facts.get(key)
        if found is None:
            unknown = _unknown(el, children, known) if children and known is not None else ()
            if unknown or invalid:
                return XmlFacts(keys, children, unknown, invalid)
            found = self._facts[key] = XmlFacts(keys, children) if keys or children else NO_FACTS
        elif invalid:  # a kept entry has no unknown children (facts with some hold lines, and are never kept)
            return XmlFacts(keys, children, (), invalid)
        return found

    def _take_invalid(self, el: etree._Element) -> tuple[tuple[str, str], ...]:
        mine = tuple((name, text) for owner, name, text in self.pending if owner is el)
        if mine:
            self.pending = [entry for entry in self.pending if entry[0] is not el]
        return mine

    def note_invalid(self, el: etree._Element, name: str, raw: str) -> None:
        """Keep the text of an invalid value for ``el``'s facts (no finding)."""
        self.pending.append((el, name, raw))

    def forget_invalid(self) -> None:
        """Drop what was noted for elements whose records were skipped (called after each top-level element)."""
        self.pending.clear()

    # ---------------------------------------------------------------------------------------------------- findings
    def where(self) -> str:
        parts = []
        if self.road is not None:
            parts.append(f"road {self.road}")
        if self.junction is not None:
            parts.append(f"junction {self.junction}")
        if self.section_s is not None:
            parts.append(f"lane section s={metres(self.section_s)}")
        if self.lane is not None:
            parts.append(f"lane {self.lane}")
        return ", ".join(parts) + ": " if parts else ""

    def report(
        self,
        rule: Rule,
        message: str,
        el: etree._Element | None = None,
        severity: Severity | None = None,
        line: int | None = None,
        uid: str | None = None,
    ) -> None:
        """Record a finding of ``rule`` located at ``el`` (or ``line``) inside the current road / lane.

        ``uid`` is the Annex F rule the finding enforces. A reader rule reports many kinds of defect and declares the
        UIDs of only some, so a finding without ``uid`` names none (never the rule's only UID by default)."""
        self.findings.append(
            rule.finding(
                self.where() + message,
                severity=severity,
                uid=NO_UID if uid is None else uid,
                road=self.road,
                lane=self.lane,
                section_s=self.section_s,
                line=line if el is None else line_of(el),
            )
        )

    def missing(
        self, el: etree._Element, name: str, then: str, severity: Severity | None = None, uid: str | None = None
    ) -> None:
        self.report(R.MISSING_ATTRIBUTE, f"{describe(el)} has no '{name}' attribute; {then}", el, severity, uid=uid)

    def missing_child(self, el: etree._Element, tag: str, then: str, uid: str | None = None) -> None:
        """Report that ``el`` has no ``<tag>`` child, and what the reader does without it (``then``)."""
        self.report(R.MISSING_ELEMENT, f"{describe(el)} has no <{tag}>; {then}", el, uid=uid)

    def invalid(self, el: etree._Element, name: str, raw: str, why: str, then: str) -> None:
        self.note_invalid(el, name, raw)
        self.report(R.INVALID_ATTRIBUTE, f'{describe(el)} has {name}="{_show(raw)}", {why}; {then}', el)

    # ---------------------------------------------------------------------------------------------------- values
    def number(
        self,
        el: etree._Element,
        name: str,
        then: str,
        *,
        required: bool = True,
        nonneg: bool = False,
        uid: str | None = None,
    ) -> float | None:
        """A finite float (>= 0 with ``nonneg``), or ``None`` with a finding (none for an absent optional one);
        ``uid`` names the Annex F rule an absent required attribute breaks."""
        raw = el.get(name)
        if raw is None:
            if required:
                self.missing(el, name, then, uid=uid)
            return None
        try:
            value = self.numbers[raw]  # finite, and remembered for the next record with the same text
        except ValueError:
            try:
                float(raw)
            except ValueError:
                self.invalid(el, name, raw, "which is not a number", then)
            else:
                self.invalid(el, name, raw, "which is not a finite number", then)
            return None
        if nonneg and value < 0.0:
            self.invalid(el, name, raw, f"but {name} must be >= 0", then)
            return None
        return value

    def floats(
        self, el: etree._Element, names: list[str], nonneg: Sequence[int], then: str
    ) -> tuple[float, ...] | None:
        """All of ``names`` as finite floats (those at indices ``nonneg`` >= 0), or ``None`` with findings."""
        try:
            if el.keys() == names:  # exactly these attributes, in this order (the usual case): all in one call
                values = tuple(map(self.numbers.__getitem__, el.values()))
            else:
                values = tuple(map(self.numbers.__getitem__, map(el.get, names)))
        except (TypeError, ValueError):
            return self.floats_slowly(el, names, nonneg, then)
        for i in nonneg:
            if values[i] < 0.0:
                return self.floats_slowly(el, names, nonneg, then)
        return values

    def floats_slowly(
        self, el: etree._Element, names: Sequence[str], nonneg: Sequence[int], then: str
    ) -> tuple[float, ...] | None:
        """:meth:`floats` attribute by attribute, reporting every missing or invalid one."""
        absent = [name for name in names if el.get(name) is None]
        if len(absent) > 1:
            listed = ", ".join(f"'{name}'" for name in absent)
            self.report(R.MISSING_ATTRIBUTE, f"{describe(el)} lacks the required attributes {listed}; {then}", el)
        elif absent:
            self.missing(el, absent[0], then)
        values = [
            self.number(el, name, then, nonneg=i in nonneg) if name not in absent else None
            for i, name in enumerate(names)
        ]
        found = tuple(v for v in values if v is not None)
        return found if len(found) == len(values) else None

    def integer(self, el: etree._Element, name: str, then: str, *, required: bool = True) -> int | None:
        raw = el.get(name)
        if raw is None:
            if required:
                self.missing(el, name, then)
            return None
        try:
            return int(raw)
        except ValueError:
            self.invalid(el, name, raw, "which is not an integer", then)
            return None

    def choice(self, el: etree._Element, name: str, values: Mapping[str, T], then: str) -> T | None:
        """An optional enumerated value, matched without regard to case; ``None`` when absent or unknown."""
        raw = el.get(name)
        if raw is None:
            return None
        value = values.get(raw.strip().lower())
        if value is None:
            allowed = ", ".join(sorted({str(getattr(v, "value", v)) for v in values.values()}))
            self.invalid(el, name, raw, f"which is not one of {allowed}", then)
        return value

    def boolean(self, el: etree._Element, name: str, then: str) -> bool | None:
        """An optional ``true``/``false`` (or ``1``/``0``); ``None`` when absent or invalid."""
        raw = el.get(name)
        if raw is None:
            return None
        value = _BOOLEANS.get(raw.strip().lower())
        if value is None:
            self.invalid(el, name, raw, "which is not true or false", then)
        return value

    # ---------------------------------------------------------------------------------------------------- as given
    def opt_number(self, el: etree._Element, name: str) -> float | None:
        """A finite float, or ``None`` (absent or invalid: the text is noted for the facts), without a finding."""
        raw = el.get(name)
        if raw is None:
            return None
        try:
            return self.numbers[raw]
        except ValueError:
            self.note_invalid(el, name, raw)
            return None

    def opt_integer(self, el: etree._Element, name: str) -> int | None:
        """An integer, or ``None`` (absent or invalid, noted), without a finding."""
        raw = el.get(name)
        if raw is None:
            return None
        try:
            return int(raw)
        except ValueError:
            self.note_invalid(el, name, raw)
            return None

    def opt_boolean(self, el: etree._Element, name: str) -> bool | None:
        """``true``/``false`` (or ``1``/``0``), or ``None`` (absent or invalid, noted), without a finding."""
        raw = el.get(name)
        if raw is None:
            return None
        value = _BOOLEANS.get(raw.strip())
        if value is None:
            self.note_invalid(el, name, raw)
        return value

    def opt_enum(self, el: etree._Element, name: str, values: Mapping[str, T]) -> T | None:
        """An enumerated value spelt as the standard spells it, or ``None`` (absent or invalid, noted)."""
        raw = el.get(name)
        if raw is None:
            return None
        value = values.get(raw)
        if value is None:
            self.note_invalid(el, name, raw)
        return value

    # ---------------------------------------------------------------------------------------------------- structure
    def repeated(self, el: etree._Element, first: etree._Element, uid: str | None = None) -> None:
        self.report(
            R.REPEATED_ELEMENT,
            f"{describe(el)} repeats the {describe(first)}, which may appear only once; only the first is read",
            el,
            uid=uid,
        )

    def check_order(self, records: Sequence, what: str, parent: etree._Element, uid: str | None = None) -> None:
        """Report the first record whose ``s`` is smaller than its predecessor's."""
        for prev, rec in pairwise(records):
            if rec.s < prev.s:
                self.report(
                    R.OUT_OF_ORDER,
                    f"{what} at line {rec.line} starts at {metres(rec.s)}, before the one at line {prev.line} "
                    f"({metres(prev.s)}); the standard wants them in ascending order of s (in {describe(parent)}); "
                    "they are kept in file order",
                    line=rec.line,
                    uid=uid,
                )
                return


def _unknown(el: etree._Element, tags: tuple[str, ...], known: frozenset[str]) -> tuple[UnknownElement, ...]:
    if all(tag in known or tag in ADDITIONAL_DATA for tag in tags):
        return ()
    return tuple(
        UnknownElement(child.tag, child.sourceline or 0)
        for child in el.iterchildren(_ELEMENTS)
        if child.tag not in known and child.tag not in ADDITIONAL_DATA
    )


_CUBIC = ["s", "a", "b", "c", "d"]
_OFFSET_CUBIC = ["sOffset", "a", "b", "c", "d"]
_FIRST = (0,)
#: The facts of a record with exactly the usual attributes in the usual order and no children (most of them).
_USUAL = {False: XmlFacts(tuple(_CUBIC)), True: XmlFacts(tuple(_OFFSET_CUBIC))}


def cubic(ctx: Context, el: etree._Element, offset: bool = False) -> Cubic | None:
    """One ``s a b c d`` record (``sOffset a b c d`` with ``offset``), or ``None`` with findings."""
    numbers = ctx.numbers
    try:
        if el.keys() == (_OFFSET_CUBIC if offset else _CUBIC):  # the usual attributes in the usual order
            s, a, b, c, d = el.values()
            usual = not len(el)  # and no children: the facts most records share
        else:
            get = el.get
            s, a, b, c, d = get("sOffset" if offset else "s"), get("a"), get("b"), get("c"), get("d")
            usual = False
        s = numbers[s]
        a = numbers[a]
        b = numbers[b]
        c = numbers[c]
        d = numbers[d]
    except (TypeError, ValueError):
        pass
    else:
        if s >= 0.0:
            return model.Cubic(s, a, b, c, d, el.sourceline, _USUAL[offset] if usual else ctx.facts(el, LEAF))
    v = ctx.floats_slowly(el, _OFFSET_CUBIC if offset else _CUBIC, _FIRST, SKIP_RECORD)
    return None if v is None else model.Cubic(v[0], v[1], v[2], v[3], v[4], el.sourceline, ctx.facts(el, LEAF))


def cubics(ctx: Context, parent: etree._Element, tag: str, uid: str | None = None) -> Profile:
    """The ``<tag s a b c d>`` records under ``parent``, checked for order (``uid``: the Annex F rule on the order)."""
    out = []
    for rec in parent:
        if rec.tag == tag:
            record = cubic(ctx, rec)
            if record is not None:
                out.append(record)
    if len(out) > 1:
        ctx.check_order(out, f"<{tag}>", parent, uid)
    return tuple(out)
