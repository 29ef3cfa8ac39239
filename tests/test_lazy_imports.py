"""Structural test of the lazy imports: which third-party packages a command loads (run in a fresh interpreter, no
timing). Heavy packages load only on the paths that need them: shapely for the overlap and junction geometry rules,
trimesh for mesh export, matplotlib for figures, tqdm for progress bars on a terminal; scipy never (the checker's
Fresnel integrals for spirals are its own)."""

from __future__ import annotations

import gc
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

import xodrcheck.cli
from xodrcheck import startup
from xodrcheck.cli import COMMANDS, command_module
from xodrcheck.startup import THREAD_VARIABLES, one_blas_thread

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

# at exit: the process's own command line ends the process when done (xodrcheck.startup.finish), after the atexit
# handlers
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
    assert ours == {"xodrcheck", "xodrcheck.cli", "xodrcheck.startup"}


def test_plain_check_loads_what_the_rules_need(tmp_path: Path, plain: Path) -> None:
    # numpy and lxml for reading and geometry, shapely for the overlap rules; no scipy (no spiral), no mesh export,
    # no figures, no XSD 1.1 validator (a 1.6 file), no progress bar (one file, not a terminal), no generator
    mods = loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(plain))
    assert mods == {"xodrcheck", "numpy", "lxml", "shapely"}


def test_plain_check_loads_no_slow_module_it_does_not_use(tmp_path: Path, plain: Path) -> None:
    names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(plain))
    assert "xodrcheck.rules.overlap" in names and "numpy" in names and "xodrcheck.memory" in names
    # np.unique imports numpy.ma to ask whether its array is masked (the geometry uses xodrcheck.arrays.unique);
    # ctypes.util (and its subprocess) only found the C library for malloc_trim; no configuration file: no TOML parser
    assert {"numpy.ma", "ctypes.util", "subprocess", "tomllib", "tomli"}.isdisjoint(names)
    # the package's data files are read from its folder (no importlib.resources readers, no zipfile), the XSD 1.1
    # fast path and its plan only for 1.8/1.9 files, tempfile only to write an output file
    lazy = {"zipfile", "importlib.readers", "tempfile", "xodrcheck.schema_fast", "xodrcheck.schema_plan"}
    assert lazy & names == set()
    assert "xodrcheck.schema" in names and "xodrcheck.standard" in names


#: Modules that read or model junctions, road objects and signals: a file without any does not load them.
FEATURE_MODULES = {
    "xodrcheck.junction_elements",
    "xodrcheck.junction_grid",
    "xodrcheck.objects.model",
    "xodrcheck.objects.read",
    "xodrcheck.objects.shape",
    "xodrcheck.objects.place",
    "xodrcheck.signals",
}

# PLAIN with one of each: a junction, an object and a signal (and their ids' references left dangling: findings
# do not matter here, only what loads)
FEATURES = PLAIN.replace(
    "    </lanes>\n",
    "    </lanes>\n"
    '    <objects><object id="5" s="5" t="4" type="pole" zOffset="0" orientation="none"/></objects>\n'
    '    <signals><signal id="6" s="5" t="-4" dynamic="no" orientation="+" zOffset="0" country="DE" type="206" '
    'subtype="-1" value="-1"/></signals>\n',
).replace("</OpenDRIVE>", '  <junction id="9" name="j"/>\n</OpenDRIVE>')


def test_plain_check_loads_no_junction_object_or_signal_module(tmp_path: Path, plain: Path) -> None:
    # the junction, object and signal rules are loaded and run; what they would read loads only for a file that
    # has junctions, objects or signals (Context.road_objects, rules.context.junction_parts, has_signals)
    names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(plain))
    rules = {"xodrcheck.rules.junction_roles", "xodrcheck.rules.junction_entries", "xodrcheck.rules.object_geometry"}
    assert rules | {"xodrcheck.rules.signal_control", "xodrcheck.rules.junction_shapes"} <= names
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
    assert {"xodrcheck.junction_elements", "xodrcheck.objects.model", "xodrcheck.objects.read"} <= names
    assert "xodrcheck.signals" in names


