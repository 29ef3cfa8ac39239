"""The README's picture of the HTML report: CARLA's Town03 checked, the report opened in the OS's Chromium, the first
error with a map position clicked (the map zooms to it and highlights its lane), saved as a small palette PNG.

    .venv/bin/python docs/report/screenshot.py [--corpus ../shared/corpus] [-o docs/report/report.png]
"""

from __future__ import annotations

import argparse
import os
import tempfile
from pathlib import Path

from PIL import Image
from playwright.sync_api import sync_playwright

from xodrcheck.check import check
from xodrcheck.report import render

REPO = Path(__file__).resolve().parents[2]
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking"]
FLAGS += ["--disable-component-update", "--disable-sync", "--no-first-run"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    parser.add_argument("--corpus", type=Path, default=default)
    parser.add_argument("-o", "--output", type=Path, default=REPO / "docs" / "report" / "report.png")
    parser.add_argument("--scale", type=float, default=2.5, help="map zoom after the click, pixels per metre")
    args = parser.parse_args()
    html = Path(tempfile.mkdtemp()) / "Town03.html"
    html.write_text(render("html", [check(args.corpus / "carla-towns/OpenDrive/Town03.xodr")]), encoding="utf-8")
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS, headless=True)
        page = browser.new_page(viewport={"width": 1280, "height": 760})
        page.goto(html.as_uri())
        page.wait_for_selector(".xc-map[data-ready=true]")
        page.locator('.xc-row[data-severity=error]:not([data-x=""])').first.locator(".xc-msg").click()
        page.evaluate("s => { const v = XC.views[0].map; v.setView(v.cx, v.cy, s); }", args.scale)
        page.wait_for_timeout(400)
        shot = html.with_suffix(".png")
        page.screenshot(path=str(shot))
        browser.close()
    Image.open(shot).convert("RGB").quantize(colors=96).save(args.output, optimize=True)
    print(f"{args.output}: {args.output.stat().st_size / 1024:.0f} KiB")


if __name__ == "__main__":
    main()
