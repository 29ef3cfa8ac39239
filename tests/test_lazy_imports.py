"""Structural test of the lazy imports: which third-party packages a command loads (run in a fresh interpreter, no
timing). Heavy packages load only on the paths that need them: shapely for the overlap and junction geometry rules,
trimesh for mesh export, matplotlib for figures, tqdm for progress bars on a terminal; scipy only for spirals."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

import xodrcheck.cli
from xodrcheck.cli import COMMANDS, command_module

#: Third-party packages whose loading the tests watch.
WATCHED = (
    "numpy",
    "scipy",
    "shapely",
    "trimesh",
    "matplotlib",
    "lxml",
    "xmlschema",
    "elementpath",
    "tqdm",
    "dask",
    "distributed",
    "junctionart",
    "xodrcheck",
)

_PROBE = """
import atexit, json, sys
out = sys.argv[1]
sys.argv = [sys.argv[2], *sys.argv[3:]]

def report():
    with open(out, 'w') as f:
        json.dump(sorted(sys.modules), f)

atexit.register(report)
try:
    from {module} import main
    code = main()
except SystemExit as exc:
    code = exc.code
sys.exit(code or 0)
"""

# A file without spirals: lines and an arc, one lane each way, OpenDRIVE 1.6 (schema checked by lxml).
PLAIN = """<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="6" name="plain"/>
  <road id="1" length="30" junction="-1">
    <link/>
    <planView>
      <geometry s="0" x="0" y="0" hdg="0" length="20"><line/></geometry>
      <geometry s="20" x="20" y="0" hdg="0" length="10"><arc curvature="0.01"/></geometry>
    </planView>
    <lanes>
      <laneSection s="0">
        <left><lane id="1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
        <center><lane id="0" type="none" level="false"/></center>
        <right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
      </laneSection>
    </lanes>
  </road>