def test_check_without_overlap_rules_loads_no_shapely(tmp_path: Path, plain: Path) -> None:
    mods = loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "check", "--ignore", "overlap", str(plain))
    assert mods == {"xodrcheck", "numpy", "lxml"}


def test_spiral_check_loads_no_scipy(tmp_path: Path, plain: Path) -> None:
    # the arc becomes a spiral from curvature 0 whose evaluation takes the Fresnel path (our own Fresnel integrals,
    # xodrcheck.geometry.fresnel: scipy.special cost 0.25-0.3 s per process); the same packages as without spirals
    spiral = tmp_path / "spiral.xodr"
    spiral.write_text(PLAIN.replace('<arc curvature="0.01"/>', '<spiral curvStart="0" curvEnd="0.01"/>'))
    names = modules(tmp_path, "xodrcheck.cli", "xodrcheck", "check", str(spiral))
    assert "xodrcheck.geometry.fresnel" in names and "xodrcheck.rules.overlap" in names
    assert {name.split(".")[0] for name in names} & set(WATCHED) == {"xodrcheck", "numpy", "lxml", "shapely"}
    assert "scipy" not in loaded(tmp_path, "xodrcheck.cli", "xodrcheck", "info", str(spiral))


def test_the_spiral_fixture_takes_the_fresnel_path() -> None:
    # what makes the test above meaningful: a = 0, b = 0.5 * 0.01 * 10 over the whole element
    from xodrcheck.geometry import spiral

    b = 0.5 * 0.01 * 10.0
    assert spiral._EPS * (2.0 / b**0.5) <= spiral._FRESNEL_BUDGET


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


_THREADS_PROBE = """
import json, os, sys
from {module} import main
try:
    main(sys.argv[2:])
except SystemExit:
    pass
names = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")
json.dump({{name: os.environ.get(name) for name in names}}, open(sys.argv[1], "w"))
"""


def _thread_variables(tmp_path: Path, module: str, argv: list[str], **env: str) -> dict[str, str | None]:
    out = tmp_path / "env.json"
    clean = {k: v for k, v in os.environ.items() if k not in THREAD_VARIABLES}
    probe = _THREADS_PROBE.format(module=module)
    command = [sys.executable, "-c", probe, str(out), *argv]
    subprocess.run(command, cwd=tmp_path, env=clean | env, capture_output=True, timeout=300, check=True)
    return json.loads(out.read_text())


def test_commands_ask_for_one_blas_thread(tmp_path: Path, plain: Path) -> None:
    one = dict.fromkeys(("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"), "1")
    assert _thread_variables(tmp_path, "xodrcheck.cli", ["check", str(plain)]) == one
    generate = ["generate", "--size", "300x300", "-q", "-o", "m.xodr"]
    assert _thread_variables(tmp_path, "junctionart.cli", generate) == one
    # the user's choice stands, whichever variable says it (OpenBLAS reads OMP_NUM_THREADS too)
    mine = _thread_variables(tmp_path, "xodrcheck.cli", ["check", str(plain)], OMP_NUM_THREADS="2")
    assert mine == {"OPENBLAS_NUM_THREADS": None, "OMP_NUM_THREADS": "2", "MKL_NUM_THREADS": None}


