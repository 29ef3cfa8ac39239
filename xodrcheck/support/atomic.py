"""Output files written whole or not at all, errors that name the path the user gave, and cleanup on signals.

Every command of both tools (``xodrcheck`` and ``junctionart``) writes its files through :func:`atomic_file`: the data
go to a temporary file ``.NAME.XXXXXXXX.tmp`` beside the target, which is renamed onto the target only when the
writing finished without an error. On an error, on Ctrl-C (``KeyboardInterrupt``) and on SIGTERM (turned into
:class:`Terminated` by :func:`signals_raise`) the temporary file is removed and an existing target is left as it was.

A problem with the target is an :class:`OutputError` whose message names the path as given and the cause
(``cannot write /proc/x.xodr: cannot create a file in folder /proc (No such file or directory)``), never the temporary
file. :func:`check_target` finds the usual ones (a missing folder, a directory) before any work is done.
"""

from __future__ import annotations

import errno
import os
import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from types import FrameType
from typing import IO, Any

from xodrcheck.findings import XodrError

__all__ = [
    "EXIT_INTERRUPTED",
    "EXIT_TERMINATED",
    "OutputError",
    "Terminated",
    "atomic_file",
    "check_target",
    "signals_raise",
    "write_bytes",
]


#: Exit status of a command stopped by SIGTERM (128 + the signal number, as a shell reports it).
EXIT_TERMINATED = 128 + signal.SIGTERM
#: Exit status of a command stopped by Ctrl-C.
EXIT_INTERRUPTED = 130


class OutputError(XodrError):
    """An output file cannot be written; the message names the path the user gave and the cause."""


class Terminated(BaseException):
    """SIGTERM arrived (raised in the main thread by the handler :func:`signals_raise` installs). A ``BaseException``
    like ``KeyboardInterrupt``, so that only cleanup code (``finally``, ``except BaseException``) sees it."""


def _cause(exc: OSError) -> str:
    if exc.errno == errno.EISDIR:
        return "it is a directory"
    if exc.errno in (errno.EACCES, errno.EPERM):
        return f"permission denied ({exc.strerror})"
    if exc.errno == errno.ENOSPC:
        return "no space left on the device"
    return exc.strerror or str(exc)


def _folder(target: Path) -> Path:
    return target.parent if str(target.parent) else Path(".")


def check_target(path: str | os.PathLike[str]) -> Path:
    """The target as a :class:`~pathlib.Path`, after checking what can be checked before any work is done: its folder
    exists and is a folder, and the target is not a directory. Raises :class:`OutputError`."""
    target = Path(path)
    folder = _folder(target)
    if target.is_dir():
        raise OutputError(f"cannot write {path}: it is a directory")
    if not folder.exists():
        raise OutputError(f"cannot write {path}: folder {folder} does not exist")
    if not folder.is_dir():
        raise OutputError(f"cannot write {path}: {folder} is not a folder")
    return target


def _umask() -> int:
    try:  # reading the mask through os.umask sets it for a moment: the kernel's copy is thread-safe
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


@contextmanager
def atomic_file(path: str | os.PathLike[str], mode: str = "w") -> Iterator[IO[Any]]:
    """A stream (``mode`` ``"w"``: UTF-8 text, ``"wb"``: bytes) whose data land in ``path`` only when the block
    finishes without an exception. Raises :class:`OutputError` (naming ``path``) when the file cannot be created,
    written or moved into place; any exception leaves no temporary file and the target untouched."""
    if mode not in ("w", "wb"):
        raise ValueError(f"mode must be 'w' or 'wb', got {mode!r}")
    target = check_target(path)
    folder = _folder(target)
    try:
        import tempfile  # here: a check that writes no file does not load it (nor random, shutil)

        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise OutputError(f"cannot write {path}: cannot create a file in folder {folder} ({_cause(exc)})") from None
    try:
        try:
            os.fchmod(fd, 0o666 & ~_umask())  # mkstemp makes the file 0600; give it the mode of any new file
            if mode == "wb":
                stream: IO[Any] = os.fdopen(fd, "wb")
            else:
                stream = os.fdopen(fd, "w", encoding="utf-8", newline="")
            with stream:
                yield stream
                stream.flush()
                os.fsync(stream.fileno())
            os.replace(tmp, target)
        except OSError as exc:
            if exc.filename not in (None, tmp) or isinstance(exc, BrokenPipeError):
                raise  # not about this file (an input the block reads, say): the caller reports it
            raise OutputError(f"cannot write {path}: {_cause(exc)}") from None
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_bytes(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (see :func:`atomic_file`); the target is returned."""
    with atomic_file(path, "wb") as stream:
        stream.write(data)
    return Path(path)


def _raise_terminated(signum: int, frame: FrameType | None) -> None:
    raise Terminated(f"signal {signum}")


@contextmanager
def signals_raise() -> Iterator[None]:
    """While the block runs, SIGTERM raises :class:`Terminated` in the main thread (the previous handler comes back
    after), so ``with atomic_file(...)`` removes its temporary file as it does on Ctrl-C. Outside the main thread
    (where Python cannot set handlers) this does nothing."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGTERM, _raise_terminated)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)
