"""Routes and unreachable lanes in the map page, in headless Chromium (see ``conftest.py``): a route between two
clicked lanes is found, measured and drawn; a map with a lane no route reaches shades it. Screenshots go to
``out/browser/``."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from tests.xodrcheck.mapview.test_browser import assert_clean, open_page
from xodrcheck.cli import main

pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[3]
T_JUNCTION = REPO / "examples" / "t-junction.xodr"
OPENING = REPO / "tests" / "xodrcheck" / "rules" / "fixtures" / "lane-unreachable" / "fail.xodr"


def _view(source: Path, tmp_path: Path) -> Path:
    out = tmp_path / f"{source.stem}.html"
    assert main(["view", str(source), "-o", str(out)]) == 0
    return out


def _click_world(page, x: float, y: float) -> None:
    """Click the map at world point (x, y)."""
    px, py = page.evaluate(
        """([x, y]) => { const v = XC.views[0].map, r = v.canvas.getBoundingClientRect();
                         const p = v.toScreen(x - v.origin[0], y - v.origin[1]);
                         return [r.left + p[0], r.top + p[1]]; }""",
        [x, y],
    )
    page.mouse.click(px, py)


def _route(page) -> dict:
    return page.eval_on_selector(".xc-map", "e => ({...e.dataset})")


def test_a_route_between_two_clicked_lanes(page, tmp_path, artefacts):
    opened = open_page(page, _view(T_JUNCTION, tmp_path))
    page.check(".xc-map [data-tool=route]")
    _click_world(page, -60.0, -1.75)  # road 1 lane -1, driven east
    _click_world(page, -1.75, -60.0)  # road 3 lane 1, driven south
    got = _route(page)
    # all of road 1 lane -1 (100 m), the right turn on connecting road 102 (lane centre radius 8.25 m), all of road 3
    assert got["routeFound"] == "true" and got["routeLanes"] == "3"
    assert float(got["routeLength"]) == pytest.approx(200 + 8.25 * math.pi / 2, abs=0.2)
    assert "route: " in page.inner_text(".xc-route-status")
    page.screenshot(path=str(artefacts / "route_t_junction.png"))
    _click_world(page, -60.0, -1.75)
    _click_world(page, -60.0, 1.75)  # road 1 lane 1: no connection turns back
    got = _route(page)
    assert got["routeFound"] == "false" and got["routeLength"] == ""
    assert page.inner_text(".xc-route-status").startswith("no route from road 1 lane -1 to road 1 lane 1")
    assert got["unreachable"] == "0" and page.query_selector(".xc-map [data-tool=unreachable]") is None
    assert_clean(opened)


def _reddish(page) -> int:
    """Pixels of the overlay canvas that are red (the shading), not grey or green."""
    return page.evaluate(
        """() => { const c = document.querySelector('.xc-map canvas:not(.xc-base)');
                   const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0;
                   for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && d[i] > d[i + 1] + 60) n++;
                   return n; }"""
    )


def test_lanes_no_route_reaches_are_shaded(page, tmp_path, artefacts):
    opened = open_page(page, _view(OPENING, tmp_path))
    assert _route(page)["unreachable"] == "1"  # lane -2 opening behind a solid line
    page.screenshot(path=str(artefacts / "route_unreachable.png"))
    shaded = _reddish(page)
    assert shaded > 100
    page.uncheck(".xc-map [data-tool=unreachable]")
    page.wait_for_timeout(100)
    cleared = _reddish(page)
    assert cleared == 0
    assert_clean(opened)
