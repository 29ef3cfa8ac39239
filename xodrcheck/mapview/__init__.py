"""A map of an OpenDRIVE file in one self-contained HTML page: ``xodrcheck view`` and ``check --format html``.

:mod:`~xodrcheck.mapview.shapes` samples the lane geometry in plan view, :mod:`~xodrcheck.mapview.encode` packs it
compactly, :mod:`~xodrcheck.mapview.page` assembles the page from the package data in ``static/`` (the viewer is
plain canvas and hand-written JavaScript: nothing is fetched, nothing is vendored).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from xodrcheck.mapview.shapes import CHORD

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.model import Document


def map_data(document: Document, chord: float = CHORD) -> tuple[dict, str | None]:
    """The encoded map of a document and a note naming the roads it leaves out (``None`` when it draws them all)."""
    from xodrcheck.mapview.encode import encode
    from xodrcheck.mapview.routes import graph_data
    from xodrcheck.mapview.shapes import map_shapes

    shapes = map_shapes(document, chord=chord)
    note = None
    if shapes.skipped:
        shown = ", ".join(shapes.skipped[:10]) + (" ..." if len(shapes.skipped) > 10 else "")
        note = f"{len(shapes.skipped)} road(s) not drawn (geometry not evaluable or not finite): {shown}"
    data = encode(shapes)
    data["graph"] = graph_data(document, shapes.roads)  # routes between clicked lanes, unreachable lanes shaded
    return data, note


def file_map_data(source: str | Path, chord: float = CHORD) -> tuple[dict | None, str | None]:
    """:func:`map_data` of a file; a file that cannot be read gives ``(None, reason)`` (never raises for content)."""
    from xodrcheck.findings import ReadError
    from xodrcheck.reader import read

    try:
        document = read(source).document
    except ReadError as exc:
        return None, f"no map: {exc}"
    if document is None:
        return None, "no map: the file could not be read as OpenDRIVE"
    return map_data(document, chord)
