"""What the subcommands share: reading a file with one clear line per problem, and writing output atomically."""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, TYPE_CHECKING

from xodrcheck.findings import ReadError, Severity

if TYPE_CHECKING:
    from xodrcheck.reader import ReadResult


def positive_number(text: str) -> float:
    """argparse type: a finite number > 0 (a step, a chord)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"must be a finite number > 0, got {text!r}")
    return value


def error(message: str) -> None:
    """One line on stderr, prefixed with the program name."""
    print(f"xodrcheck: {message}", file=sys.stderr)


def read_file(path: str) -> ReadResult | None:
    """Read ``path``; on :class:`ReadError` print why and return ``None`` (the caller exits 2)."""
    from xodrcheck.reader import read  # here: `xodrcheck --help` loads no reader

    try:
        return read(path)
    except ReadError as exc:
        error(f"cannot read {path}: {exc}")
        return None


def report_errors(path: str, result: ReadResult) -> bool:
    """Print one line if the reader found error-level problems; return whether it did."""
    errors = [f for f in result.findings if f.severity >= Severity.ERROR]
    if not errors:
        return False
    first = errors[0]
    where = f" (line {first.line})" if first.line else ""
    more = f" and {len(errors) - 1} more" if len(errors) > 1 else ""
    error(f"{path}: {first.code} {first.name}: {first.message}{where}{more}")
    return True


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


@contextmanager
def output(path: str | None) -> Iterator[IO[str]]:
    """A text stream for ``path`` (stdout for ``None`` or ``-``). A file is written to a temporary file beside it and
    moved into place only when the block finishes without an exception, so a failed run leaves no partial file."""
    if path is None or path == "-":
        yield sys.stdout
        sys.stdout.flush()
        return
    target = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    try:
        os.fchmod(fd, 0o666 & ~_umask())
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as stream:
            yield stream
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def guarded(path: str, action: Callable[[], int]) -> int:
    """Run one file's work; an unexpected exception becomes one line and exit 2 instead of a traceback."""
    try:
        return action()
    except (KeyboardInterrupt, BrokenPipeError):
        raise
    except Exception as exc:
        error(f"internal error on {path}: {type(exc).__name__}: {exc}")
        return 2
