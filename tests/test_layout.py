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
