"""The HTML page: one self-contained file (styles and scripts inline, no request to any network) with, per file, the map
and the findings list, a summary on top and an index when there are several files.

The page's DOM contract (tools and tests rely on it): each finding is an element ``.xc-row`` with ``data-code``,
``data-severity``, ``data-category``, ``data-road``, ``data-lane``, ``data-section-s``, ``data-s``, ``data-x``,
``data-y``, ``data-line``, ``data-rule-uid``, ``data-basis`` and ``data-fixable`` (empty where the finding has no
such value; ``data-fixable`` is ``safe``, ``unsafe`` or ``safe+unsafe`` where ``xodrcheck fix`` has a fix for the
rule, and the row shows "fix"; any further field of :class:`~xodrcheck.findings.Finding` becomes a ``data-*``
attribute too); each map is an element ``.xc-map`` whose ``data-center-x``/``data-center-y`` give the world
coordinates of its view centre, updated on every pan and zoom, and ``data-ready="true"`` once it has been drawn. The
verdict of a report is an element ``.xc-verdict`` with ``data-verdict`` PASS, FAIL or INCOMPLETE (one on top for the
whole report, one per file).

Info markers are off on the map by default (a CARLA town has over a thousand: they hid the errors): the map's
``info markers`` box (``[data-tool=info-markers]``) draws them; the list shows infos unless their severity box is
unticked, and an info chosen in the list is drawn on the map either way.
"""

from __future__ import annotations

import json
import math
import re
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, fields
from functools import cache
from html import escape
from importlib import resources

from xodrcheck.findings import Finding, Severity
from xodrcheck.report import tool_version

#: Script files, in the order they run (one inline script).
SCRIPTS = ("decode.js", "map.js", "render.js", "route.js", "report.js")
_SEVERITIES = (Severity.ERROR, Severity.WARNING, Severity.INFO)
_KNOWN = (
    *("code", "name", "category", "severity", "message", "road", "lane", "section_s", "s", "x", "y", "z", "line"),
    *("rule_uid", "basis"),
)


@dataclass(frozen=True)
class FilePage:
    """What the page shows of one file. ``findings`` ``None``: a map alone (``xodrcheck view``)."""

    path: str | None
    version: str | None
    findings: tuple[Finding, ...] | None
    map_data: dict | None
    #: Why there is no map, or what it leaves out.
    note: str | None = None
    #: The file's verdict line (:func:`xodrcheck.report.verdict.verdict`); ``None`` for a map alone.
    verdict: str | None = None


def asset(name: str) -> str:
    """A file of ``xodrcheck/mapview/static`` (package data)."""
    return resources.files("xodrcheck.mapview").joinpath("static").joinpath(name).read_text(encoding="utf-8")


