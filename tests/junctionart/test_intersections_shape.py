"""The intersection stage stays in small pieces (issue 17): no function in ``junctionart/intersections/`` is over 60
lines, so each phase of a pass can be read, changed and tested on its own.

The stage was once one class whose pass was a single 149-line method; this keeps it from growing back.
"""

from __future__ import annotations

import ast
from pathlib import Path

import junctionart.intersections

LIMIT = 60
PACKAGE = Path(junctionart.intersections.__file__).parent


def _functions(path: Path) -> list[tuple[str, int, int]]:
    """(qualified name, first line, line count) of every function and method in a module, nested ones included."""
    out = []

    def visit(node: ast.AST, prefix: str) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                first = min([child.lineno, *(d.lineno for d in child.decorator_list)])
                out.append((prefix + child.name, first, child.end_lineno - first + 1))
                visit(child, prefix + child.name + ".")
            elif isinstance(child, ast.ClassDef):
                visit(child, prefix + child.name + ".")

    visit(ast.parse(path.read_text(encoding="utf-8")), "")
    return out


def test_the_package_is_where_the_test_looks():
    modules = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert "layout.py" in modules and len(modules) >= 10, modules
    assert sum(len(_functions(PACKAGE / m)) for m in modules) > 50


def test_no_function_in_the_intersection_stage_is_over_60_lines():
    long = [
        f"{path.name}:{first} {name} ({lines} lines)"
        for path in sorted(PACKAGE.glob("*.py"))
        for name, first, lines in _functions(path)
        if lines > LIMIT
    ]
    assert not long, "functions over 60 lines in junctionart/intersections/: " + ", ".join(long)


def test_the_measure_counts_a_long_function(tmp_path):
    body = "\n".join(f"    x{i} = {i}" for i in range(LIMIT))
    module = tmp_path / "m.py"
    module.write_text(f"class C:\n    @staticmethod\n    def f():\n    {body.replace(chr(10), chr(10) + '    ')}\n")
    ((name, first, lines),) = _functions(module)
    assert name == "C.f" and first == 2 and lines == LIMIT + 2
