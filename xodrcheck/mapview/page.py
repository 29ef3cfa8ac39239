"""The HTML page: one self-contained file (styles and scripts inline, no request to any network) with, per file, the map
and the findings list, a summary on top and an index when there are several files.

The page's DOM contract (tools and tests rely on it): each finding is an element ``.xc-row`` with ``data-code``,
``data-severity``, ``data-category``, ``data-road``, ``data-lane``, ``data-section-s``, ``data-s``, ``data-x``,
``data-y`` and ``data-line`` (empty where the finding has no such value; any further field of
:class:`~xodrcheck.findings.Finding` becomes a ``data-*`` attribute too); each map is an element ``.xc-map`` whose
``data-center-x``/``data-center-y`` give the world coordinates of its view centre, updated on every pan and zoom, and
``data-ready="true"`` once it has been drawn.
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

#: Script files, in the order they run (one inline script).
SCRIPTS = ("decode.js", "map.js", "render.js", "report.js")
_SEVERITIES = (Severity.ERROR, Severity.WARNING, Severity.INFO)
_KNOWN = ("code", "name", "category", "severity", "message", "road", "lane", "section_s", "s", "x", "y", "z", "line")


@dataclass(frozen=True)
class FilePage:
    """What the page shows of one file. ``findings`` ``None``: a map alone (``xodrcheck view``)."""

    path: str | None
    version: str | None
    findings: tuple[Finding, ...] | None
    map_data: dict | None
    #: Why there is no map, or what it leaves out.
    note: str | None = None


def tool_version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("junctionart")
    except PackageNotFoundError:
        return "unknown"


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


def _summary(files: Sequence[FilePage], title: str) -> str:
    parts = [f"<h1>{escape(title)}</h1>", f'<span class="xc-tool-version">xodrcheck {escape(tool_version())}</span>']
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
        rows.append(
            f'<tr><td><a href="#file-{k}">{escape(f.path or "(bytes)")}</a></td><td>{escape(f.version or "?")}</td>'
            f"{cells}</tr>"
        )
    head = "".join(f"<th>{sev}</th>" for sev in ("errors", "warnings", "info"))
    return (
        '<nav class="xc-index" id="xc-index" aria-label="files"><table>'
        f"<thead><tr><th>file</th><th>OpenDRIVE</th>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table></nav>"
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
    values = ((k, getattr(f, k)) for k in _extra_fields())
    return {k: str(v) for k, v in values if v is not None and v != ""}


@cache
def _extra_fields() -> tuple[str, ...]:
    return tuple(field.name for field in fields(Finding) if field.name not in _KNOWN)


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
    }
    extra = _extra(f)
    attrs.update({re.sub(r"[^a-z0-9]+", "-", k.lower()): v for k, v in extra.items()})
    data = " ".join(f'data-{k}="{_attr(v)}"' for k, v in attrs.items())
    return (
        f'<li class="xc-row" tabindex="0" {data}>'
        f'<span class="xc-code">{escape(f.code)}</span> <span class="xc-name">{escape(f.name)}</span>'
        f'<button class="xc-doc" type="button" data-code="{_attr(f.code)}" title="rule documentation">?</button>'
        f'<div class="xc-msg">{escape(f.message)}</div><div class="xc-where">{_where(f, extra)}</div></li>'
    )


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
        '<label><input type="checkbox" data-tool="reference"> reference lines</label></div>'
        '<div class="xc-legend"></div><div class="xc-tip" hidden></div>'
        f'<script type="application/json" class="xc-map-data">{json_script(f.map_data)}</script></div>'
    )


def _file_section(k: int, f: FilePage, indexed: bool = False) -> str:
    meta = [f"OpenDRIVE {escape(f.version or '?')}"]
    if f.findings is not None:
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
    """The documentation of every rule with a finding on the page."""
    from xodrcheck.rules import load_rules

    rules = load_rules()
    codes = sorted({x.code for f in files for x in f.findings or ()})
    return {
        c: {"name": r.name, "category": str(r.category), "severity": str(r.severity), "doc": r.doc}
        for c in codes
        if (r := rules.get(c)) is not None
    }


def render_page(files: Sequence[FilePage], title: str) -> str:
    """The whole page (see the module docstring)."""
    script = "\n".join(asset(name) for name in SCRIPTS)
    parts = {
        "version": escape(tool_version()),
        "title": escape(title),
        "css": asset("style.css"),
        "summary": _summary(files, title),
        "index": _index(files),
        "files": "\n".join(_file_section(k, f, len(files) > 1) for k, f in enumerate(files)),
        "docs": json_script(_docs(files)),
        "script": f'(function () {{\n"use strict";\n{script}\n}}());',
    }
    page = re.sub(r"@(\w+)@", lambda m: parts[m.group(1)], asset("page.html"))
    if all(f.findings is None for f in files):
        page = page.replace("<body>", '<body class="xc-viewer">', 1)
    return page
