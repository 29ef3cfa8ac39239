"""The dataclass byte-code cache (:mod:`xodrcheck.classcache`): a class built from the cache has the methods
dataclasses compiles, the cache is only a cache (damaged, foreign or unwritable: compile as usual), and the stdlib's
module is left as it was."""

from __future__ import annotations

import ast
import dataclasses
import inspect
import json
import os
import re
import subprocess
import sys
from pathlib import Path
from types import CodeType

import pytest

from xodrcheck import classcache


def _signature(code: CodeType) -> tuple:
    """What a code object does (byte code, constants, names, tables), nested code objects included."""
    consts = tuple(_signature(c) if isinstance(c, CodeType) else repr(c) for c in code.co_consts)
    return (
        code.co_name,
        code.co_code,
        consts,
        code.co_names,
        code.co_varnames,
        code.co_freevars,
        code.co_cellvars,
        code.co_linetable,
        code.co_exceptiontable,
        code.co_filename,
        code.co_flags,
    )


def _methods(cls: type) -> dict[str, tuple]:
    """The methods dataclasses generated (their code is compiled from a string), unwrapped (``__repr__``)."""
    out = {}
    for name, value in vars(cls).items():
        function = inspect.unwrap(value) if callable(value) else None
        if hasattr(function, "__code__") and function.__code__.co_filename == "<string>":
            out[name] = _signature(function.__code__)
    return out


def _make(decorator):
    @decorator(frozen=True, slots=True, order=True)
    class Point:
        """A point."""

        x: float
        y: float = 0.0
        tags: tuple[str, ...] = dataclasses.field(default_factory=tuple)

    return Point


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A fresh cache in a temporary folder, written even though the tests run with PYTHONDONTWRITEBYTECODE."""
    monkeypatch.setenv("XODRCHECK_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    monkeypatch.setattr(classcache, "_CACHE", classcache._Cache())
    folder = classcache.cache_dir()
    assert folder is not None
    return folder


def _fresh(monkeypatch: pytest.MonkeyPatch) -> classcache._Cache:
    """A new process's cache, in this process (what is on disk, nothing in memory)."""
    fresh = classcache._Cache()
    monkeypatch.setattr(classcache, "_CACHE", fresh)
    return fresh


def test_a_class_from_the_cache_has_the_methods_dataclasses_compiles(cache: Path, monkeypatch) -> None:
    plain = _make(dataclasses.dataclass)
    first = _make(classcache.dataclass)
    assert classcache._CACHE.missed  # nothing cached yet: compiled, and saved at exit (here: now)
    classcache._CACHE.save()
    assert (cache / f"{__name__}.marshal").is_file()
    fresh = _fresh(monkeypatch)
    second = _make(classcache.dataclass)
    assert not fresh.missed  # every method's code came from the file
    expected = _methods(plain)
    assert set(expected) >= {"__init__", "__repr__", "__eq__", "__lt__", "__setattr__", "__hash__"}
    assert _methods(first) == expected == _methods(second)
    p = second(1.0, tags=("a",))
    assert (p.x, p.y, p.tags) == (1.0, 0.0, ("a",)) and repr(p).endswith("Point(x=1.0, y=0.0, tags=('a',))")
    assert second(1.0) < second(2.0) and hash(second(1.0)) == hash(second(1.0))
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.x = 2.0  # type: ignore[misc]
    assert [f.name for f in dataclasses.fields(second)] == ["x", "y", "tags"]
    assert "exec" not in vars(dataclasses)  # the stdlib module is left as it was


def test_a_changed_class_misses_and_compiles(cache: Path, monkeypatch) -> None:
    _make(classcache.dataclass)
    classcache._CACHE.save()
    fresh = _fresh(monkeypatch)

    @classcache.dataclass(frozen=True)
    class Point:
        x: float
        z: float  # another field: another source text

    assert fresh.missed
    assert repr(Point(1.0, 2.0)).endswith(".Point(x=1.0, z=2.0)")


