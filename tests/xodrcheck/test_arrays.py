"""``xodrcheck.arrays.unique`` is ``np.unique``, bit for bit (which of -0.0 and 0.0 survives, one NaN), without
importing ``numpy.ma``."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from xodrcheck.arrays import unique

SPECIAL = np.array([0.0, -0.0, np.nan, np.inf, -np.inf, 1e-300, -1e-300, 5e-324, 1.0, 1.0 + 2**-52])


def _same(values: np.ndarray) -> None:
    ours, theirs = unique(values), np.unique(values)
    assert ours.dtype == theirs.dtype and ours.shape == theirs.shape
    assert ours.tobytes() == theirs.tobytes()  # bit for bit: the sign of zeros, the NaN kept


@pytest.mark.parametrize("seed", range(40))
def test_unique_is_numpys_on_floats_with_repeats_zeros_and_nans(seed: int) -> None:
    rng = np.random.default_rng(seed)
    n = int(rng.integers(0, 3000))
    pool = np.concatenate([SPECIAL, rng.normal(size=8), np.round(rng.normal(size=8), 1)])
    values = rng.choice(pool, size=n)
    _same(values)
    _same(values.reshape(-1, 1) if n else values)  # flattened like numpy's
    _same(rng.normal(size=n))  # no repeats
    _same(np.sort(values))  # already sorted


@pytest.mark.parametrize("dtype", [np.int64, np.int32, np.uint8, bool, np.float32])
def test_unique_is_numpys_on_other_kinds(dtype) -> None:
    rng = np.random.default_rng(7)
    for n in (0, 1, 2, 17, 1000):
        _same(rng.integers(-5, 6, size=n).astype(dtype))


def test_unique_of_an_empty_array_and_a_scalar() -> None:
    _same(np.array([], dtype=float))
    _same(np.array(3.0))
    _same(np.array([np.nan, np.nan, -0.0, 0.0, -0.0]))


def test_unique_imports_no_numpy_ma() -> None:
    code = (
        "import sys, numpy as np; from xodrcheck.arrays import unique; "
        "unique(np.array([2.0, 1.0, 2.0])); unique(np.arange(5)); print('numpy.ma' in sys.modules)"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True)
    assert done.stdout.strip() == "False"
