"""The HTML report and map in a real browser (headless Chromium through Playwright): rows, filters, clicks, hover,
rule documentation, no console error and no network request. Each test leaves a screenshot in ``out/browser/``."""

from __future__ import annotations

import json
import math
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from xodrcheck.check import check
from xodrcheck.cli import main
from xodrcheck.report import render
from xodrcheck.report.verdict import verdict

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

MAPS = {
    "town01": "carla-towns/OpenDrive/Town01.xodr",
    "multi_intersections": "esmini/resources/xodr/multi_intersections.xodr",
    "junction_m2a": "ika-roadgeneration/test/gt/junction_m2a.xodr",
}


@dataclass
class Opened:
    """A page opened from a file, with everything it logged and asked for."""

    page: object
    url: str
    console_errors: list[str] = field(default_factory=list)
    requests: list[str] = field(default_factory=list)

    def row_data(self, key: str = "severity", visible: bool | None = None) -> list[str]:
        return self.page.evaluate(
            """([key, visible]) => Array.from(document.querySelectorAll('.xc-row'))
                 .filter(r => visible === null || r.hidden !== visible).map(r => r.dataset[key])""",
            [key, visible],
        )

    def center(self, selector: str = ".xc-map") -> tuple[float, float]:
        x, y = self.page.eval_on_selector(selector, "e => [e.dataset.centerX, e.dataset.centerY]")
        return float(x), float(y)


def open_page(page, path: Path) -> Opened:
    opened = Opened(page, path.resolve().as_uri())
    page.on("console", lambda m: opened.console_errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: opened.console_errors.append(f"uncaught: {e}"))
    page.on("request", lambda r: opened.requests.append(r.url))
    page.on("websocket", lambda w: opened.requests.append(w.url))
    page.goto(opened.url)
    page.wait_for_selector(".xc-map[data-ready=true]", timeout=30_000)
    return opened


def assert_clean(opened: Opened) -> None:
    assert opened.console_errors == []
    assert opened.requests == [opened.url], "the page asked for something besides itself"


def drawn_fraction(opened: Opened) -> float:
    """Share of the map's pixels that are not background: the map drew something."""
    return opened.page.evaluate(
        """() => { const c = document.querySelector('.xc-map canvas.xc-base');
                   const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0;
                   for (let i = 0; i < d.length; i += 4)
                     if (d[i] !== 0xee || d[i + 1] !== 0xf0 || d[i + 2] !== 0xea) n++;
                   return n / (d.length / 4); }"""
    )


@pytest.fixture(scope="module")
def reports(corpus_dir: Path, tmp_path_factory) -> dict[str, tuple[Path, dict]]:
    """For each map: its HTML report and its JSON report (both rendered from one check)."""
    out = tmp_path_factory.mktemp("reports")
    made = {}
    for name, rel in MAPS.items():
        report = check(corpus_dir / rel)
        html = out / f"{name}.html"
        html.write_text(render("html", [report]), encoding="utf-8")
        made[name] = (html, json.loads(render("json", [report])))
    return made


def set_severities(page, wanted: set[str]) -> None:
    for box in page.query_selector_all("input[data-filter=severity]"):
        (box.check if box.get_attribute("value") in wanted else box.uncheck)()


