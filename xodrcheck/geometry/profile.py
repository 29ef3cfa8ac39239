"""Piecewise cubic profiles (lane width and border, laneOffset, elevation, superelevation), vectorised over ``s``.

At ``s`` the record in force is the last one whose start is at or before ``s`` (for equal starts, the later one in
the file), and the value is ``a + b ds + c ds^2 + d ds^3`` with ``ds = s - start``. The last record holds to the end
(the standard: "valid until the next element starts or the road reference line ends"; for lane records "until ... the
lane section ends").

Decisions
---------
* An empty profile is 0 everywhere: the standard's defaults are zero elevation, zero superelevation and no lane offset.
* Before the first record the value is also 0, not the first record extrapolated backwards: the standard gives every
  record a start and says what holds from there on, so before the first start no record is in force and the default
  (zero) applies. For lane widths this makes a lane whose first ``<width>`` starts at ``sOffset > 0`` zero-wide until
  then, which the lane rules can report, rather than inventing a width the file did not give.

``origin`` shifts every record start (lane records keep ``sOffset`` relative to their lane section: pass the section's
``s`` as ``origin`` and absolute ``s``).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import lru_cache

import numpy as np

from xodrcheck.geometry.pose import as_array
from xodrcheck.model import Cubic, Profile
from xodrcheck.support.arrays import ranges


class Piecewise:
    """A profile compiled for fast repeated evaluation (record starts shifted by ``origin``, sorted)."""

    __slots__ = ("_single", "coefficients", "starts")

    def __init__(self, profile: Profile, origin: float = 0.0):
        # Stable sort: equal starts keep file order.
        records = sorted(profile, key=lambda r: r.s) if len(profile) > 1 else profile
        self.starts = np.array([r.s + origin for r in records], dtype=float)
        self.coefficients = np.array([[r.a, r.b, r.c, r.d] for r in records], dtype=float).reshape(-1, 4)
        # One record (the common case): its start and coefficients as plain floats, for the fast path of jet().
        self._single: tuple[float, float, float, float, float] | None = None
        if len(records) == 1:
            a, b, c, d = map(float, self.coefficients[0])
            self._single = (float(self.starts[0]), a, b, c, d)

    def jet(self, s) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Value, first and second derivative at ``s``."""
        s = as_array(s)
        if self._single is not None:
            start, a0, b0, c0, d0 = self._single
            return _cubic_jet(a0, b0, c0, d0, s - start, None)
        if len(self.starts) == 0:
            return np.zeros_like(s), np.zeros_like(s), np.zeros_like(s)
        index = np.searchsorted(self.starts, s, side="right") - 1
        active = index >= 0
        index = np.maximum(index, 0)
        a, b, c, d = self.coefficients[index].T
        return _cubic_jet(a, b, c, d, s - self.starts[index], active)


#: Profiles with at most this many records find each point's record by counting the starts at or before it (cost:
#: records x points comparisons); longer ones search.
_COUNTED_RECORDS = 32
#: Fewer profiles of several records than this are searched one by one (counting pays for many at once).
_COUNT_TOGETHER = 8


class Table:
    """Profiles compiled for :class:`Laws`, one per row (``None``: no profile, zero): the single-record ones as rows
    of one coefficient array, the others kept as they are."""

    __slots__ = ("multi", "single", "single_rows")

    def __init__(self, laws: Sequence[Piecewise | None]):
        single = [(row, law._single) for row, law in enumerate(laws) if law is not None and law._single is not None]
        self.single_rows = np.array([row for row, _ in single], dtype=np.int64)
        #: start, a, b, c, d of each single-record profile
        self.single = np.array([record for _, record in single], dtype=float).reshape(-1, 5)
        self.multi = [(row, law) for row, law in enumerate(laws) if law is not None and len(law.starts) > 1]


