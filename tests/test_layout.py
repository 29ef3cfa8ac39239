"""The repository's layout and which parts may import which.

- The tests never import ``benchmarks/``: the benchmarks import the tests' helpers (e.g.
  ``tests/interop/asam_harness.py``), not the other way round; a test must run from the package and its own tree.
- The top of ``xodrcheck/`` holds only its public entry points; everything else lives in sub-packages.
- No import circle among xodrcheck's modules: none when the modules are imported, and no new one through the imports
  deferred into functions either (the known ones are listed until they are untangled).
"""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parent
XODRCHECK = TESTS.parent / "xodrcheck"

#: The modules the top of ``xodrcheck/`` may hold: the package, ``python -m``, the API behind ``xodrcheck.check``, its
#: configuration, findings and verdicts, and the pytest plugin users' conftests load by name.
TOP_LEVEL = {"__init__", "__main__", "check", "config", "findings", "verdict", "pytest_plugin"}

#: Modules still at the top only until their users read the typed document instead (they are then deleted).
PENDING: set[str] = set()


def _imported_modules(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module)
    return names


def test_no_test_imports_benchmarks() -> None:
    files = sorted(TESTS.rglob("*.py"))
    assert len(files) > 100, "the tests tree should hold its modules"
    offenders = {
        p.relative_to(TESTS).as_posix(): sorted(m for m in _imported_modules(p) if m.split(".")[0] == "benchmarks")
        for p in files
    }
    assert {k: v for k, v in offenders.items() if v} == {}


def test_top_of_xodrcheck_holds_only_entry_points() -> None:
    modules = {p.stem for p in XODRCHECK.glob("*.py")}
    assert modules - PENDING == TOP_LEVEL
    assert len(TOP_LEVEL) <= 8
    packages = {p.parent.name for p in XODRCHECK.glob("*/__init__.py")}
    assert {"analysis", "geometry", "mesh", "reader", "rules", "schema", "support"} <= packages


def _module_names(root: Path) -> dict[str, Path]:
    names = {}
    for path in root.rglob("*.py"):
        parts = path.relative_to(root.parent).with_suffix("").parts
        names[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return names


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _imports(tree: ast.Module, deferred: bool) -> list[ast.Import | ast.ImportFrom]:
    """The import statements run when the module is imported (module level, outside ``if TYPE_CHECKING``), and with
    ``deferred`` also those inside functions."""
    found: list[ast.Import | ast.ImportFrom] = []
    todo: list[ast.AST] = list(tree.body)
    while todo:
        node = todo.pop()
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            found.append(node)
        elif isinstance(node, ast.If) and _is_type_checking(node.test):
            continue
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            if deferred or isinstance(node, ast.ClassDef):
                todo.extend(node.body)
        else:
            todo.extend(child for child in ast.iter_child_nodes(node) if isinstance(child, ast.stmt))
    return found


def _import_graph(deferred: bool) -> dict[str, set[str]]:
    """Module -> the xodrcheck modules it imports (``from pkg import sub`` names the submodule; a module importing a
    name from its own package's ``__init__`` depends on that ``__init__`` too)."""
    modules = _module_names(XODRCHECK)
    graph: dict[str, set[str]] = {name: set() for name in modules}
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in _imports(ast.parse(path.read_text(encoding="utf-8")), deferred):
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            else:
                base = node.module or ""
                if node.level:
                    anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                    base = ".".join([*anchor, base] if base else anchor)
                targets = []
                for alias in node.names:
                    sub = f"{base}.{alias.name}"
                    targets.append(sub if sub in modules else base)
                    if sub in modules and not name.startswith(base + "."):
                        targets.append(base)
            graph[name].update(t for t in targets if t in modules and t != name)
    return graph


def _circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    circles: list[list[str]] = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    circles.append(sorted(component))
    return sorted(circles)


def test_circle_finder_finds_a_circle() -> None:
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set(), "e": {"d"}}
    assert _circles(graph) == [["a", "b", "c"]]
    assert _circles({"a": {"b"}, "b": set()}) == []


def test_import_graph_sees_the_imports() -> None:
    graph = _import_graph(deferred=False)
    assert len(graph) > 200
    assert "xodrcheck.support.memory" in graph["xodrcheck.check"]  # from xodrcheck.support import memory
    assert "xodrcheck.mesh.surfaces" in graph["xodrcheck.mesh.footprint"]


def test_no_import_circle_at_import_time() -> None:
    assert _circles(_import_graph(deferred=False)) == []


def test_no_circle_through_deferred_imports_either() -> None:
    assert _circles(_import_graph(deferred=True)) == []


#: What may import lxml: the reader (the one reader of OpenDRIVE XML), schema validation and the writers of XML reports.
LXML_USERS = ("xodrcheck.reader", "xodrcheck.schema", "xodrcheck.report.junit", "xodrcheck.report.xqar")


