"""Numbers in findings' messages, written one way: what a user reads, without float noise.

A position along a road or a length (``s``, ``sOffset``, a road's or element's length, a ``t`` or ``u``/``v``
offset), in metres, goes through :func:`metres`: rounded to the micrometre (finer than any tolerance of the checker,
close enough to find the value in the file) and written without trailing zeros, so ``99.9999999`` reads ``100``,
``0.1 + 0.2`` reads ``0.3`` and ``1.68793e-06`` reads ``0.000002``. A measured size shown to a few significant digits
(a gap of ``0.001104 m``, a radius of ``3.62 m``, an angle in degrees) keeps its own precision in the message.
"""

from __future__ import annotations

import math

__all__ = ["metres"]

#: Decimals of :func:`metres`: micrometres.
DECIMALS = 6


def metres(value: float | None) -> str:
    """``value`` (metres) rounded to the micrometre, without trailing zeros: ``12.5``, ``100``, ``0.000017``.

    A value that is not zero but rounds to it keeps two significant digits (``3e-07``) so that a message never calls
    a non-zero length 0; ``-0`` reads ``0``; a value that is not finite reads as Python writes it (``inf``, ``nan``);
    ``None`` (a value the file did not give) reads ``?``.
    """
    if value is None:
        return "?"
    if not math.isfinite(value):
        return str(value)
    text = f"{value:.{DECIMALS}f}".rstrip("0").rstrip(".")
    if text in ("0", "-0"):
        return "0" if value == 0.0 else f"{value:.2g}"
    return text