@pytest.mark.parametrize("name", list(MAPS))
def test_report_rows_filters_click_and_screenshot(page, reports, name, artefacts):
    html, doc = reports[name]
    findings = doc["files"][0]["findings"]
    opened = open_page(page, html)
    assert len(opened.row_data()) == len(findings) > 0
    placed = [f for f in findings if f["x"] is not None and f["y"] is not None]
    assert page.evaluate("XC.views[0].map.markers.length") == len(placed)
    assert drawn_fraction(opened) > 0.02

    by_severity = Counter(f["severity"] for f in findings)
    for severity, count in by_severity.items():
        set_severities(page, {severity})
        assert opened.row_data(visible=True) == [severity] * count
        assert severity not in opened.row_data(visible=False)
        assert len(opened.row_data(visible=False)) == len(findings) - count
        hidden_markers = page.evaluate("XC.views[0].map.markers.filter(m => !m.hidden).map(m => m.severity)")
        assert set(hidden_markers) <= {severity}
    set_severities(page, {"error", "warning", "info"})
    assert len(opened.row_data(visible=True)) == len(findings)

    code, count = Counter(f["code"] for f in findings).most_common(1)[0]
    page.select_option("select[data-filter=code]", code)
    assert opened.row_data("code", visible=True) == [code] * count
    page.select_option("select[data-filter=code]", "")
    road = next(f["road"] for f in findings if f["road"] is not None)
    page.fill("input[data-filter=road]", road)
    assert opened.row_data("road", visible=True) == [road] * sum(1 for f in findings if f["road"] == road)
    page.fill("input[data-filter=road]", "")

    target = placed[len(placed) // 2] if placed else None
    assert target is not None, f"{name}: a map with a placed finding is needed for the click test"
    row = page.locator(f'.xc-row[data-x="{target["x"]}"][data-y="{target["y"]}"][data-code="{target["code"]}"]').first
    row.scroll_into_view_if_needed()
    row.locator(".xc-msg").click()
    x, y = opened.center()
    assert math.hypot(x - target["x"], y - target["y"]) < 5.0
    assert "xc-selected" in row.get_attribute("class")
    if target["road"] is not None and target["lane"] is not None:
        assert page.evaluate("XC.views[0].map.highlight.length") >= 1
    page.wait_for_timeout(300)
    page.screenshot(path=str(artefacts / f"report_{name}.png"))
    assert_clean(opened)


@pytest.mark.parametrize("name", ["town01"])
def test_rule_documentation_is_one_click_away(page, reports, name):
    html, _ = reports[name]
    opened = open_page(page, html)
    first = page.locator(".xc-row").first
    code = first.get_attribute("data-code")
    first.locator(".xc-doc").click()
    dialog = page.locator("#xc-doc")
    assert dialog.evaluate("d => d.open")
    assert dialog.locator(".xc-doc-title").inner_text().startswith(code)
    assert len(dialog.locator(".xc-doc-text").inner_text()) > 40
    page.keyboard.press("Escape")
    assert not dialog.evaluate("d => d.open")
    assert_clean(opened)


def lane_point(page) -> dict:
    """Centre the map on the middle of a wide lane outside junctions; its screen point, road and lane id."""
    return page.evaluate(
        """() => { const v = XC.views[0].map;
          for (const sec of v.sections) { if (sec.junction !== null || sec.n < 3) continue; const j = sec.n >> 1;
            for (const lane of sec.lanes) {
              const X = sec.xs, Y = sec.ys, a = lane.inner, b = lane.outer;
              if (Math.hypot(X[a][j] - X[b][j], Y[a][j] - Y[b][j]) < 2.5) continue;
              const x = (X[a][j] + X[b][j]) / 2, y = (Y[a][j] + Y[b][j]) / 2;
              v.centerOn(x + v.origin[0], y + v.origin[1], 20);
              const p = v.toScreen(x, y), r = v.canvas.getBoundingClientRect();
              return { x: r.left + p[0], y: r.top + p[1], road: sec.roadId, lane: lane.id, type: lane.type,
                       s: sec.s[j] };
            } } return null; }"""
    )


def test_view_hover_pan_zoom_and_reference_lines(page, corpus_dir, tmp_path, artefacts):
    out = tmp_path / "town03.html"
    assert main(["view", str(corpus_dir / "carla-towns/OpenDrive/Town03.xodr"), "-o", str(out)]) == 0
    opened = open_page(page, out)
    assert opened.row_data() == []
    legend = page.locator(".xc-legend").inner_text()
    assert "driving" in legend and "sidewalk" in legend and "junction" in legend
    page.screenshot(path=str(artefacts / "view_town03.png"))

    spot = lane_point(page)
    assert spot is not None
    page.mouse.move(spot["x"], spot["y"])
    tip = page.locator(".xc-map .xc-tip")
    text = tip.inner_text()
    assert f"road {spot['road']}" in text and f"lane {spot['lane']} · {spot['type']}" in text
    s_shown = float(text.split("\ns ")[1].split(" m")[0])
    assert abs(s_shown - spot["s"]) < 0.5

    x0, y0 = opened.center()
    scale = float(page.eval_on_selector(".xc-map", "e => e.dataset.scale"))
    page.mouse.move(700, 500)
    page.mouse.down()
    page.mouse.move(800, 450, steps=5)
    page.mouse.up()
    x1, y1 = opened.center()
    assert math.isclose(x1, x0 - 100 / scale, abs_tol=0.05) and math.isclose(y1, y0 - 50 / scale, abs_tol=0.05)
    page.mouse.wheel(0, -300)
    page.wait_for_timeout(100)
    assert float(page.eval_on_selector(".xc-map", "e => e.dataset.scale")) > scale

    page.click("button[data-tool=fit]")
    before = reference_pixels(page)
    page.check("input[data-tool=reference]")
    page.wait_for_timeout(200)
    assert reference_pixels(page) > before + 100
    page.screenshot(path=str(artefacts / "view_town03_reference.png"))
    assert_clean(opened)


def reference_pixels(page) -> int:
    return page.evaluate(
        """() => { const c = document.querySelector('.xc-map canvas.xc-base');
                   const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0;
                   for (let i = 0; i < d.length; i += 4) if (d[i] > 150 && d[i + 1] < 90 && d[i + 2] > 100) n++;
                   return n; }"""
    )


def test_several_files_give_one_page_with_an_index(page, corpus_dir, tmp_path, artefacts):
    files = [corpus_dir / MAPS["multi_intersections"], corpus_dir / "esmini/resources/xodr/fabriksgatan.xodr"]
    out = tmp_path / "two.html"
    main(["check", *map(str, files), "--format", "html", "-o", str(out)])
    opened = open_page(page, out)
    links = page.locator(".xc-index a")
    assert links.count() == 2
    assert page.locator("section.xc-file").count() == 2
    links.nth(1).click()
    page.wait_for_selector("#file-1 .xc-map[data-ready=true]", timeout=30_000)
    assert page.locator("#file-1 .xc-row").count() == len(check(files[1]).findings)
    assert page.locator("#file-0 .xc-row").count() == len(check(files[0]).findings)
    page.screenshot(path=str(artefacts / "report_two_files.png"), full_page=True)
    page.locator("#file-1 .xc-back").click()
    assert page.evaluate("document.getElementById('xc-index').getBoundingClientRect().top") < 5
    assert_clean(opened)


INFO_PIXELS = """() => { const c = document.querySelector('.xc-map canvas:not(.xc-base)');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0;
  for (let i = 0; i < d.length; i += 4)  // the info colour, #2e86de
    if (Math.abs(d[i] - 0x2e) < 12 && Math.abs(d[i + 1] - 0x86) < 12 && Math.abs(d[i + 2] - 0xde) < 12) n++;
  return n; }"""


def test_town03_report_says_fail_renders_help_and_keeps_info_markers_off(page, corpus_dir, tmp_path, artefacts):
    """Issue 26 on CARLA's Town03: the verdict on top, the basis on each row, the rule help rendered (no ``::`` or
    double backquotes), and its info markers off the map until asked for (they buried the junctions), while the list
    still shows the infos and a chosen info is drawn."""
    report = check(corpus_dir / "carla-towns/OpenDrive/Town03.xodr")
    html = tmp_path / "town03.html"
    html.write_text(render("html", [report]), encoding="utf-8")
    opened = open_page(page, html)
    top = page.locator(".xc-top .xc-verdict")
    assert top.get_attribute("data-verdict") == ("PASS" if report.ok else "FAIL")
    assert " ".join(top.inner_text().split()) == verdict([report]).replace(": ", " ", 1)
    assert page.locator(".xc-row .xc-basis").count() == len(report.findings)

    infos = [f for f in report.findings if str(f.severity) == "info" and f.x is not None]
    assert len(infos) > 100, "Town03 is chosen for its many info markers"
    drawn = "XC.views[0].map.markers.filter(m => m.severity === 'info' && !m.muted && !m.hidden).length"
    assert page.evaluate(drawn) == 0
    assert page.evaluate(INFO_PIXELS) == 0
    assert len(opened.row_data(visible=True)) == len(report.findings)  # the list shows them all
    page.screenshot(path=str(artefacts / "report_town03.png"))

    page.check("input[data-tool=info-markers]")
    page.wait_for_timeout(200)
    assert page.evaluate(drawn) == len(infos) and page.evaluate(INFO_PIXELS) > 1000
    page.screenshot(path=str(artefacts / "report_town03_infos.png"))
    page.uncheck("input[data-tool=info-markers]")
    page.wait_for_timeout(200)
    assert page.evaluate(INFO_PIXELS) == 0

    row = page.locator(".xc-row[data-severity=info]:not([data-x=''])").first
    row.scroll_into_view_if_needed()
    row.locator(".xc-msg").click()
    page.wait_for_timeout(200)
    assert page.evaluate(INFO_PIXELS) > 20  # the chosen info is drawn though info markers are off

    page.locator(".xc-row .xc-doc").first.click()
    text = page.locator("#xc-doc .xc-doc-text")
    assert text.locator("p").count() >= 2 and text.locator("pre").count() >= 1 and text.locator("code").count() >= 1
    shown = text.inner_text()
    assert "``" not in shown and "::" not in shown
    assert "basis: " in page.locator("#xc-doc .xc-doc-meta").inner_text()
    page.screenshot(path=str(artefacts / "report_town03_help.png"))
    assert_clean(opened)
