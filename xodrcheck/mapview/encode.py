"""Map shapes as compact JSON for the page (decoded by ``static/map.js``, function ``decodeMap``).

Coordinates become integer centimetres from the map's ``origin`` (the south-west corner of its bounds, in whole
metres), ``s`` integer centimetres from the section start. Each section adds to one integer stream:

* its ``n`` sample ``s``, each as the difference from the previous one;
* for each line (reference line first, see :mod:`xodrcheck.mapview.shapes`), its ``n`` x then its ``n`` y, each the
  difference from the previous line's point at the same sample (the reference line: from the origin) and then from
  the previous sample: lane borders run beside each other, so most of these second differences are small.

The stream is written as zigzag varints (7 bits a byte, low group first) and base64. Section records are arrays:
``[road, index, s0, n, left, right, marks]`` with ``left``/``right`` flat ``[lane id, lane type index, ...]`` inner
to outer and ``marks`` flat ``[line, first sample, last sample, mark type index, colour index, width cm, ...]``.
"""

from __future__ import annotations

import base64

import numpy as np

from xodrcheck.mapview.shapes import MapShapes, SectionShape


def zigzag_varints(values: np.ndarray) -> bytes:
    """Signed integers as zigzag varints (0, -1, 1, -2 ... -> 0, 1, 2, 3 ...), vectorised."""
    v = np.asarray(values, dtype=np.int64)
    z = ((v << 1) ^ (v >> 63)).astype(np.uint64)
    sizes = np.ones(len(z), dtype=np.int64)
    limit = np.uint64(128)
    for k in range(1, 10):
        sizes += z >= limit ** np.uint64(k)
    ends = np.cumsum(sizes)
    starts = ends - sizes
    out = np.empty(int(ends[-1]) if len(z) else 0, dtype=np.uint8)
    for k in range(int(sizes.max()) if len(z) else 0):
        has = sizes > k
        group = (z[has] >> np.uint64(7 * k)) & np.uint64(127)
        more = np.where(sizes[has] > k + 1, 128, 0).astype(np.uint64)
        out[starts[has] + k] = (group | more).astype(np.uint8)
    return out.tobytes()


def _section_stream(sec: SectionShape, origin: np.ndarray) -> np.ndarray:
    s = np.rint((sec.s - sec.s0) * 100.0).astype(np.int64)
    s[1:] = np.diff(s)
    q = np.rint((sec.lines - origin) * 100.0).astype(np.int64)  # (lines, n, 2)
    across = q.copy()
    across[1:] -= q[:-1]
    along = across.copy()
    along[:, 1:] -= across[:, :-1]
    return np.concatenate([s, along.transpose(0, 2, 1).ravel()])


class _Table:
    """Strings as indices into a list (lane types, mark types, colours)."""

    def __init__(self) -> None:
        self.items: list[str] = []
        self._index: dict[str, int] = {}

    def __call__(self, item: str) -> int:
        found = self._index.get(item)
        if found is None:
            found = self._index[item] = len(self.items)
            self.items.append(item)
        return found


def encode(shapes: MapShapes) -> dict:
    """The JSON-ready description of a map (see the module docstring); ``bounds`` ``None`` for a map with no shapes."""
    bounds = shapes.bounds()
    origin = np.floor(np.array(bounds[:2])) if bounds else np.zeros(2)
    lane_types, mark_types, colors = _Table(), _Table(), _Table()
    records = []
    streams = []
    for sec in shapes.sections:
        marks: list[int] = []
        for m in sec.marks:
            width = round(m.width * 100) if 0 < m.width < 10 else 0
            marks += [m.line, m.start, m.stop, mark_types(m.type), colors(m.color), width]
        records.append(
            [
                sec.road,
                sec.index,
                sec.s0,
                len(sec.s),
                [v for lane_id, kind in sec.left for v in (lane_id, lane_types(kind))],
                [v for lane_id, kind in sec.right for v in (lane_id, lane_types(kind))],
                marks,
            ]
        )
        streams.append(_section_stream(sec, origin))
    stream = np.concatenate(streams) if streams else np.zeros(0, dtype=np.int64)
    return {
        "origin": [float(origin[0]), float(origin[1])],
        "bounds": list(bounds) if bounds else None,
        "roads": [list(road) for road in shapes.roads],
        "laneTypes": lane_types.items,
        "markTypes": mark_types.items,
        "markColors": colors.items,
        "sections": records,
        "stream": base64.b64encode(zigzag_varints(stream)).decode("ascii"),
        "skipped": list(shapes.skipped),
    }
