"""The wheel ships the OpenDRIVE schemas as package data, and an installed tree finds them through importlib.resources.

The wheel is built from a copy of the source tree so that the build leaves nothing behind in the checkout.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
SCHEMAS = REPO / "schemas"

pytestmark = pytest.mark.slow


def _schema_files() -> set[str]:
    """Schema files of the source tree, relative to ``schemas/``."""
    files = {p.relative_to(SCHEMAS).as_posix() for p in SCHEMAS.rglob("*.xsd")}
    assert len(files) > 20, "the source tree should hold the XSDs of OpenDRIVE 1.1 to 1.9.0"
    return files | {"NOTICE.md"}


@pytest.fixture(scope="module")
def source(tmp_path_factory) -> Path:
    """A copy of the checkout's sources (what the wheel is built from)."""
    src = tmp_path_factory.mktemp("source") / "src"
    shutil.copytree(
        REPO,
        src,
        ignore=shutil.ignore_patterns(
            ".git", ".venv*", "build", "dist", "*.egg-info", "__pycache__", ".pytest_cache", ".hypothesis", "out"
        ),
    )
    return src


@pytest.fixture(scope="module")
def wheel(source: Path, tmp_path_factory) -> Path:
    tmp = tmp_path_factory.mktemp("wheel")
    out = tmp / "dist"
    proc = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", str(source), "--no-deps", "--no-build-isolation", "-q", "-w", str(out)],
        check=False,
        capture_output=True,
        text=True,
        cwd=tmp,
    )
    assert proc.returncode == 0, f"pip wheel failed:\n{proc.stdout}\n{proc.stderr}"
    wheels = list(out.glob("*.whl"))
    assert len(wheels) == 1, wheels
    return wheels[0]


def test_wheel_contains_every_schema_and_the_notice(wheel: Path):
    with zipfile.ZipFile(wheel) as zf:
        names = set(zf.namelist())
    shipped = {n.removeprefix("xodrcheck/schemas/") for n in names if n.startswith("xodrcheck/schemas/")}
    missing = _schema_files() - shipped
    assert not missing, f"not in the wheel: {sorted(missing)}"


def test_wheel_contains_every_package_of_the_source_tree(wheel: Path, source: Path):
    """A subpackage missing from pyproject's package list would install without its modules."""
    with zipfile.ZipFile(wheel) as zf:
        names = set(zf.namelist())
    modules = {
        p.relative_to(source).as_posix()
        for top in ("xodrcheck", "junctionart")
        for p in (source / top).rglob("*.py")
        if "__pycache__" not in p.parts
    }
    missing = modules - names
    assert not missing, f"not in the wheel (add their packages to [tool.setuptools] packages): {sorted(missing)}"


def test_wheel_installs_no_top_level_name_but_the_two_tools(wheel: Path):
    """A wheel that installed a top-level ``fuzz`` (or ``tests``, ``benchmarks``) would squat on names in every
    user's site-packages; the dist-info directory is the only other entry."""
    with zipfile.ZipFile(wheel) as zf:
        tops = {n.split("/", 1)[0] for n in zf.namelist()}
    assert {t for t in tops if not t.endswith(".dist-info")} == {"xodrcheck", "junctionart"}
    assert "junctionart/py.typed" in zf.namelist() and "xodrcheck/py.typed" in zf.namelist()
    assert "junctionart/fuzz/regressions.json" in zf.namelist()


def test_installed_tree_finds_schemas_through_importlib_resources(wheel: Path, tmp_path: Path):
    target = tmp_path / "site"
    proc = subprocess.run(
        [sys.executable, "-m", "pip", "install", "--no-deps", "-q", "--target", str(target), str(wheel)],
        check=False,
        capture_output=True,
        text=True,
    )
    assert proc.returncode == 0, f"pip install --target failed:\n{proc.stdout}\n{proc.stderr}"
    # -S: no site-packages, so neither the editable install nor the checkout can answer instead of the installed tree.
    probe = (
        "import importlib.resources, json, xodrcheck\n"
        "root = importlib.resources.files('xodrcheck.schemas')\n"
        "def walk(node, prefix=''):\n"
        "    for child in node.iterdir():\n"
        "        if child.is_dir():\n"
        "            yield from walk(child, prefix + child.name + '/')\n"
        "        else:\n"
        "            yield prefix + child.name\n"
        "print(json.dumps({'package': xodrcheck.__file__, 'files': sorted(walk(root)),\n"
        "                  'notice': root.joinpath('NOTICE.md').read_text(encoding='utf-8')[:200]}))\n"
    )
    proc = subprocess.run(
        [sys.executable, "-S", "-c", probe],
        check=False,
        capture_output=True,
        text=True,
        cwd=tmp_path,
        env={"PYTHONPATH": str(target), "PATH": "/usr/bin:/bin"},
    )
    assert proc.returncode == 0, proc.stderr
    found = json.loads(proc.stdout)
    assert Path(found["package"]).resolve().is_relative_to(target.resolve()), found["package"]
    missing = _schema_files() - set(found["files"])
    assert not missing, f"importlib.resources does not find: {sorted(missing)}"
    assert found["notice"].strip(), "NOTICE.md is empty"


def test_wheel_contains_the_map_page_assets(wheel: Path):
    """The HTML report's scripts, styles and page template are package data (read by xodrcheck.mapview.page)."""
    from xodrcheck.mapview.page import SCRIPTS

    with zipfile.ZipFile(wheel) as zf:
        names = set(zf.namelist())
    wanted = {f"xodrcheck/mapview/static/{name}" for name in (*SCRIPTS, "style.css", "page.html")}
    assert wanted <= names, f"not in the wheel: {sorted(wanted - names)}"
