#!/usr/bin/env python3
"""Write the fast verdict's plan of each XSD 1.1 schema (``schemas/<folder>/fast-plan.json``, for OpenDRIVE 1.8 and
1.9) from xmlschema's compiled schema (:mod:`xodrcheck.schema.plan`).

Usage: ``scripts/schema_plan.py`` (from the repository; re-run after changing a schema folder, the errata or the
translation, then commit the plans).
"""

from __future__ import annotations

import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from xodrcheck.schema import plan as schema_plan  # noqa: E402
from xodrcheck.schema import validate as schema  # noqa: E402


def main() -> int:
    for version in sorted(schema.XSD11):
        folder, _ = schema.SCHEMA_FOLDERS[version]
        plan = schema_plan.build(schema.compiled(version))
        out = REPO / "schemas" / folder / schema_plan.PLAN_FILE
        out.write_text(schema_plan.dumps(plan), encoding="utf-8")
        untranslated = sum(a["xpath"] is None for t in plan["types"] for a in t["assertions"]) + sum(
            a["xpath"] is None and a["test"] is not None for d in plan["decls"] for a in d["alternatives"]
        )
        print(
            f"{out.relative_to(REPO)}: {len(plan['decls'])} declarations, {len(plan['types'])} types, "
            f"{untranslated} tests not translated"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
