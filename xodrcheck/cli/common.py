"""What the subcommands share: reading a file with one clear line per problem, and writing output atomically.

The rules every subcommand follows (the README's table): an input that cannot be opened or read whole gives one line
and exit 2, and nothing is written for it; ``-o FILE`` is checked before any work and written whole or not at all
(:mod:`xodrcheck.support.atomic`), also on Ctrl-C (exit 130) and SIGTERM (exit 143); exit 2 never leaves a new file.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import IO, TYPE_CHECKING

from xodrcheck.findings import ReadError, Severity
from xodrcheck.support.atomic import OutputError, atomic_file, check_target

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
    """Read ``path`` for a command that turns a map into data. ``None`` after one line on stderr (the caller exits 2,
    writing nothing for this file) when it cannot be opened or cannot be read whole (see
    :meth:`~xodrcheck.reader.ReadResult.not_whole`: not well-formed, not OpenDRIVE, entity references left out)."""
    from xodrcheck.reader import read  # here: `xodrcheck --help` loads no reader

    try:
        result = read(path)
    except ReadError as exc:
        error(str(exc))
        return None
    why = result.not_whole()
    if why is not None:
        error(not_whole_message(path, why))
        return None
    return result


def not_whole_message(path: str, why: str) -> str:
    """The one line every command prints for a file it cannot read whole."""
    return f"cannot read {path} whole, so nothing is written for it: {why}"


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


def target_ok(path: str | None) -> bool:
    """Whether ``-o path`` can be written, checked before any work (one line on stderr when it cannot: exit 2).
    ``None`` and ``-`` (standard output) always can."""
    if path is None or path == "-":
        return True
    try:
        check_target(path)
    except OutputError as exc:
        error(str(exc))
        return False
    return True


@contextmanager
def output(path: str | None) -> Iterator[IO[str]]:
    """A text stream for ``path`` (stdout for ``None`` or ``-``). A file is written whole or not at all
    (:func:`xodrcheck.support.atomic.atomic_file`): a failed or interrupted run leaves no partial file, and a problem
    with the target raises :class:`~xodrcheck.support.atomic.OutputError` naming ``path``."""
    if path is None or path == "-":
        yield sys.stdout
        sys.stdout.flush()
        return
    with atomic_file(path, "w") as stream:
        yield stream


def written(path: str | None, write: Callable[[IO[str]], object]) -> bool:
    """Whether ``write`` could write its whole output to ``path`` through :func:`output`; ``False`` after one line on
    stderr when the target failed (the caller exits 2: nothing was written)."""
    try:
        with output(path) as stream:
            write(stream)
    except OutputError as exc:
        error(str(exc))
        return False
    return True


def guarded(path: str, action: Callable[[], int]) -> int:
    """Run one file's work; an unexpected exception becomes one line and exit 2 instead of a traceback."""
    try:
        return action()
    except (KeyboardInterrupt, BrokenPipeError):
        raise
    except Exception as exc:
        error(f"internal error on {path}: {type(exc).__name__}: {exc}")
        return 2
