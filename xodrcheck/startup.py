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
* :func:`finish`: a command on the process's own command line ends the process when it is done, after flushing
  stdout and stderr and running the :mod:`atexit` handlers (xodrcheck's dataclass cache, coverage, logging), without
  the interpreter's teardown: freeing every module, class and array one by one took 10-60 ms of a run of
  ``xodrcheck check FILE`` (more the larger the file), and nothing of it is seen. Not when a thread other than the
  main one is alive (a ``-j`` or Dask run still shutting down), nor when the streams cannot be flushed (a closed
  pipe): the usual exit then.
"""

from __future__ import annotations

import atexit
import gc
import os
import sys

#: The variables OpenBLAS (``OPENBLAS_NUM_THREADS``, then ``GOTO_NUM_THREADS``, then ``OMP_NUM_THREADS``), OpenMP
#: and MKL read for their number of threads.
THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")

#: What :func:`one_blas_thread` sets (``GOTO_NUM_THREADS`` is only read, an older name of OpenBLAS's own).
SET = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")

_paused = False
#: Whether the running command is the process's own command line (:func:`begin` without ``argv``).
_own = False


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
    global _own
    one_blas_thread()
    _own = argv is None
    if _own:
        pause_collector()


def finish(code: int) -> int:
    """After the command's work: for the process's own command line, flush the streams, run the :mod:`atexit`
    handlers and end the process with ``code`` now, without the interpreter's teardown (no return); else ``code``.
    The usual exit (``code`` returned) when another thread is alive or a stream cannot be flushed."""
    threading = sys.modules.get("threading")
    if not _own or (threading is not None and threading.active_count() > 1):
        return code
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except (OSError, ValueError):  # a closed pipe or stream: Python's own exit reports it as it always did
        return code
    atexit._run_exitfuncs()
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    finally:
        os._exit(code)
