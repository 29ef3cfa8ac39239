"""HTML report speed and size: a generated 5 km x 5 km map's report opens and becomes interactive in headless
Chromium within 3 s, and every report stays within about 3x the size of its ``.xodr``.

Generates the map (``junctionart generate``, in a subprocess), checks it and writes its HTML report, then opens the
report ``--repeats`` times in the OS's Chromium (Playwright, ``/usr/bin/chromium``, the flags of the browser tests)
and prints the time from navigation until the map is drawn, zooms under the mouse wheel and (when there are findings)
moves to a placed finding clicked in the list (median and range; absolute seconds on this machine), with the page's
own split (decoding, first drawing). Then the time to draw a frame at a few zooms, and a gesture frame (the last frame
moved and scaled). With the CARLA towns of the corpus (``--towns``, default on), prints each report's size as a ratio
to its ``.xodr``, and the CPU time of writing the HTML as a ratio to the check's.

    python benchmarks/bench_html.py [--size 5000] [--seed 0] [--repeats 3] [--no-towns] [--keep DIR]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from xodrcheck.check import check
from xodrcheck.report import render

REPO = Path(__file__).resolve().parents[1]
CHROMIUM = os.environ.get("XODRCHECK_CHROMIUM", "/usr/bin/chromium")
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
TARGET_S = 3.0
SIZE_TARGET = 3.0


def cpu_timed(fn):
    start = time.process_time()
    value = fn()
    return time.process_time() - start, value


def timed(fn):
    start = time.perf_counter()
    value = fn()
    return time.perf_counter() - start, value


def report_of(xodr: Path, out: Path) -> tuple[float, float, int]:
    """Check a file and write its HTML report; (check CPU s, HTML CPU s, findings). CPU time of this process: what
    the two cost relative to each other, less disturbed than wall time by other work on the machine."""
    check_s, report = cpu_timed(lambda: check(xodr))
    html_s, page = cpu_timed(lambda: render("html", [report]))
    out.write_text(page, encoding="utf-8")
    return check_s, html_s, len(report.findings)


def generate(size: float, seed: int, folder: Path) -> Path:
    path = folder / f"generated_{int(size)}m_seed{seed}.xodr"
    cmd = [sys.executable, "-m", "junctionart", "generate", "--size", f"{size:g}x{size:g}", "--seed", str(seed)]
    elapsed, _ = timed(lambda: subprocess.run([*cmd, "-q", "-o", str(path)], check=True))
    print(f"generated {size / 1000:g} km x {size / 1000:g} km map (seed {seed}) in {elapsed:.1f} s: {path}")
    return path


MOVED = "b => { const d = document.querySelector('.xc-map').dataset; return d.scale + d.centerX !== b; }"
ZOOM_PROBE = """async (scale) => {
  const v = XC.views[0].map; v.fit(); if (scale) v.setView(v.cx, v.cy, scale);
  const frame = (quick) => { const t = performance.now();
    v.setView(v.cx + 20 / v.scale, v.cy, v.scale, quick); if (quick) v.renderQuick(); else v.render();
    v.bctx.getImageData(0, 0, 1, 1); return performance.now() - t; };
  frame(false); const times = []; for (let i = 0; i < 9; i++) times.push(frame(false));
  const quick = []; if (v.slow) for (let i = 0; i < 9; i++) quick.push(frame(true));
  const med = (a) => a.length ? a.sort((x, y) => x - y)[a.length >> 1] : null;
  return [v.scale, med(times), med(quick)];
}"""


def interact(page) -> None:
    """Interactive: the wheel zooms the map, and a click on a finding (if any) selects it and moves the map there."""
    scale = page.eval_on_selector(".xc-map", "e => e.dataset.scale")
    box = page.locator(".xc-map canvas:not(.xc-base)").bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.wheel(0, -200)
    page.wait_for_function("s => document.querySelector('.xc-map').dataset.scale !== s", arg=scale)
    placed = page.locator('.xc-row:not([data-x=""])')
    if placed.count():
        before = page.eval_on_selector(".xc-map", "e => e.dataset.scale + e.dataset.centerX")
        placed.first.locator(".xc-msg").click()
        page.wait_for_function(MOVED, arg=before)


def open_times(html: Path, repeats: int) -> None:
    from playwright.sync_api import sync_playwright

    results, splits = [], []
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS, headless=True)
        for _ in range(repeats):
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            start = time.perf_counter()
            page.goto(html.resolve().as_uri())
            page.wait_for_selector(".xc-map[data-ready=true]", timeout=60_000)
            interact(page)
            results.append(time.perf_counter() - start)
            splits.append(page.evaluate("XC.views[0].map.timings"))
            page.close()
        page = browser.new_page(viewport={"width": 1400, "height": 900})
        page.goto(html.resolve().as_uri())
        page.wait_for_selector(".xc-map[data-ready=true]", timeout=60_000)
        frames = [page.evaluate(ZOOM_PROBE, scale) for scale in (None, 1.0, 5.0, 30.0)]
        browser.close()
    median = statistics.median(results)
    print(
        f"open to interactive: median {median:.2f} s (range {min(results):.2f}-{max(results):.2f} s, {repeats} runs; "
        f"target {TARGET_S:g} s: {'met' if median <= TARGET_S else 'NOT met'})"
    )
    last = splits[-1]
    print(
        f"  in the page: map decoded in {last['decode'] / 1000:.2f} s, first drawing {last['draw'] / 1000:.2f} s, "
        f"drawn {last['ready'] / 1000:.2f} s after navigation"
    )
    for scale, full, quick in frames:
        gesture = f", gesture frame {quick:.0f} ms" if quick is not None else ""
        print(f"  frame at {scale:7.3f} px/m: {full:.0f} ms{gesture}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    parser.add_argument("--corpus", type=Path, default=default)
    parser.add_argument("--size", type=float, default=5000.0, help="generated map side in metres")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--no-towns", action="store_true", help="skip the size ratios of the CARLA towns")
    parser.add_argument("--keep", type=Path, help="write the maps and reports here (default: a temporary folder)")
    args = parser.parse_args()
    if not Path(CHROMIUM).is_file():
        raise SystemExit(f"Chromium not found at {CHROMIUM}: run scripts/setup (apt-get install chromium)")
    folder = args.keep or Path(tempfile.mkdtemp(prefix="bench_html_"))
    folder.mkdir(parents=True, exist_ok=True)

    rows = []
    if not args.no_towns:
        for town in sorted((args.corpus / "carla-towns").rglob("Town*.xodr")):
            out = folder / f"{town.stem}.html"
            check_s, html_s, n = report_of(town, out)
            rows.append((town.stem, town, out, check_s, html_s, n))
    xodr = generate(args.size, args.seed, folder)
    out = folder / f"{xodr.stem}.html"
    check_s, html_s, n = report_of(xodr, out)
    rows.append((xodr.stem, xodr, out, check_s, html_s, n))

    print(f"report size / .xodr size (target about {SIZE_TARGET:g}x); check and HTML: CPU seconds of this process")
    for name, source, html, check_s, html_s, n in rows:
        ratio = html.stat().st_size / source.stat().st_size
        print(
            f"  {name:<26} {source.stat().st_size / 1e6:6.2f} MB -> {html.stat().st_size / 1e6:6.2f} MB "
            f"({ratio:.2f}x; {n} findings)   check {check_s:5.1f} s, HTML {html_s:5.1f} s ({html_s / check_s:.2f}x)"
        )
    print(f"opening {out.name} in {CHROMIUM}")
    open_times(out, args.repeats)


if __name__ == "__main__":
    main()