def json_script(value: object) -> str:
    """JSON safe inside ``<script>``: ``<``, ``>`` and ``&`` escaped, so no ``</script>`` can close it early."""
    text = json.dumps(value, separators=(",", ":"), allow_nan=False, ensure_ascii=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def _attr(value: object) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return ""
    return escape(str(value), quote=True)


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 or word == "info" else f"{n} {word}s"


def _counts(findings: Sequence[Finding]) -> str:
    by = Counter(f.severity for f in findings)
    chips = [f'<span class="xc-chip {sev}">{_plural(by[sev], str(sev))}</span>' for sev in _SEVERITIES if by[sev]]
    return "".join(chips) or '<span class="xc-chip ok">no findings</span>'


def _categories(findings: Sequence[Finding]) -> str:
    by = Counter(str(f.category) for f in findings)
    return "".join(f'<span class="xc-chip">{escape(c)} {n}</span>' for c, n in sorted(by.items()))


def _verdict(line: str | None, tag: str = "span") -> str:
    """The verdict line with its word as a coloured chip: ``FAIL`` and the reason."""
    if line is None:
        return ""
    word, _, why = line.partition(": ")
    return (
        f'<{tag} class="xc-verdict" data-verdict="{_attr(word)}"><span class="xc-chip {word.lower()}">{escape(word)}'
        f"</span> {escape(why)}</{tag}>"
    )


def _summary(files: Sequence[FilePage], title: str, verdict: str | None) -> str:
    parts = [f"<h1>{escape(title)}</h1>", f'<span class="xc-tool-version">xodrcheck {escape(tool_version())}</span>']
    parts.append(_verdict(verdict))
    checked = [f for f in files if f.findings is not None]
    if checked:
        every = [x for f in checked for x in f.findings or ()]
        parts.append(f"<span>{_plural(len(files), 'file')} · {_plural(len(every), 'finding')}</span>")
        parts.append(f'<span class="xc-counts">{_counts(every)}</span>')
        parts.append(f'<span class="xc-counts">{_categories(every)}</span>')
    return "\n".join(parts)


def _index(files: Sequence[FilePage]) -> str:
    if len(files) < 2:
        return ""
    rows = []
    for k, f in enumerate(files):
        by = Counter(x.severity for x in f.findings or ())
        cells = "".join(f'<td class="n">{by[sev]}</td>' for sev in _SEVERITIES)
        word = (f.verdict or "").partition(":")[0]
        chip = f'<span class="xc-chip {word.lower()}">{escape(word)}</span>' if word else ""
        rows.append(
            f'<tr><td>{chip}</td><td><a href="#file-{k}">{escape(f.path or "(bytes)")}</a></td>'
            f"<td>{escape(f.version or '?')}</td>{cells}</tr>"
        )
    head = "".join(f"<th>{sev}</th>" for sev in ("errors", "warnings", "info"))
    return (
        '<nav class="xc-index" id="xc-index" aria-label="files"><table>'
        f"<thead><tr><th>verdict</th><th>file</th><th>OpenDRIVE</th>{head}</tr></thead><tbody>{''.join(rows)}</tbody>"
        "</table></nav>"
    )


def _where(f: Finding, extra: dict[str, object]) -> str:
    parts = []
    if f.road is not None:
        parts.append(f"road {f.road}")
    if f.lane is not None:
        parts.append(f"lane {f.lane}")
    if f.s is not None and math.isfinite(f.s):
        parts.append(f"s {f.s:.2f}")
    if f.x is not None and f.y is not None and math.isfinite(f.x) and math.isfinite(f.y):
        z = getattr(f, "z", None)
        height = f", z {z:.2f}" if z is not None and math.isfinite(z) and abs(z) >= 0.005 else ""
        parts.append(f"x {f.x:.2f}, y {f.y:.2f}{height}")
    else:
        parts.append("no map position")
    if f.line:
        parts.append(f"line {f.line}")
    parts += [f"{k.replace('_', ' ')} {v}" for k, v in extra.items()]
    return escape(" · ".join(parts))


def _extra(f: Finding) -> dict[str, object]:
    """Fields of the finding beyond the ones the page knows (added to Finding later), where set."""
    kind: type = type(f)  # the cache key (typed plainly: mypy takes a frozen dataclass class for unhashable)
    values = ((k, getattr(f, k)) for k in _extra_fields(kind))
    return {k: str(v) for k, v in values if v is not None and v != ""}


@cache
def _extra_fields(kind: type) -> tuple[str, ...]:
    return tuple(field.name for field in fields(kind) if field.name not in _KNOWN)


@cache
def _fixable(code: str) -> str | None:
    """``safe``, ``unsafe`` or ``safe+unsafe`` when ``xodrcheck fix`` has fixes of that kind for the rule."""
    from xodrcheck.fix.registry import fixable

    return fixable(code)


def _row(i: int, f: Finding) -> str:
    attrs = {
        "index": i,
        "code": f.code,
        "severity": str(f.severity),
        "category": str(f.category),
        "road": f.road,
        "lane": f.lane,
        "section-s": f.section_s,
        "s": f.s,
        "x": f.x if f.y is not None else None,
        "y": f.y if f.x is not None else None,
        "line": f.line or None,
        "z": getattr(f, "z", None),
        "rule-uid": f.rule_uid,
        "basis": f.basis,
    }
    extra = _extra(f)
    attrs.update({re.sub(r"[^a-z0-9]+", "-", k.lower()): v for k, v in extra.items()})
    fix = _fixable(f.code)
    attrs["fixable"] = fix
    data = " ".join(f'data-{k}="{_attr(v)}"' for k, v in attrs.items())
    mark = (
        f' <span class="xc-fix" title="xodrcheck fix has a {fix} fix for this rule">fix</span>'
        if fix is not None
        else ""
    )
    return (
        f'<li class="xc-row" tabindex="0" {data}>'
        f'<span class="xc-code">{escape(f.code)}</span> <span class="xc-name">{escape(f.name)}</span>{mark}'
        f'<button class="xc-doc" type="button" data-code="{_attr(f.code)}" title="rule documentation">?</button>'
        f"{_basis_tag(f.basis)}"
        f'<div class="xc-msg">{escape(f.message)}</div><div class="xc-where">{_where(f, extra)}</div></li>'
    )


def _basis_tag(text: str) -> str:
    """The basis as a small tag: an Annex F UID by its rule name (the whole UID in the tooltip), else its word."""
    uid = text.count(":") == 3
    short = text.rsplit(":", 1)[-1] if uid else text
    kind = "annex-f" if uid else text
    title = f"Annex F rule {text}" if uid else _BASIS_WORDS.get(text, text)
    return f'<span class="xc-basis {_attr(kind)}" title="{_attr(title)}">{escape(short)}</span>'


#: What a basis that is not an Annex F UID means, for the tag's tooltip.
_BASIS_WORDS = {
    "schema": "the XSD of the file's OpenDRIVE version",
    "reading": "the file cannot be read as OpenDRIVE as written",
    "plausibility": "the checker's own judgement: the standard does not state it",
    "incomplete": "the check did not run to its end",
}


def _filters(findings: Sequence[Finding]) -> str:
    by = Counter(f.severity for f in findings)
    boxes = "".join(
        f'<label><input type="checkbox" data-filter="severity" value="{sev}" checked> {sev} ({by[sev]})</label>'
        for sev in _SEVERITIES
    )
    categories = sorted({str(f.category) for f in findings})
    codes = sorted({f.code for f in findings})
    cat = "".join(f'<option value="{escape(c)}">{escape(c)}</option>' for c in categories)
    code = "".join(f'<option value="{escape(c)}">{escape(c)}</option>' for c in codes)
    return (
        f'<div class="xc-filters">{boxes}'
        f'<select data-filter="category" aria-label="category"><option value="">all categories</option>{cat}</select>'
        f'<select data-filter="code" aria-label="code"><option value="">all codes</option>{code}</select>'
        f'<input type="search" data-filter="road" placeholder="road id(s)" aria-label="road">'
        f'<span class="xc-status"><span class="xc-shown">{len(findings)}</span> of {len(findings)} shown</span></div>'
    )


def _map(f: FilePage) -> str:
    label = escape(f"map of {f.path or 'the file'}", quote=True)
    if f.map_data is None or f.map_data.get("bounds") is None:
        note = escape(f.note or "nothing to draw: no road with a plan view and lanes")
        return f'<div class="xc-map xc-nomap"><div class="xc-empty">{note}</div></div>'
    return (
        f'<div class="xc-map" data-center-x="" data-center-y=""><canvas tabindex="0" aria-label="{label}"></canvas>'
        '<div class="xc-tools"><button type="button" data-tool="zoom-in" title="zoom in">+</button>'
        '<button type="button" data-tool="zoom-out" title="zoom out">&minus;</button>'
        '<button type="button" data-tool="fit" title="whole map">fit</button>'
        '<label><input type="checkbox" data-tool="reference"> reference lines</label>'
        f"{_info_box(f.findings or ())}</div>"
        '<div class="xc-legend"></div><div class="xc-tip" hidden></div>'
        f'<script type="application/json" class="xc-map-data">{json_script(f.map_data)}</script></div>'
    )


def _info_box(findings: Sequence[Finding]) -> str:
    """The box that draws the info markers, off by default; none when no info has a place on the map."""
    placed = sum(1 for x in findings if x.severity is Severity.INFO and x.x is not None and x.y is not None)
    if not placed:
        return ""
    title = "info markers are off by default so that errors and warnings stand out; the list shows every info"
    return f'<label title="{title}"><input type="checkbox" data-tool="info-markers"> info markers ({placed})</label>'


def _file_section(k: int, f: FilePage, indexed: bool = False) -> str:
    """One file's heading, map and list; its verdict where there are several (one file's is the page's)."""
    meta = [f"OpenDRIVE {escape(f.version or '?')}"]
    if f.findings is not None:
        meta = [_verdict(f.verdict), *meta] if f.verdict and indexed else meta
        meta += [part for part in (_counts(f.findings), _categories(f.findings)) if part]
    if f.note and f.map_data is not None:
        meta.append(f"<span>{escape(f.note)}</span>")
    back = ' <a class="xc-back" href="#xc-index" title="back to the list of files">↑ files</a>' if indexed else ""
    panel = ""
    if f.findings is not None:
        ordered = sorted(f.findings, key=lambda x: -x.severity)  # worst first, file order within a severity
        rows = "".join(_row(i, x) for i, x in enumerate(ordered))
        body = (
            f'{_filters(f.findings)}<ol class="xc-rows">{rows}</ol>' if rows else '<p class="xc-none">No findings.</p>'
        )
        panel = f'<div class="xc-findings">{body}</div>'
    return (
        f'<section class="xc-file" id="file-{k}"><h2>{escape(f.path or "(bytes)")}{back}</h2>'
        f'<div class="xc-file-meta">{" · ".join(meta)}</div><div class="xc-body">{_map(f)}{panel}</div></section>'
    )


def _docs(files: Sequence[FilePage]) -> dict[str, dict[str, str]]:
    """The documentation of every rule with a finding on the page, rendered as HTML, with what its findings rest
    on."""
    from xodrcheck.report import rule_bases
    from xodrcheck.rules import load_rules
    from xodrcheck.rules.shared.docformat import html

    rules = load_rules()
    found: dict[str, list[Finding]] = {}
    for x in (x for f in files for x in f.findings or ()):
        found.setdefault(x.code, []).append(x)
    return {
        c: {
            "name": r.name,
            "category": str(r.category),
            "severity": str(r.severity),
            "basis": ", ".join(rule_bases(r, found[c])),
            "html": html(r.doc),
        }
        for c in sorted(found)
        if (r := rules.get(c)) is not None
    }


def render_page(files: Sequence[FilePage], title: str, verdict: str | None = None) -> str:
    """The whole page (see the module docstring); ``verdict`` is the report's verdict line, shown on top."""
    script = "\n".join(asset(name) for name in SCRIPTS)
    parts = {
        "version": escape(tool_version()),
        "title": escape(title),
        "css": asset("style.css"),
        "summary": _summary(files, title, verdict),
        "index": _index(files),
        "files": "\n".join(_file_section(k, f, len(files) > 1) for k, f in enumerate(files)),
        "docs": json_script(_docs(files)),
        "script": f'(function () {{\n"use strict";\n{script}\n}}());',
    }
    page = re.sub(r"@(\w+)@", lambda m: parts[m.group(1)], asset("page.html"))
    if all(f.findings is None for f in files):
        page = page.replace("<body>", '<body class="xc-viewer">', 1)
    return page
