"""What the command-line tools do to start faster, and only they (``import xodrcheck`` as a library does none of it).

* :func:`one_blas_thread`: numpy's OpenBLAS (and an OpenMP or MKL build) starts a pool of threads when numpy is
  imported; on a 2-core machine that costs about 0.06-0.09 s of CPU in every run of ``xodrcheck check`` and
  ``junctionart generate``, spinning threads that the commands' small arrays never use (parallel work runs in
  processes: ``-j N``). The libraries read their thread count from the environment once, when they load, so this
  runs before the first ``import numpy``. It sets nothing when the user set any of the variables (their choice
  stands) or numpy is already loaded. Results are the same with any number of threads (``benchmarks/identity.py``
  with 1, 2 and 8 threads); the variables pass on to worker processes, which then do not oversubscribe the cores.
* :func:`pause_collector` / :func:`imports_done`: importing the checker or the generator creates some 10^5 objects
  that live as long as the process (modules, classes, functions), and the cyclic garbage collector traverses them
  again and again while they are made (about 10-14 ms of a command's start). A command pauses the collector while it
  imports what it needs, then freezes those objects (:func:`gc.freeze`: never traversed again; the little garbage
  made meanwhile stays) and resumes it before its work, so a large file is checked with the collector running as
  usual. Only for the process's own command line (``main()`` without arguments), never for a caller of ``main(argv)``
  in its own process (a test, say), whose objects must stay collectable.
"""

from __future__ import annotations

import gc
import os
import sys

#: The variables OpenBLAS (``OPENBLAS_NUM_THREADS``, then ``GOTO_NUM_THREADS``, then ``OMP_NUM_THREADS``), OpenMP
#: and MKL read for their number of threads.
THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")

#: What :func:`one_blas_thread` sets (``GOTO_NUM_THREADS`` is only read, an older name of OpenBLAS's own).
SET = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")

_paused = False


def one_blas_thread() -> bool:
    """Ask the BLAS and OpenMP libraries for one thread, unless the user chose a number or numpy is loaded; whether
    it did."""
    if "numpy" in sys.modules or any(name in os.environ for name in THREAD_VARIABLES):
        return False
    for name in SET:
        os.environ[name] = "1"
    return True


def pause_collector() -> bool:
    """Stop the cyclic garbage collector until :func:`imports_done` (not when it is stopped already); whether it
    did."""
    global _paused
    if _paused or not gc.isenabled():
        return False
    gc.disable()
    _paused = True
    return True


def imports_done() -> None:
    """After a command's imports: freeze what exists and resume the collector, if :func:`pause_collector` stopped
    it (else nothing)."""
    global _paused
    if _paused:
        _paused = False
        gc.freeze()
        gc.enable()


def begin(argv: object) -> None:
    """First thing of a command's ``main(argv)``: :func:`one_blas_thread`, and for the process's own command line
    (``argv`` None) :func:`pause_collector`."""
    one_blas_thread()
    if argv is None:
        pause_collector()