class Laws:
    """Profiles evaluated together, with exactly :meth:`Piecewise.jet`'s arithmetic: row ``r`` of table ``t`` at
    samples ``s[sample:sample + n]`` written at ``dest + r * n``. The single-record profiles (the common case: one
    ``<width>`` per lane) are evaluated as one array computation, many with a few records likewise after finding each
    point's record by counting (what ``searchsorted`` finds, NaN and infinities included), the rest one by one."""

    __slots__ = ("_multi", "_single")

    def __init__(self) -> None:
        self._single: list[tuple[Table, int, int, int]] = []  # table, dest, sample, n
        self._multi: list[tuple[Piecewise, int, int, int]] = []  # law, dest, sample, n

    def add(self, table: Table, dest: int, sample: int, n: int) -> None:
        if len(table.single_rows):
            self._single.append((table, dest, sample, n))
        for row, law in table.multi:
            self._multi.append((law, dest + row * n, sample, n))

    def evaluate(self, s: np.ndarray, size: int) -> np.ndarray:
        """Value, first and second derivative, as the rows of a ``(3, size)`` array (zero where nothing was
        written)."""
        out = np.zeros((3, size))
        if self._single:
            self._singles(s, out)
        few = [m for m in self._multi if len(m[0].starts) <= _COUNTED_RECORDS and not np.isnan(m[0].starts).any()]
        together = len(few) >= _COUNT_TOGETHER
        if together:
            _counted(few, s, out)
        for law, dest, sample, n in self._multi:
            if not together or len(law.starts) > _COUNTED_RECORDS or np.isnan(law.starts).any():
                out[:, dest : dest + n] = law.jet(s[sample : sample + n])
        return out

    def _singles(self, s: np.ndarray, out: np.ndarray) -> None:
        entries = self._single
        _, _, sample, n = entries[0]
        if all(entry[2] == sample and entry[3] == n for entry in entries):  # one block of samples: rows of a 2-D array
            coef = np.concatenate([t.single for t, _, _, _ in entries]) if len(entries) > 1 else entries[0][0].single
            first = np.concatenate([dest + t.single_rows * n for t, dest, _, _ in entries])
            ds = s[sample : sample + n] - coef[:, :1]
            jet = _cubic_jet(coef[:, 1:2], coef[:, 2:3], coef[:, 3:4], coef[:, 4:5], ds, None)
            out[:, first[:, None] + np.arange(n)] = jet
            return
        rows = np.array([len(t.single_rows) for t, _, _, _ in entries], dtype=np.int64)
        dest, samples, counts = (np.array([entry[i] for entry in entries], dtype=np.int64) for i in (1, 2, 3))
        owner = np.repeat(np.arange(len(entries)), rows)
        first = np.concatenate([t.single_rows for t, _, _, _ in entries]) * counts[owner] + dest[owner]
        sizes = counts[owner]
        per = np.repeat(np.concatenate([t.single for t, _, _, _ in entries]), sizes, axis=0)
        at = ranges(samples[owner], sizes)
        jet = _cubic_jet(per[:, 1], per[:, 2], per[:, 3], per[:, 4], s[at] - per[:, 0], None)
        out[:, ranges(first, sizes)] = jet


def _counted(laws: list[tuple[Piecewise, int, int, int]], s: np.ndarray, out: np.ndarray) -> None:
    """Profiles of a few records: each point's record by counting the starts at or before it (NaN: the last record,
    as ``searchsorted`` places NaN after every start)."""
    width = max(len(law.starts) for law, _, _, _ in laws)
    starts = np.full((len(laws), width), np.inf)
    coef = np.zeros((len(laws), width, 4))
    records = np.zeros(len(laws), dtype=np.int64)
    for i, (law, _, _, _) in enumerate(laws):
        records[i] = len(law.starts)
        starts[i, : records[i]] = law.starts
        coef[i, : records[i]] = law.coefficients
    n = np.array([n for _, _, _, n in laws], dtype=np.int64)
    owner = np.repeat(np.arange(len(laws)), n)
    at = s[ranges([a for _, _, a, _ in laws], n)]
    count = np.zeros(len(at), dtype=np.int64)
    for j in range(width):  # one pass per record position: no (points x records) array
        count += at >= starts[owner, j]
    count = np.where(np.isnan(at), records[owner], np.minimum(count, records[owner]))
    index = np.maximum(count - 1, 0)
    a, b, c, d = coef[owner, index].T
    out[:, ranges([d for _, d, _, _ in laws], n)] = _cubic_jet(a, b, c, d, at - starts[owner, index], count > 0)


