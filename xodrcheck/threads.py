"""One thread for the numerical libraries under numpy, in the command-line tools only (not on ``import xodrcheck``).

numpy's OpenBLAS (and an OpenMP or MKL build) starts a pool of threads when numpy is imported: on a 2-core machine
that costs about 0.06-0.09 s of CPU in every run of ``xodrcheck check`` and ``junctionart generate``, spinning
threads that the commands' small arrays never use (parallel work runs in processes: ``-j N``). The libraries read
their thread count from the environment once, when they load, so :func:`one_blas_thread` must run before the first
``import numpy``. It sets nothing when the user set any of the variables (their choice stands) or numpy is already
loaded (too late to matter). Results are the same with any number of threads (``benchmarks/identity.py`` with 1, 2
and 8 threads); the variables pass on to worker processes, which then do not oversubscribe the cores either.
"""

from __future__ import annotations

import os
import sys

#: The variables OpenBLAS (``OPENBLAS_NUM_THREADS``, then ``GOTO_NUM_THREADS``, then ``OMP_NUM_THREADS``), OpenMP
#: and MKL read for their number of threads.
THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")

#: What :func:`one_blas_thread` sets (``GOTO_NUM_THREADS`` is only read, an older name of OpenBLAS's own).
SET = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def one_blas_thread() -> bool:
    """Ask the BLAS and OpenMP libraries for one thread, unless the user chose a number or numpy is loaded; whether
    it did."""
    if "numpy" in sys.modules or any(name in os.environ for name in THREAD_VARIABLES):
        return False
    for name in SET:
        os.environ[name] = "1"
    return True
