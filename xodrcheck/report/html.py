"""HTML: one self-contained page with, per file, a map of the lanes and a marker for each finding at its x, y, a list
that filters by severity, category, code and road, the verdict (PASS or FAIL and why) of the report and of each file,
each finding's basis, and the documentation of every rule that occurs, rendered
(:mod:`xodrcheck.mapview.page` describes the page and its DOM contract).

Each file is read again to draw its map (a report knows its findings, not its geometry).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from xodrcheck.mapview import file_map_data
from xodrcheck.mapview.page import FilePage, render_page
from xodrcheck.report.verdict import verdict


def _file(report) -> FilePage:
    data, note = (None, "no map: the file was given as bytes") if report.path is None else file_map_data(report.path)
    return FilePage(report.path, report.version, tuple(report.findings), data, note, verdict([report]))


def render(reports: Sequence) -> str:
    title = "xodrcheck report" if len(reports) != 1 else f"xodrcheck: {Path(reports[0].path or 'report').name}"
    return render_page([_file(r) for r in reports], title, verdict(reports))
