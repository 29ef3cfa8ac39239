"""``xodrcheck snapshot FILE.xodr [-o SNAP.json]``: write the invariants of a map as JSON (see
:mod:`xodrcheck.analysis.snapshot`). Exit 0 when the snapshot was written, 2 when the file cannot be read whole, the
configuration cannot be read or the output cannot be written (nothing written then).
"""

from __future__ import annotations

import argparse
import json

from xodrcheck.analysis.snapshot import NotReadWhole, Snapshot, snapshot_of
from xodrcheck.cli.common import error, guarded, not_whole_message, target_ok, written
from xodrcheck.config import Config, ConfigError, load_config
from xodrcheck.findings import ReadError

NAME = "snapshot"
HELP = (
    "Write the invariants of a map as JSON: counts of roads, junctions and lanes, legs, lane length, lane graph "
    "hash, bounding box and findings."
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="OpenDRIVE file")
    parser.add_argument("-o", "--output", metavar="SNAP", help="write to this file instead of standard output")


def dumps(data: dict) -> str:
    """The snapshot's JSON text: one key per line, sorted, so that a committed snapshot diffs readably."""
    return json.dumps(data, indent=1, sort_keys=True) + "\n"


def snapshot_or_error(path: str, config: Config) -> Snapshot | None:
    """The snapshot of the map at ``path``, or ``None`` after one error line when it cannot be taken."""
    try:
        return snapshot_of(path, config)
    except ReadError as exc:
        error(str(exc))
        return None
    except NotReadWhole as exc:
        error(not_whole_message(path, exc.why))
        return None


def config_or_error() -> Config | None:
    """The project configuration, or ``None`` after one error line when it cannot be read."""
    try:
        return load_config()
    except (OSError, ValueError, ConfigError) as exc:
        error(f"configuration: {exc}")
        return None


def run(args: argparse.Namespace) -> int:
    config = config_or_error()
    if config is None or not target_ok(args.output):
        return 2

    def one() -> int:
        snap = snapshot_or_error(args.file, config)
        if snap is None:
            return 2
        return 0 if written(args.output, lambda stream: stream.write(dumps(snap.to_json()))) else 2

    return guarded(args.file, one)