def test_only_the_reader_schema_and_xml_writers_import_lxml() -> None:
    users = set()
    for name, path in _module_names(XODRCHECK).items():
        for node in _imports(ast.parse(path.read_text(encoding="utf-8")), deferred=True):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
            if any(n == "lxml" or n.startswith("lxml.") for n in names):
                users.add(name)
    assert {"xodrcheck.reader", "xodrcheck.schema.validate"} <= users  # the test sees the imports
    assert sorted(u for u in users if not u.startswith(LXML_USERS)) == []


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


#: Calls that reach an attribute by name: ``setattr(module, "_name", ...)``, ``monkeypatch.setattr`` and the like.
_BY_NAME = {"setattr", "getattr", "delattr", "hasattr"}


def _private_reaches(tree: ast.Module, modules: set[str]) -> list[str]:
    """Where a test reaches a private name (one leading underscore) of an xodrcheck module: ``module._name`` on an
    imported module (bound by ``import``, ``import ... as`` or ``from package import module``, or reached through a
    package's attributes), ``from xodrcheck.m import _name``, an import of a private module,
    ``monkeypatch.setattr(module, "_name", ...)`` (and setattr, getattr, delattr, hasattr), and a dotted target
    ``"xodrcheck.m._name"`` handed to a call (``monkeypatch.setattr``, ``mock.patch``). Names are bound per file.
    An attribute of an object the module made (``cache._keys``) is beyond what the syntax shows."""
    bound: dict[str, str] = {}
    found: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "xodrcheck":
                    bound[alias.asname or "xodrcheck"] = alias.name if alias.asname else "xodrcheck"
                    if any(_private(part) for part in alias.name.split(".")):
                        found.append(ast.unparse(node))
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and (node.module or "").split(".")[0] == "xodrcheck":
            module = node.module or ""
            if any(_private(part) for part in module.split(".")) or any(_private(a.name) for a in node.names):
                found.append(ast.unparse(node))
            for alias in node.names:
                if f"{module}.{alias.name}" in modules:
                    bound[alias.asname or alias.name] = f"{module}.{alias.name}"

    def module_of(node: ast.expr) -> str | None:
        if isinstance(node, ast.Name):
            return bound.get(node.id)
        if isinstance(node, ast.Attribute):
            base = module_of(node.value)
            if base is not None and f"{base}.{node.attr}" in modules:
                return f"{base}.{node.attr}"
        return None

    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and _private(node.attr) and module_of(node.value) is not None:
            found.append(ast.unparse(node))
        elif isinstance(node, ast.Call) and node.args:
            func = node.func
            name = func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else ""
            first, second = node.args[0], node.args[1] if len(node.args) > 1 else None
            by_name = (
                name in _BY_NAME
                and isinstance(second, ast.Constant)
                and isinstance(second.value, str)
                and _private(second.value)
                and module_of(first) is not None
            )
            dotted = (
                isinstance(first, ast.Constant)
                and isinstance(first.value, str)
                and first.value.split(".")[0] == "xodrcheck"
                and any(_private(part) for part in first.value.split("."))
            )
            if by_name or dotted:
                found.append(ast.unparse(node))
    return found


def test_the_private_name_scan_sees_each_way_of_reaching_one() -> None:
    source = """
import xodrcheck
import xodrcheck.reader as reader
from xodrcheck.mesh import surfaces as mesh
from xodrcheck.rules.object_surfaces import _boxes, surface_boxes
from xodrcheck.rules.shared import sampled

def test_it(monkeypatch, ctx):
    xodrcheck._EXPORTS, reader._load(), xodrcheck.rules.shared.sampled._grid, sampled.LINES[ctx]._keys
    monkeypatch.setattr(mesh, "_MESH_BATCH", 1)
    monkeypatch.setattr("xodrcheck.mesh.footprint._PAIR_BLOCK", 1)
    getattr(sampled, "_grid")
    monkeypatch.setattr(mesh, "MESH_BATCH", 1), sampled.LINES, surface_boxes(ctx), reader.os._exit, self._own
"""
    assert sorted(_private_reaches(ast.parse(source), set(_module_names(XODRCHECK)))) == sorted(
        [
            "from xodrcheck.rules.object_surfaces import _boxes, surface_boxes",
            "xodrcheck._EXPORTS",
            "reader._load",
            "xodrcheck.rules.shared.sampled._grid",
            "monkeypatch.setattr(mesh, '_MESH_BATCH', 1)",
            "monkeypatch.setattr('xodrcheck.mesh.footprint._PAIR_BLOCK', 1)",
            "getattr(sampled, '_grid')",
        ]
    )


def test_no_test_reaches_a_private_name_of_an_xodrcheck_module() -> None:
    """Tests use xodrcheck's public names (a kernel or batch size a test needs has a public, documented name); a
    private name stays in its module, free to change. Every test file is scanned, not only tests/xodrcheck."""
    modules = set(_module_names(XODRCHECK))
    files = sorted(TESTS.rglob("*.py"))
    assert len(files) > 100, "the tests tree should hold its modules"
    found = [
        f"{path.relative_to(TESTS).as_posix()}: {hit}"
        for path in files
        for hit in _private_reaches(ast.parse(path.read_text(encoding="utf-8"), filename=str(path)), modules)
    ]
    assert found == []