def test_one_blas_thread_only_before_numpy_and_without_a_choice(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in THREAD_VARIABLES:
        monkeypatch.delenv(name, raising=False)
    import numpy  # noqa: F401 (loaded, as in most test processes; whichever test ran first in this worker)

    assert "numpy" in sys.modules  # too late to set anything
    assert not one_blas_thread() and not set(THREAD_VARIABLES) & set(os.environ)
    monkeypatch.delitem(sys.modules, "numpy")
    monkeypatch.setenv("GOTO_NUM_THREADS", "3")
    assert not one_blas_thread() and "OPENBLAS_NUM_THREADS" not in os.environ
    monkeypatch.delenv("GOTO_NUM_THREADS")
    assert one_blas_thread() and os.environ["OPENBLAS_NUM_THREADS"] == "1"  # monkeypatch restores the environment
    for name in THREAD_VARIABLES:
        monkeypatch.delenv(name, raising=False)


def test_import_xodrcheck_sets_no_thread_variable(tmp_path: Path) -> None:
    code = "import os, xodrcheck, xodrcheck.check; print(sorted(k for k in os.environ if k.endswith('_NUM_THREADS')))"
    clean = {k: v for k, v in os.environ.items() if k not in THREAD_VARIABLES}
    done = subprocess.run([sys.executable, "-c", code], env=clean, capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"


_GC_PROBE = """
import atexit, gc, json, sys
from {module} import main
out, own = sys.argv[1], sys.argv[2] == "own"
sys.argv = ["prog", *sys.argv[3:]]

def report():
    with open(out, "w") as f:
        json.dump({{"enabled": gc.isenabled(), "frozen": gc.get_freeze_count()}}, f)

atexit.register(report)  # the process's own command line ends the process when done, after the atexit handlers
try:
    main() if own else main(sys.argv[1:])
except SystemExit:
    pass
"""


def _collector(tmp_path: Path, module: str, own: bool, *argv: str) -> dict[str, Any]:
    out = tmp_path / "gc.json"
    probe = _GC_PROBE.format(module=module)
    command = [sys.executable, "-c", probe, str(out), "own" if own else "call", *argv]
    subprocess.run(command, cwd=tmp_path, capture_output=True, timeout=300, check=True)
    return json.loads(out.read_text())


def test_commands_freeze_their_imports_and_resume_the_collector(tmp_path: Path, plain: Path) -> None:
    # the process's own command line: the modules imported with the collector paused are frozen, then it runs again
    for module, argv in (
        ("xodrcheck.cli", ("check", str(plain))),
        ("xodrcheck.cli", ("info", str(plain))),
        ("junctionart.cli", ("generate", "--size", "300x300", "-q", "-o", "m.xodr")),
    ):
        state = _collector(tmp_path, module, True, *argv)
        assert state["enabled"] and state["frozen"] > 10_000, (module, argv, state)
        # main(argv), as a caller in its own process (a test) runs it: the caller's objects stay collectable
        assert _collector(tmp_path, module, False, *argv) == {"enabled": True, "frozen": 0}


def test_collector_pause_and_resume(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(startup, "_paused", False)
    monkeypatch.setattr(gc, "freeze", lambda: None)  # this test's process keeps its objects collectable
    assert gc.isenabled()
    try:
        assert startup.pause_collector() and not gc.isenabled()
        assert not startup.pause_collector()  # once
        startup.imports_done()
        assert gc.isenabled()
        startup.imports_done()  # nothing to resume
        assert gc.isenabled()
        gc.disable()
        assert not startup.pause_collector()  # a collector stopped by someone else stays stopped
        startup.imports_done()
        assert not gc.isenabled()
    finally:
        gc.enable()


_FINISH_PROBE = """
import atexit, sys
from xodrcheck.cli import main
own = sys.argv[1] == "own"
sys.argv = ["xodrcheck", *sys.argv[2:]]
atexit.register(lambda: print("atexit ran", flush=True))
code = main() if own else main(sys.argv[1:])
print("returned", code, flush=True)
sys.exit(7)
"""


def test_own_command_line_ends_the_process_after_the_atexit_handlers(tmp_path: Path, plain: Path) -> None:
    # xodrcheck.startup.finish: the report written, the atexit handlers run, the command's exit code, no return
    for own in (True, False):
        argv = ["own" if own else "call", "check", "--format", "json", str(plain)]
        done = subprocess.run(
            [sys.executable, "-c", _FINISH_PROBE, *argv], cwd=tmp_path, capture_output=True, text=True, timeout=300
        )
        report, _, rest = done.stdout.rpartition("}")
        assert json.loads(report + "}")["files"][0]["path"].endswith("plain.xodr")
        if own:
            assert (rest.split(), done.returncode) == (["atexit", "ran"], 0)
        else:  # main(argv), as a caller in its own process runs it: it returns, the caller exits as it likes
            assert (rest.split(), done.returncode) == (["returned", "0", "atexit", "ran"], 7)
