import itertools

import numpy as np
import pytest

from xodrcheck.geometry import profile
from xodrcheck.model import Cubic

RECORDS = (Cubic(2.0, 1.0, 0.5, -0.1, 0.01), Cubic(10.0, 3.0, 0.0, 0.2, 0.0))


def _cubic(record, s):
    ds = s - record.s
    return record.a + record.b * ds + record.c * ds**2 + record.d * ds**3


def test_value_and_derivatives_follow_the_record_in_force():
    s = np.array([2.0, 5.0, 9.999, 10.0, 14.0])
    value, first, second = profile.jet(RECORDS, s)
    for i, si in enumerate(s):
        record = RECORDS[0] if si < 10.0 else RECORDS[1]
        ds = si - record.s
        assert value[i] == pytest.approx(_cubic(record, si), abs=1e-12)
        assert first[i] == pytest.approx(record.b + 2 * record.c * ds + 3 * record.d * ds**2, abs=1e-12)
        assert second[i] == pytest.approx(2 * record.c + 6 * record.d * ds, abs=1e-12)
    assert np.array_equal(profile.evaluate(RECORDS, s), value)
    assert np.array_equal(profile.jet(RECORDS, s)[1], first)
    assert np.array_equal(profile.second_derivative(RECORDS, s), second)


def test_last_record_holds_to_the_end():
    assert profile.evaluate(RECORDS, 1000.0)[0] == pytest.approx(_cubic(RECORDS[1], 1000.0))


def test_empty_profile_is_zero():
    value, first, second = profile.jet((), [0.0, 5.0])
    assert not value.any() and not first.any() and not second.any()


def test_before_the_first_record_the_default_zero_applies():
    value, first, second = profile.jet(RECORDS, [0.0, 1.999])
    assert not value.any() and not first.any() and not second.any()


def test_equal_starts_take_the_later_record():
    records = (Cubic(0.0, 1.0, 0.0, 0.0, 0.0), Cubic(5.0, 2.0, 0.0, 0.0, 0.0), Cubic(5.0, 3.0, 0.0, 0.0, 0.0))
    assert profile.evaluate(records, [4.0, 5.0, 6.0]).tolist() == [1.0, 3.0, 3.0]


def test_unsorted_records_are_looked_up_by_start():
    records = (RECORDS[1], RECORDS[0])
    assert np.array_equal(profile.evaluate(records, [3.0, 11.0]), profile.evaluate(RECORDS, [3.0, 11.0]))


def test_origin_shifts_record_starts():
    """Lane records are sOffsets: with the section start as origin, absolute s works."""
    assert profile.evaluate(RECORDS, [102.0, 111.0], origin=100.0).tolist() == pytest.approx(
        [_cubic(RECORDS[0], 2.0), _cubic(RECORDS[1], 11.0)]
    )
    assert profile.breakpoints(RECORDS, origin=100.0).tolist() == [102.0, 110.0]


def _random_profile(rng, records: int, origin: float) -> profile.Piecewise:
    starts = np.sort(rng.uniform(0.0, 50.0, records))
    if records > 2:
        starts[2] = starts[1]  # equal starts: the later record holds
    cubics = tuple(Cubic(float(st), *map(float, rng.normal(size=4))) for st in rng.permutation(starts))
    return profile.Piecewise(cubics, origin)


@pytest.mark.parametrize("with_nan", [False, True])
def test_laws_give_exactly_each_profiles_own_jet(with_nan):
    """Profiles evaluated together (profile.Laws: many tables of rows at many blocks of s) are each profile's own
    Piecewise.jet, to the last bit, NaN and infinities included; rows without a profile are zero."""
    rng = np.random.default_rng(7)
    # Empty, single-record, few-record (enough to be counted together) and many-record profiles, some starting after
    # the first s.
    counts = (0, 1, 1, 3, 5, 40, 2, 0, 1, 3, 4, 2, 6)
    laws = tuple(_random_profile(rng, n, origin) for n in counts for origin in (0.0, 7.5))
    s = np.concatenate([[-1.0, 0.0, 60.0, np.inf, -np.inf], rng.uniform(-5.0, 70.0, 200)])
    if with_nan:
        s[5] = np.nan
    for rows, blocks in (
        ((None, *laws), [(0, len(s))]),  # one block: a 2-D computation
        ((None, *laws), [(0, len(s)), (7, 40), (len(s) - 3, 3)]),
        ((None, *laws[:10]), [(0, len(s))]),  # few profiles of several records: searched one by one
    ):
        table = profile.Table(rows)
        together = profile.Laws()
        dest = 0
        for lo, n in blocks:
            together.add(table, dest, lo, n)
            dest += len(rows) * n
        found = together.evaluate(s, dest)
        dest = 0
        for lo, n in blocks:
            for row, law in enumerate(rows):
                got = found[:, dest + row * n : dest + (row + 1) * n]
                expected = law.jet(s[lo : lo + n]) if law is not None else (np.zeros(n),) * 3
                for part, want in zip(got, expected):
                    assert part.tobytes() == want.tobytes()
            dest += len(rows) * n


_EXTREMES = (0.0, -0.0, 1.0, -2.5, 0.1, 1e-300, 1e300, 1e308, -1e308, float("nan"), float("inf"), 123456.789)


@pytest.mark.parametrize("origin", [0.0, 317.25, 1e300])
def test_jumps_are_the_piecewise_values_to_the_last_bit(origin):
    """jumps() evaluates the two records at each start in scalar arithmetic: the numbers are Piecewise.jet's, bit for
    bit, overflow and NaN included (a record pair whose difference is not finite is left out)."""
    rng = np.random.default_rng(5)
    for _ in range(400):
        picks = rng.choice(len(_EXTREMES), size=(3, 5))
        records = tuple(
            Cubic(
                float(10 * k + rng.uniform(0, 5)) if k else 0.0,
                *(_EXTREMES[i] if i % 3 else rng.uniform(-9, 9) for i in picks[k][1:]),
            )
            for k in range(3)
        )
        got = profile.jumps(records, origin)
        want = []
        for previous, record in itertools.pairwise(records):
            at = np.array([record.s + origin])
            with np.errstate(all="ignore"):
                reached = profile.Piecewise((previous,), origin).jet(at)[0][0]
                starts = profile.Piecewise((record,), origin).jet(at)[0][0]
                if np.isfinite(reached - starts):
                    want.append((record, reached.tobytes(), starts.tobytes()))
        assert [(r, np.float64(a).tobytes(), np.float64(b).tobytes()) for r, a, b in got] == want
