"""Browser tests drive the operating system's Chromium (Debian's ``chromium``, installed by ``scripts/setup``) through
Playwright (pytest-playwright's ``page`` fixture); no browser is ever downloaded. A missing Chromium fails the tests
with a message saying how to install it. ``$XODRCHECK_CHROMIUM`` names another executable."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[3]
#: Screenshots of the pages the tests opened, for people to look at.
ARTEFACTS = REPO / "out" / "browser"
CHROMIUM = Path(os.environ.get("XODRCHECK_CHROMIUM", "/usr/bin/chromium"))
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args: dict) -> dict:
    if not (CHROMIUM.is_file() and os.access(CHROMIUM, os.X_OK)):
        pytest.fail(
            f"Chromium not found at {CHROMIUM}: the browser tests need the operating system's Chromium; run "
            "scripts/setup (it runs `apt-get install chromium`) or set XODRCHECK_CHROMIUM to a Chromium executable"
        )
    return {**browser_type_launch_args, "executable_path": str(CHROMIUM), "args": FLAGS, "headless": True}


@pytest.fixture(scope="session")
def browser_context_args(browser_context_args: dict) -> dict:
    return {**browser_context_args, "viewport": {"width": 1400, "height": 900}, "device_scale_factor": 1}


@pytest.fixture(scope="session")
def artefacts() -> Path:
    ARTEFACTS.mkdir(parents=True, exist_ok=True)
    return ARTEFACTS
