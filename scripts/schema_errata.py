#!/usr/bin/env python3
"""Write the corrected copies of the official OpenDRIVE XSDs (``schemas/1.8.1-corrected``, ``schemas/1.9.0-corrected``)
from the official folders, applying :data:`xodrcheck.schema.errata.ERRATA`.

Usage: ``scripts/schema_errata.py`` (from the repository; re-run after changing the errata, then commit the folders).
"""

from __future__ import annotations

import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from xodrcheck.schema.errata import CORRECTED, corrected_files  # noqa: E402


def main() -> int:
    for release, target in CORRECTED.items():
        out = REPO / "schemas" / target
        out.mkdir(exist_ok=True)
        for name, data in corrected_files(release).items():
            (out / name).write_bytes(data)
        print(f"schemas/{target}: {len(list(out.glob('*.xsd')))} files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
