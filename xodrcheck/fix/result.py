"""``fix(path)``: the fixed bytes of one file, the repairs applied and rolled back, and the check of the result with
why each finding left is left."""

from __future__ import annotations

import dataclasses
import difflib
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from xodrcheck.check import Report, Selection, check
from xodrcheck.config import Config
from xodrcheck.findings import Finding, ReadError
from xodrcheck.fix.driver import Applied, RolledBack, Session

__all__ = ["FixResult", "fix"]


@dataclass(frozen=True)
class FixResult:
    """What :func:`fix` did to one file.

    ``data`` are the fixed bytes (``original`` when nothing was fixed); ``applied`` the repairs that stayed,
    ``rolled_back`` those taken back and why; ``report`` the check of ``data`` (with the selection asked for);
    ``remaining`` each of its findings with why it is left."""

    path: str | None
    original: bytes
    data: bytes
    applied: tuple[Applied, ...]
    rolled_back: tuple[RolledBack, ...]
    report: Report
    remaining: tuple[tuple[Finding, str], ...]

    @property
    def changed(self) -> bool:
        return self.data != self.original

    def fixed(self) -> Counter[str]:
        """Findings removed, by rule code (as claimed by the repairs that stayed)."""
        return Counter(f.code for a in self.applied for f in a.repair.findings)

    def diff(self, fromfile: str | None = None, tofile: str | None = None) -> str:
        """A unified diff from the original to the fixed text (empty when nothing changed)."""
        if not self.changed:
            return ""
        name = self.path or "map.xodr"  # both sides name the file: `patch -p0` applies the diff to it
        old = self.original.decode("utf-8", "surrogateescape").splitlines(keepends=True)
        new = self.data.decode("utf-8", "surrogateescape").splitlines(keepends=True)
        lines = difflib.unified_diff(old, new, fromfile or name, tofile or name)
        return "".join(
            line if line.endswith(("\n", "\r")) else line + "\n\\ No newline at end of file\n" for line in lines
        )


def _source_bytes(source: str | Path | bytes, config: Config) -> tuple[bytes, str | None]:
    if isinstance(source, bytes):
        data, path = source, None
    else:
        path = str(source)
        try:
            data = Path(path).read_bytes()
        except IsADirectoryError:
            raise ReadError("it is a directory, not a file", path) from None
        except OSError as exc:
            raise ReadError(exc.strerror or str(exc), path) from None
    if len(data) > config.tolerances.max_file_bytes:
        raise ReadError("it is larger than the limit (tolerance max_file_bytes)", path)
    if data.startswith(b"\x1f\x8b"):
        raise ReadError("it is gzip-compressed (.xodrz): decompress it to fix it", path)
    return data, path


def fix(
    source: str | Path | bytes,
    config: Config | None = None,
    *,
    select: Sequence[str] = (),
    ignore: Sequence[str] = (),
    unsafe: bool = False,
) -> FixResult:
    """Fix one OpenDRIVE file (a path, or its bytes); nothing is written.

    ``select``/``ignore`` (as :func:`~xodrcheck.check.check`'s) choose the findings to fix and the report's; every
    repair is judged by the configured check of the whole file, so a repair that brings a finding of a rule not
    selected is rolled back too. ``unsafe`` adds the fixes that may move geometry up to their stated bound or drop
    references. Raises :class:`~xodrcheck.findings.ReadError` when the file cannot be read (or is compressed) and
    :class:`~xodrcheck.config.ConfigError` for an unknown selector.
    """
    config = config or Config()
    selection = Selection(tuple(select) or config.select, tuple(ignore) or config.ignore)
    data, path = _source_bytes(source, config)
    session = Session(data, config, selection, unsafe)
    session.run()
    assert session.report is not None
    report = session.report
    if select or ignore:  # the session's check is the configured one; the report is the one asked for
        report = check(session.data, config, select, ignore)
    report = dataclasses.replace(report, path=path)
    return FixResult(
        path,
        data,
        session.data,
        tuple(session.applied),
        tuple(session.rolled_back),
        report,
        tuple(session.remaining(report.findings)),
    )
