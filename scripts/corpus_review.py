"""Corpus review (docs/corpus-review.md): tables of the corpus check's findings and, for CARLA's towns, each error
code's worst and a typical finding recomputed independently of the rule, with a picture.

    .venv/bin/python scripts/corpus_review.py                      # runs xodrcheck check on ../shared/corpus
    .venv/bin/python scripts/corpus_review.py --report check.json  # or reads a saved `check --format json` report

Writes ``docs/corpus-review/tables.md`` (the tables the review quotes) and ``docs/corpus-review/<code>.png``. About
2 minutes for the check and 2 for the figures on a busy 2-core machine."""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).parent))

from corpus_review_draw import draw
from corpus_review_verify import STATED, VERIFY, stated

ROOT = Path(__file__).resolve().parent.parent
SOURCES = ("carla-towns", "esmini", "ika-roadgeneration", "scenariogeneration-examples")
#: CARLA codes drawn (worst finding of each), and the half width of the window where the default does not show it.
FIGURES = {
    "C001": 6.0,
    "C002": 4.0,
    "O002": 5.0,
    "K101": None,
    "K103": None,
    "L101": 6.0,
    "O001": 12.0,
    "O003": 20.0,
    "J101": 12.0,
}


def run_check(corpus: Path) -> dict[str, Any]:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "check.json"
        cmd = [str(Path(sys.executable).parent / "xodrcheck"), "check", str(corpus), "--format", "json", "-o", str(out)]
        subprocess.run(cmd, check=False)
        return json.loads(out.read_text(encoding="utf-8"))


def _source(path: str) -> str:
    return path.split("corpus/", 1)[-1].split("/", 1)[0]


def _table(rows: list[list[str]], head: list[str]) -> str:
    lines = ["| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def tables(report: dict[str, Any]) -> str:
    errors: dict[tuple[str, str, str], Counter[str]] = defaultdict(Counter)
    warnings: dict[tuple[str, str], Counter[str]] = defaultdict(Counter)
    per_file: Counter[str] = Counter()
    for f in report["files"]:
        src = _source(f["path"])
        for x in f["findings"]:
            if x["severity"] == "error":
                errors[(x["code"], x["name"], x["rule_uid"] or "-")][src] += 1
                per_file[f["path"].split("corpus/", 1)[-1]] += 1
            elif x["severity"] == "warning":
                warnings[(x["code"], x["name"])][src] += 1
    head = ["code", "name", "Annex F rule_uid", *SOURCES, "total"]
    rows = [
        [c, n, u.replace("asam.net:xodr:", ""), *(str(v[s] or "") for s in SOURCES), str(sum(v.values()))]
        for (c, n, u), v in sorted(errors.items())
    ]
    total = [sum(v[s] for v in errors.values()) for s in SOURCES]
    rows.append(["**all**", "", "", *(f"**{t}**" for t in total), f"**{sum(total)}**"])
    files: dict[str, list[str]] = defaultdict(list)
    for name, n in sorted(per_file.items()):
        files[_source(name)].append(f"{name.split('/')[-1]} {n}")
    clean = Counter(_source(f["path"]) for f in report["files"] if f["ok"])
    counted = Counter(_source(f["path"]) for f in report["files"])
    file_rows = [[s, f"{clean[s]} / {counted[s]}", ", ".join(files[s])] for s in SOURCES]
    warn_rows = [
        [c, n, *(str(v[s] or "") for s in SOURCES), str(sum(v.values()))] for (c, n), v in sorted(warnings.items())
    ]
    summary = report["summary"]
    return "\n\n".join(
        [
            f"{summary['files']} files, {summary['files_failed']} with errors: {summary['errors']} errors, "
            f"{summary['warnings']} warnings, {summary['infos']} infos.",
            "### Errors per code and source\n\n" + _table(rows, head),
            "### Errors per file (files without errors / files)\n\n" + _table(file_rows, ["source", "clean", "errors"]),
            "### Warnings per code and source\n\n" + _table(warn_rows, ["code", "name", *SOURCES, "total"]),
        ]
    )


def _pick(findings: list[dict[str, Any]], code: str) -> list[tuple[str, dict[str, Any]]]:
    """The worst finding by the number its message states, and the median one."""
    worse = STATED.get(code, ("", True))[1]

    def key(x: dict[str, Any]) -> tuple[float, str, str]:
        value = stated(x)
        return (0.0 if math.isnan(value) else value, x["file"], str(x["road"]))

    ranked = sorted(findings, key=key)
    if worse:
        ranked.reverse()
    return [("worst", ranked[0]), ("typical", ranked[len(ranked) // 2])]


def carla(report: dict[str, Any], out: Path, figures: bool) -> str:
    from lxml import etree

    from xodrcheck.reader import read

    by_code: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for f in report["files"]:
        if _source(f["path"]) != "carla-towns":
            continue
        for x in f["findings"]:
            if x["severity"] == "error":
                by_code[x["code"]].append({**x, "file": Path(f["path"]).stem, "path": f["path"]})
    docs: dict[str, Any] = {}
    rows = []
    for code in sorted(by_code):
        found = by_code[code]
        where = ", ".join(f"{t} {n}" for t, n in sorted(Counter(x["file"] for x in found).items()))
        for tag, x in _pick(found, code):
            if code not in VERIFY:
                rows.append([code, tag, where, x["file"], str(x["road"]), "", "", x["message"][:90]])
                where = ""
                continue
            if x["path"] not in docs:
                docs[x["path"]] = (read(x["path"]).document, etree.parse(x["path"]))
            doc, xml = docs[x["path"]]
            value, note, scene = VERIFY[code](doc, xml, x)
            shown = stated(x)
            rows.append(
                [
                    code,
                    tag,
                    where,
                    x["file"],
                    str(x["road"]),
                    "" if math.isnan(shown) else f"{shown:g}",
                    "" if value is None else f"{value:.4g}",
                    note,
                ]
            )
            if figures and tag == "worst" and code in FIGURES and scene is not None:
                half = FIGURES[code]
                if half is not None:
                    scene.half = half
                draw(doc, scene, out / f"{code}.png")
                print(f"{code}: {out / f'{code}.png'}", file=sys.stderr)
            where = ""
    head = ["code", "finding", "towns (errors)", "town", "road", "stated", "recomputed", "how"]
    return "### CARLA's errors recomputed\n\n" + _table(rows, head)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, default=ROOT.parent / "shared" / "corpus")
    parser.add_argument("--report", type=Path, help="a saved `xodrcheck check --format json` report of the corpus")
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "corpus-review")
    parser.add_argument("--save-report", type=Path, help="keep the check's JSON report here")
    parser.add_argument("--no-figures", action="store_true")
    args = parser.parse_args()
    report = json.loads(args.report.read_text(encoding="utf-8")) if args.report else run_check(args.corpus)
    if args.save_report:
        args.save_report.write_text(json.dumps(report), encoding="utf-8")
    args.out.mkdir(parents=True, exist_ok=True)
    text = tables(report) + "\n\n" + carla(report, args.out, not args.no_figures) + "\n"
    (args.out / "tables.md").write_text(text, encoding="utf-8")
    print(text)


if __name__ == "__main__":
    main()
