"""pytest plugin (entry point ``pytest11``): assert a map against its committed snapshot.

The fixture ``xodr_snapshot`` is a function ``xodr_snapshot(source, snapshot=None)``: ``source`` is an OpenDRIVE file
(path or bytes), ``snapshot`` the JSON file of its invariants (see :mod:`xodrcheck.analysis.snapshot`; by default
``snapshots/<file stem>.json`` beside the test module). The test fails with one readable line per change when the
map's invariants differ from the snapshot, or when there is no snapshot yet. ``pytest --xodr-snapshot-update``
writes the snapshots instead (new and changed ones), and the test passes::

    def test_my_map(xodr_snapshot, tmp_path):
        path = tmp_path / "town.xodr"
        my_generator.write(path, seed=7)
        xodr_snapshot(path, snapshot=Path(__file__).parent / "snapshots" / "town-7.json")
"""

from __future__ import annotations

from pathlib import Path

import pytest

_OPTION = "--xodr-snapshot-update"


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("xodrcheck", "OpenDRIVE map snapshots")
    group.addoption(
        _OPTION,
        action="store_true",
        default=False,
        help="write the snapshots the xodr_snapshot fixture compares with, instead of comparing",
    )


class SnapshotAssertion:
    """The callable behind the ``xodr_snapshot`` fixture."""

    def __init__(self, folder: Path, update: bool) -> None:
        self.folder = folder
        self.update = update

    def __call__(self, source: str | Path | bytes, snapshot: str | Path | None = None) -> None:
        from xodrcheck.analysis.snapshot import SnapshotError, differences, snapshot_of
        from xodrcheck.cli.diff import load
        from xodrcheck.cli.snapshot import dumps

        if snapshot is None:
            if isinstance(source, bytes):
                raise TypeError("xodr_snapshot(bytes) needs snapshot=PATH")
            snapshot = self.folder / "snapshots" / f"{Path(source).stem}.json"
        snapshot = Path(snapshot)
        new = snapshot_of(source)
        if self.update:
            snapshot.parent.mkdir(parents=True, exist_ok=True)
            text = dumps(new.to_json())
            if not snapshot.is_file() or snapshot.read_text(encoding="utf-8") != text:
                snapshot.write_text(text, encoding="utf-8")
            return
        if not snapshot.is_file():
            pytest.fail(f"no snapshot {snapshot}; run pytest {_OPTION} to write it", pytrace=False)
        try:
            old = load(str(snapshot))
        except (OSError, SnapshotError) as exc:
            pytest.fail(f"cannot use snapshot {snapshot}: {exc}", pytrace=False)
        lines = list(differences(old, new))
        if lines:
            where = "the map" if isinstance(source, bytes) else str(source)
            pytest.fail(
                f"{where} differs from {snapshot} (run pytest {_OPTION} to accept):\n  " + "\n  ".join(lines),
                pytrace=False,
            )


@pytest.fixture
def xodr_snapshot(request: pytest.FixtureRequest) -> SnapshotAssertion:
    """Assert an OpenDRIVE map against its snapshot: ``xodr_snapshot(path_or_bytes, snapshot=None)``."""
    return SnapshotAssertion(Path(request.path).parent, bool(request.config.getoption(_OPTION)))


__all__ = ["SnapshotAssertion", "xodr_snapshot"]
