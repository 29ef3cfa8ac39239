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

import math
from functools import lru_cache

import numpy as np

from xodrcheck.geometry.pose import as_array
from xodrcheck.model import Cubic, Profile


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


#: Profiles with at most this many records are batched by counting starts (cost: records x points comparisons).
_BATCHED_RECORDS = 32


class Batch:
    """Several compiled profiles evaluated together at one array of ``s``, with exactly :meth:`Piecewise.jet`'s
    arithmetic: the single-record ones (the common case: one ``<width>`` per lane) as rows of one array computation,
    those with a few records likewise after finding each point's record by counting the starts at or before it (what
    ``searchsorted`` finds; done per profile instead when an ``s`` is NaN), the empty ones as zeros and the rest one
    by one."""

    __slots__ = ("_batched", "_coefficients", "_laws", "_multi", "_rows", "_starts")

    def __init__(self, laws: tuple[Piecewise, ...]):
        self._laws = laws
        single = [(i, law._single) for i, law in enumerate(laws) if law._single is not None]
        self._rows = {i: row for row, (i, _) in enumerate(single)}
        self._starts = np.array([record[0] for _, record in single], dtype=float)[:, None]
        self._coefficients = np.array([record[1:] for _, record in single], dtype=float).reshape(-1, 4).T[..., None]
        multi = [
            i
            for i, law in enumerate(laws)
            if 2 <= len(law.starts) <= _BATCHED_RECORDS and not np.isnan(law.starts).any()
        ]
        self._multi = {i: row for row, i in enumerate(multi)}
        sizes = [len(laws[i].starts) for i in multi]
        #: The batched profiles' records: (offset of each profile's first record, record starts, coefficients).
        self._batched: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
        if multi:
            self._batched = (
                np.concatenate(([0], np.cumsum(sizes)[:-1])).astype(np.intp),
                np.concatenate([laws[i].starts for i in multi]),
                np.concatenate([laws[i].coefficients for i in multi]).T.copy(),
            )

    def jets(self, s) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
        """``laws[i].jet(s)`` for every law, in order (read-only: arrays may be shared between laws)."""
        s = as_array(s)
        rows, multi = self._rows, self._multi
        if rows:
            a, b, c, d = self._coefficients
            single = _cubic_jet(a, b, c, d, s - self._starts, None)
        batched = self._batched if multi else None
        if batched is not None and np.isnan(s).any():
            multi, batched = {}, None
        if batched is not None:
            offsets, record_starts, record_coefficients = batched
            counts = np.add.reduceat(s >= record_starts[:, None], offsets, axis=0, dtype=np.intp)
            index = offsets[:, None] + np.maximum(counts - 1, 0)
            ds = s - record_starts[index]
            a, b, c, d = (column[index] for column in record_coefficients)
            several = _cubic_jet(a, b, c, d, ds, counts > 0)
        out = []
        zero = None
        for i, law in enumerate(self._laws):
            row = rows.get(i)
            if row is not None:
                out.append((single[0][row], single[1][row], single[2][row]))
                continue
            row = multi.get(i)
            if row is not None:
                out.append((several[0][row], several[1][row], several[2][row]))
            elif len(law.starts) == 0:
                zero = np.zeros_like(s) if zero is None else zero
                out.append((zero, zero, zero))
            else:
                out.append(law.jet(s))
        return out


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
    the value the new one starts with. Pairs whose difference is not finite are left out (a damaged record)."""
    records = sorted(profile, key=lambda r: r.s) if len(profile) > 1 else profile
    out = []
    previous = None
    for k, record in enumerate(records):
        if k + 1 < len(records) and records[k + 1].s == record.s:
            continue  # a later record with the same start holds from there
        if previous is not None and record.s > previous.s:
            at = record.s + origin
            reached = _value(previous, origin, at)
            starts = _value(record, origin, at)
            if math.isfinite(reached - starts):
                out.append((record, reached, starts))
        previous = record
    return out


def _value(record: Cubic, origin: float, at: float) -> float:
    """``Piecewise((record,), origin).jet(np.array([at]))[0][0]`` in scalar arithmetic: the same IEEE double
    operations in the same order, so the same number, without building arrays (0 before the record starts, or where
    ``at`` is NaN)."""
    ds = float(at) - float(record.s + origin)
    if not ds >= 0:
        return 0.0
    a, b, c, d = float(record.a), float(record.b), float(record.c), float(record.d)
    return a + ds * (b + ds * (c + ds * d))
