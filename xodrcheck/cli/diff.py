"""``xodrcheck diff SNAPSHOT FILE.xodr``: what changed in a map since its snapshot, one readable line per change.

Exit 0 when nothing changed, 1 when something did, 2 when the snapshot or the map cannot be read.
"""

from __future__ import annotations

import argparse
import json

from xodrcheck.analysis.snapshot import Snapshot, SnapshotError, differences
from xodrcheck.cli.common import error, guarded
from xodrcheck.cli.snapshot import config_or_error, snapshot_or_error

NAME = "diff"
HELP = "Compare a map with its snapshot (from 'xodrcheck snapshot'): print what changed, exit 1 if anything did."


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("snapshot", metavar="SNAPSHOT", help="snapshot JSON written by 'xodrcheck snapshot'")
    parser.add_argument("file", metavar="FILE", help="OpenDRIVE file")


def load(path: str) -> Snapshot:
    """A snapshot file; :class:`SnapshotError` (or :class:`OSError`) when it cannot be used."""
    with open(path, encoding="utf-8") as stream:
        try:
            data = json.load(stream)
        except (json.JSONDecodeError, UnicodeDecodeError) as exc:
            raise SnapshotError(f"not JSON: {exc}") from None
    return Snapshot.from_json(data)


def run(args: argparse.Namespace) -> int:
    config = config_or_error()
    if config is None:
        return 2
    try:
        old = load(args.snapshot)
    except (OSError, SnapshotError) as exc:
        error(f"cannot use snapshot {args.snapshot}: {exc}")
        return 2

    def one() -> int:
        new = snapshot_or_error(args.file, config)
        if new is None:
            return 2
        lines = list(differences(old, new, config.tolerances))
        for line in lines:
            print(f"{args.file}: {line}")
        if not lines:
            print(f"{args.file}: no change from {args.snapshot}")
        return 1 if lines else 0

    return guarded(args.file, one)