</OpenDRIVE>
"""


def modules(tmp_path: Path, module: str, *argv: str) -> set[str]:
    """Every module loaded by ``module.main()`` run with ``argv`` in a new interpreter."""
    out = tmp_path / "modules.json"
    probe = _PROBE.format(module=module)
    subprocess.run(
        [sys.executable, "-c", probe, str(out), *argv], cwd=tmp_path, capture_output=True, timeout=300, check=False
    )
    return set(json.loads(out.read_text()))


def loaded(tmp_path: Path, module: str, *argv: str) -> set[str]:
    """Top-level packages of :data:`WATCHED` loaded by ``module.main()`` run with ``argv`` in a new interpreter."""
    return {name.split(".")[0] for name in modules(tmp_path, module, *argv)} & set(WATCHED)


@pytest.fixture
def plain(tmp_path: Path) -> Path:
    path = tmp_path / "plain.xodr"
    path.write_text(PLAIN)
    return path


def test_help_loads_no_third_party_package(tmp_path: Path) -> None:
    assert loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "--help") == {"xodrcheck"}
    assert loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "check", "--help") == {"xodrcheck"}


def test_help_loads_no_module_of_the_checker(tmp_path: Path) -> None:
    # the package's __init__ names the engine lazily: no model, configuration, rules or engine for the bare usage
    ours = {m for m in modules(tmp_path, "xodrcheck.cli", "xodrcheck", "--help") if m.split(".")[0] == "xodrcheck"}
    assert ours == {"xodrcheck", "xodrcheck.cli"}


def test_plain_check_loads_what_the_rules_need(tmp_path: Path, plain: Path) -> None:
    # numpy and lxml for reading and geometry, shapely for the overlap rules; no scipy (no spiral), no mesh export,
    # no figures, no XSD 1.1 validator (a 1.6 file), no progress bar (one file, not a terminal), no generator
    mods = loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(plain))
    assert mods == {"xodrcheck", "numpy", "lxml", "shapely"}


def test_plain_check_loads_no_slow_module_it_does_not_use(tmp_path: Path, plain: Path) -> None:
    names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(plain))
    assert "xodrcheck.rules.overlap" in names and "numpy" in names and "xodrcheck.support.memory" in names
    # ctypes.util (and its subprocess) only found the C library for malloc_trim; no configuration file: no TOML parser
    assert {"ctypes.util", "subprocess", "tomllib", "tomli"}.isdisjoint(names)
    # the XSD 1.1 fast path and its plan only for 1.8/1.9 files
    lazy = {"xodrcheck.schema.fast", "xodrcheck.schema.plan"}
    assert lazy & names == set()
    assert "xodrcheck.schema.validate" in names and "xodrcheck.standard" in names


#: Modules that read or model junction parts, road objects and signals: a file without any does not load them.
FEATURE_MODULES = {
    "xodrcheck.model.junction_parts",
    "xodrcheck.geometry.junction_grid",
    "xodrcheck.model.objects",
    "xodrcheck.reader.objects",
    "xodrcheck.geometry.object_shape",
    "xodrcheck.geometry.object_place",
    "xodrcheck.model.signals",
    "xodrcheck.model.surface",
    "xodrcheck.model.railroad",
}

# PLAIN with one of each: a junction with a part (a priority), an object and a signal (and their ids' references left
# dangling: findings do not matter here, only what loads)
FEATURES = PLAIN.replace(
    "    </lanes>\n",
    "    </lanes>\n"
    '    <objects><object id="5" s="5" t="4" type="pole" zOffset="0" orientation="none"/></objects>\n'
    '    <signals><signal id="6" s="5" t="-4" dynamic="no" orientation="+" zOffset="0" country="DE" type="206" '
    'subtype="-1" value="-1"/></signals>\n',
).replace("</OpenDRIVE>", '  <junction id="9" name="j"><priority high="1" low="2"/></junction>\n</OpenDRIVE>')


def test_plain_check_loads_no_junction_object_or_signal_module(tmp_path: Path, plain: Path) -> None:
    # the junction, object and signal rules are loaded and run; what they would read loads only for a file that
    # has junction parts, objects or signals (Context.road_objects, the model's junction parts and signals)
    names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(plain))
    rules = {"xodrcheck.rules.junction_roles", "xodrcheck.rules.junction_entries", "xodrcheck.rules.object_geometry"}
    assert rules | {"xodrcheck.rules.signal_control", "xodrcheck.rules.shared.junction_shapes"} <= names
    assert FEATURE_MODULES.isdisjoint(names)


def test_plain_check_of_any_version_loads_no_junction_object_or_signal_module(tmp_path: Path) -> None:
    # 1.7 and 1.8 run rules a 1.6 file does not (validity orientation, surface volumes, the junction grid's entries);
    # an empty <objects/> holds nothing to read
    for minor in (7, 8):
        path = tmp_path / f"plain-1.{minor}.xodr"
        path.write_text(PLAIN.replace('revMinor="6"', f'revMinor="{minor}"'))
        names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(path))
        assert "xodrcheck.rules.junction_entries" in names and "xodrcheck.rules.object_surfaces" in names
        assert FEATURE_MODULES.isdisjoint(names), (minor, FEATURE_MODULES & names)
    path = tmp_path / "empty-objects.xodr"
    path.write_text(PLAIN.replace("    </lanes>\n", "    </lanes>\n    <objects><!-- none --></objects>\n"))
    names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(path))
    assert FEATURE_MODULES.isdisjoint(names), FEATURE_MODULES & names


def test_check_of_junctions_objects_and_signals_loads_their_modules(tmp_path: Path) -> None:
    path = tmp_path / "features.xodr"
    path.write_text(FEATURES)
    names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(path))
    assert {"xodrcheck.model.junction_parts", "xodrcheck.model.objects", "xodrcheck.reader.objects"} <= names
    assert "xodrcheck.model.signals" in names  # the signal rules read the document's signals


def test_check_without_overlap_rules_loads_no_shapely(tmp_path: Path, plain: Path) -> None:
    mods = loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "check", "--ignore", "overlap", str(plain))
    assert mods == {"xodrcheck", "numpy", "lxml"}


def test_scipy_loads_only_for_spirals(tmp_path: Path, plain: Path) -> None:
    # the arc becomes a spiral from curvature 0 whose evaluation takes the Fresnel path (scipy.special.fresnel)
    spiral = tmp_path / "spiral.xodr"
    spiral.write_text(PLAIN.replace('<arc curvature="0.01"/>', '<spiral curvStart="0" curvEnd="0.01"/>'))
    assert "scipy" in loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "info", str(spiral))
    assert "scipy" not in loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "info", str(plain))


def test_the_spiral_fixture_takes_the_fresnel_path() -> None:
    # what makes the test above meaningful: a = 0, b = 0.5 * 0.01 * 10 over the whole element
    import numpy as np

    from xodrcheck.geometry import spiral

    b = 0.5 * 0.01 * 10.0
    assert spiral.uses_fresnel(np.array([0.0]), np.array([b])).all()


def test_import_xodrcheck_loads_no_third_party_package(tmp_path: Path) -> None:
    out = tmp_path / "modules.json"
    code = f"import json, sys; import xodrcheck; json.dump(sorted(sys.modules), open({str(out)!r}, 'w'))"
    subprocess.run([sys.executable, "-c", code], check=True, timeout=300)
    names = set(json.loads(out.read_text()))
    assert {m.split(".")[0] for m in names} & set(WATCHED) == {"xodrcheck"}
    assert {m for m in names if m.startswith("xodrcheck.")} == set()  # every public name loads on first use


def test_generate_loads_no_checker_scipy_or_figures(tmp_path: Path) -> None:
    mods = loaded(tmp_path, "junctionart.cli", "junctionart", "generate", "--size", "300x300", "-q", "-o", "m.xodr")
    assert (tmp_path / "m.xodr").is_file()
    assert mods <= {"junctionart", "numpy", "shapely", "xodrcheck"}
    assert {"scipy", "matplotlib", "trimesh", "lxml", "tqdm"}.isdisjoint(mods)


def test_generate_imports_no_other_subcommand(tmp_path: Path) -> None:
    names = modules(tmp_path, "junctionart.cli", "junctionart", "generate", "--size", "300x300", "-q", "-o", "m.xodr")
    assert "junctionart.cli" in names and (tmp_path / "m.xodr").is_file()
    others = {"junctionart.render", "junctionart.era", "junctionart.intersection_cli", "junctionart.search.cli"}
    assert others.isdisjoint(names)
    assert {"multiprocessing", "concurrent", "csv"}.isdisjoint(name.split(".")[0] for name in names)  # era's


def test_command_table_matches_the_modules() -> None:
    for name, help_text in COMMANDS.items():
        module = command_module(name)
        assert (name, help_text) == (module.NAME, module.HELP)
    assert tuple(COMMANDS) == xodrcheck.cli.SUBCOMMANDS


def test_junctionart_help_loads_no_stage_of_the_generator(tmp_path: Path) -> None:
    names = modules(tmp_path, "junctionart.cli", "junctionart", "--help")
    assert {m for m in names if m.split(".")[0] == "junctionart"} <= {
        "junctionart",
        "junctionart.cli",
        "junctionart.errors",
        "junctionart.params",
    }
    assert "junctionart.cli" in names
    assert {m.split(".")[0] for m in names} & set(WATCHED) <= {"junctionart", "xodrcheck"}
