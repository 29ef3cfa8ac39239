"""Accuracy and speed of xodrcheck's Fresnel integrals (xodrcheck.geometry.fresnel) against scipy.special.fresnel.

    python benchmarks/fresnel_accuracy.py [--mpmath-points 20000] [--dense 1000000]

Accuracy: max absolute and relative error of ours and of scipy's against mpmath (40 digits) on random points of each
method's range, log-spaced points up to 1e10 and points next to every switch of method; then ours against scipy on a
dense grid of [0, 10], log-spaced points up to 1e10 and the switch points. Speed: microseconds per point on 1e5 points
of each range (minimum of 15 calls each, CPU time). Needs scipy and mpmath (test dependencies).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import mpmath as mp
import numpy as np
from scipy.special import fresnel as scipy_fresnel

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from xodrcheck.geometry.fresnel import fresnel  # noqa: E402 (after the sys.path entry)

EPS = float(np.finfo(float).eps)


def switch_points() -> np.ndarray:
    """Points within 80 eps (relative) of 1, 5.5 and every node's half-way point (n + 1/2) / 16."""
    edges = np.concatenate([[1.0, 5.5], (np.arange(16, 89) + 0.5) / 16])
    return np.unique((edges[:, None] * (1 + np.arange(-20, 21) * 4 * EPS)).ravel())


def reference(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    with mp.workdps(40):
        s = np.array([float(mp.fresnels(mp.mpf(float(v)))) for v in x])
        c = np.array([float(mp.fresnelc(mp.mpf(float(v)))) for v in x])
    return s, c


def errors(got: tuple[np.ndarray, np.ndarray], want: tuple[np.ndarray, np.ndarray]) -> tuple[float, float]:
    """Max absolute and max relative error over S and C (relative where the reference is a normal number)."""
    absolute = max(float(np.max(np.abs(g - w))) for g, w in zip(got, want))
    relative = 0.0
    for g, w in zip(got, want):
        normal = np.abs(w) > 1e-290
        if normal.any():
            relative = max(relative, float(np.max(np.abs(g - w)[normal] / np.abs(w[normal]))))
    return absolute, relative


def accuracy(points: int, dense: int) -> None:
    rng = np.random.default_rng(1)
    share = points // 5
    ranges = {
        "[0, 1)": rng.uniform(0, 1, share),
        "[1, 5.5)": rng.uniform(1, 5.5, 2 * share),
        "[5.5, 12)": rng.uniform(5.5, 12, share),
        "1e-300..1e10": 10 ** rng.uniform(-300, 10, share),
        "switches": switch_points(),
    }
    print("against mpmath (40 digits): max abs / max rel error")
    for name, x in ranges.items():
        want = reference(x)
        ours, theirs = errors(fresnel(x), want), errors(scipy_fresnel(x), want)
        print(f"  {name:14s} {len(x):7d} points  ours {ours[0]:.3g} / {ours[1]:.3g}", end="")
        print(f"  scipy {theirs[0]:.3g} / {theirs[1]:.3g}")
    print("ours against scipy: max abs / max rel difference")
    grids = {
        f"[0, 10] x {dense}": np.linspace(0, 10, dense),
        "log 1e-300..1e4": np.geomspace(1e-300, 1e4, dense),
        "log 1e4..1e10": np.geomspace(1e4, 1e10, dense // 10),
        "switches": switch_points(),
    }
    for name, x in grids.items():
        diff = errors(fresnel(x), scipy_fresnel(x))
        print(f"  {name:18s} {diff[0]:.3g} / {diff[1]:.3g}")


def speed() -> None:
    rng = np.random.default_rng(0)
    print("microseconds per point, 1e5 points (min of 15 calls, CPU time)")
    for name, x in {
        "[0, 1)": rng.uniform(0, 1, 10**5),
        "[1, 5.5)": rng.uniform(1, 5.5, 10**5),
        "[5.5, 12)": rng.uniform(5.5, 12, 10**5),
        "[0, 10]": rng.uniform(0, 10, 10**5),
        "1e-3..1e10": 10 ** rng.uniform(-3, 10, 10**5),
    }.items():
        best = {}
        for label, function in (("ours", fresnel), ("scipy", scipy_fresnel)):
            function(x)
            times = []
            for _ in range(15):
                start = time.process_time()
                function(x)
                times.append(time.process_time() - start)
            best[label] = min(times) / x.size * 1e6
        ratio = best["ours"] / best["scipy"]
        print(f"  {name:11s} ours {best['ours']:.3f}  scipy {best['scipy']:.3f}  ratio {ratio:.1f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mpmath-points", type=int, default=20_000)
    parser.add_argument("--dense", type=int, default=1_000_000)
    args = parser.parse_args()
    accuracy(args.mpmath_points, args.dense)
    speed()
    return 0


if __name__ == "__main__":
    sys.exit(main())