def _cubic_jet(a, b, c, d, ds: np.ndarray, active: np.ndarray | None):
    """:meth:`Piecewise.jet`'s arithmetic on arrays of coefficients (``active``: where a record is in force; ``None``
    for ``ds >= 0``)."""
    with np.errstate(over="ignore", invalid="ignore"):  # s or a coefficient near 1e308: inf/nan, as the reader allows
        value = a + ds * (b + ds * (c + ds * d))
        first = b + ds * (2.0 * c + ds * 3.0 * d)
        second = 2.0 * c + 6.0 * d * ds
    active = ds >= 0 if active is None else active
    if active.all():
        return value, first, second
    return np.where(active, value, 0.0), np.where(active, first, 0.0), np.where(active, second, 0.0)


@lru_cache(maxsize=16384)
def compiled(profile: Profile, origin: float = 0.0) -> Piecewise:
    """The cached :class:`Piecewise` of a profile."""
    return Piecewise(profile, origin)


def jet(profile: Profile, s, origin: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Value, first and second derivative at ``s`` in one lookup."""
    return compiled(profile, origin).jet(s)


def evaluate(profile: Profile, s, origin: float = 0.0) -> np.ndarray:
    return jet(profile, s, origin)[0]


def second_derivative(profile: Profile, s, origin: float = 0.0) -> np.ndarray:
    return jet(profile, s, origin)[2]


def breakpoints(profile: Profile, origin: float = 0.0) -> np.ndarray:
    """Record starts (shifted by ``origin``), sorted."""
    return compiled(profile, origin).starts


def jumps(profile: Profile, origin: float = 0.0) -> list[tuple[Cubic, float, float]]:
    """Where the profile is discontinuous: for every record start after the first, the record in force from there (the
    last of equal starts, as :meth:`Piecewise.jet` picks it), the value the record in force before reaches there and
    the value the new one starts with (:meth:`Piecewise.jet`'s arithmetic: 0 before a record starts, or where the
    start is NaN). Pairs whose difference is not finite are left out (a damaged record)."""
    records = sorted(profile, key=lambda r: r.s) if len(profile) > 1 else profile
    pairs = []
    previous = None
    for k, record in enumerate(records):
        if k + 1 < len(records) and records[k + 1].s == record.s:
            continue  # a later record with the same start holds from there
        if previous is not None and record.s > previous.s:
            pairs.append((previous, record))
        previous = record
    if not pairs:
        return []
    at = np.array([record.s + origin for _, record in pairs], dtype=float)
    reached = _values([before for before, _ in pairs], origin, at)
    starts = _values([record for _, record in pairs], origin, at)
    with np.errstate(invalid="ignore", over="ignore"):
        finite = np.isfinite(reached - starts)
    return [(record, float(a), float(b)) for (_, record), a, b, ok in zip(pairs, reached, starts, finite) if ok]


def _values(records: list[Cubic], origin: float, at: np.ndarray) -> np.ndarray:
    """The value of each record at its ``at`` (0 before the record starts), with :meth:`Piecewise.jet`'s arithmetic."""
    a, b, c, d = np.array([(r.a, r.b, r.c, r.d) for r in records], dtype=float).reshape(-1, 4).T
    return _cubic_jet(a, b, c, d, at - np.array([r.s + origin for r in records], dtype=float), None)[0]