@pytest.mark.parametrize("damage", ["garbage", "truncated", "other-version", "world-writable"])
def test_a_damaged_or_untrusted_file_is_ignored(cache: Path, monkeypatch, damage: str) -> None:
    _make(classcache.dataclass)
    classcache._CACHE.save()
    path = cache / f"{__name__}.marshal"
    data = path.read_bytes()
    if damage == "garbage":
        path.write_bytes(b"\x00" * 100)
    elif damage == "truncated":
        path.write_bytes(data[: len(data) // 2])
    elif damage == "other-version":
        path.write_bytes(data.replace(classcache._magic(), b"\x00\x00\r\n", 1))
    else:
        os.chmod(path, 0o666)
    fresh = _fresh(monkeypatch)
    cls = _make(classcache.dataclass)
    assert fresh.missed  # compiled as usual
    assert _methods(cls) == _methods(_make(dataclasses.dataclass))


def test_no_cache_no_write_and_an_unwritable_folder_are_not_errors(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setattr(classcache, "_CACHE", classcache._Cache())
    monkeypatch.setenv("XODRCHECK_CACHE_DIR", "")
    assert classcache.cache_dir() is None
    _make(classcache.dataclass)
    classcache._CACHE.save()  # nothing to write to

    blocked = tmp_path / "file"
    blocked.write_text("not a folder")
    monkeypatch.setenv("XODRCHECK_CACHE_DIR", str(blocked))
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    _fresh(monkeypatch)
    _make(classcache.dataclass)
    classcache._CACHE.save()  # cannot create the folder: silently nothing
    assert blocked.read_text() == "not a folder"

    folder = tmp_path / "quiet"
    monkeypatch.setenv("XODRCHECK_CACHE_DIR", str(folder))
    monkeypatch.setattr(sys, "dont_write_bytecode", True)  # python -B, PYTHONDONTWRITEBYTECODE
    _fresh(monkeypatch)
    _make(classcache.dataclass)
    classcache._CACHE.save()
    assert not folder.exists()


_DIGEST = """
import dataclasses, hashlib, json, sys
import xodrcheck.model, xodrcheck.objects.model, xodrcheck.signals, junctionart.opendrive
sys.path.insert(0, {tests!r})
from test_classcache import _methods
out = {{}}
for module in (xodrcheck.model, xodrcheck.objects.model, xodrcheck.signals, junctionart.opendrive):
    for name, value in sorted(vars(module).items()):
        if isinstance(value, type) and dataclasses.is_dataclass(value) and value.__module__ == module.__name__:
            methods = _methods(value)
            assert "__init__" in methods and "__repr__" in methods, name
            out[f"{{module.__name__}}.{{name}}"] = hashlib.sha256(repr(sorted(methods.items())).encode()).hexdigest()
from xodrcheck import classcache
print(json.dumps({{"digests": out, "missed": sorted(classcache._CACHE.missed)}}))
"""


def test_the_models_classes_are_the_same_with_and_without_the_cache(tmp_path: Path) -> None:
    """Three new processes: no cache, a cold cache (compiles, writes), a warm one (reads): the same methods."""

    def run(folder: str, write: bool) -> dict:
        env = dict(os.environ, XODRCHECK_CACHE_DIR=folder)
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        if not write:
            env["PYTHONDONTWRITEBYTECODE"] = "1"
        code = _DIGEST.format(tests=str(Path(__file__).parent))
        done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout)

    plain = run("", write=False)
    cold = run(str(tmp_path / "cache"), write=True)
    warm = run(str(tmp_path / "cache"), write=True)
    assert len(plain["digests"]) > 40
    assert plain["digests"] == cold["digests"] == warm["digests"]
    assert cold["missed"] and not warm["missed"]


def test_every_dataclass_of_both_packages_uses_the_cache() -> None:
    """A module taking ``dataclass`` from the stdlib again would compile its methods on every start."""
    root = Path(__file__).resolve().parents[2]
    stdlib = re.compile(r"^\s*(from dataclasses import [^\n]*\bdataclass\b|@dataclasses\.dataclass\b)", re.M)
    direct = [
        str(path.relative_to(root))
        for package in ("xodrcheck", "junctionart")
        for path in sorted((root / package).rglob("*.py"))
        if path.name != "classcache.py" and stdlib.search(path.read_text())
    ]
    assert direct == []


def test_every_dataclass_of_both_packages_has_a_docstring() -> None:
    """Without one, dataclasses makes one from ``inspect.signature`` of the class, at import, on every start."""
    root = Path(__file__).resolve().parents[2]
    missing = []
    for package in ("xodrcheck", "junctionart"):
        for path in sorted((root / package).rglob("*.py")):
            for node in ast.walk(ast.parse(path.read_text())):
                is_dataclass = isinstance(node, ast.ClassDef) and any(_is_dataclass(d) for d in node.decorator_list)
                if is_dataclass and ast.get_docstring(node) is None:
                    missing.append(f"{path.relative_to(root)}:{node.name}")
    assert missing == []


def _is_dataclass(decorator: ast.expr) -> bool:
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    return (isinstance(target, ast.Name) and target.id == "dataclass") or (
        isinstance(target, ast.Attribute) and target.attr == "dataclass"
    )


def test_other_generated_code_compiles_as_exec_would_and_is_recorded():
    from xodrcheck.classcache import compiled

    source = "def make(a, b=1):\n    return (a, b)\n"
    code = compiled(source, "tests.generated")
    assert code == compile(source, "<string>", "exec", dont_inherit=True)
    assert compiled(source, "tests.generated") == code
    assert classcache._CACHE.used["tests.generated"][source] == code  # saved with that module's file at exit
    namespace: dict = {}
    exec(code, namespace)
    assert namespace["make"](3) == (3, 1)
