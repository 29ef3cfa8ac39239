"""``--where``: a small, safe expression language over metric names, parsed with :mod:`ast` and a whitelist.

Grammar (Python's syntax, a small part of it): comparisons of metric names and numbers (``<``, ``<=``, ``>``, ``>=``,
``==``, ``!=``, chains such as ``3 <= legs <= 5``), joined by ``and``, ``or``, ``not`` and parentheses. Numbers may be
negative. Anything else (calls, attributes, strings, arithmetic, unknown names) is refused with one line naming it. The
tree is walked by :func:`Predicate.__call__`; nothing is ever passed to ``eval``.

>>> Predicate.parse("legs >= 6 and min_angle < 30", ("legs", "min_angle"))({"legs": 7, "min_angle": 12.5})
True
"""

from __future__ import annotations

import ast
import operator
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass

from ..errors import ParamsError

#: Longest expression accepted (characters).
MAX_LENGTH = 500

_COMPARE: dict[type, Callable[[float, float], bool]] = {
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
}


def _describe(node: ast.AST) -> str:
    try:
        return repr(ast.unparse(node))
    except Exception:  # pragma: no cover - unparse handles every node parse makes
        return type(node).__name__


@dataclass(frozen=True)
class Predicate:
    """A parsed ``--where`` expression: call it with a mapping of metric values."""

    text: str
    tree: ast.Expression
    names: tuple[str, ...]  #: the metric names it reads

    @classmethod
    def parse(cls, text: str, known: Iterable[str]) -> Predicate:
        """Parse ``text``; :class:`ParamsError` (one line) for anything outside the language or an unknown name."""
        known = tuple(known)
        if len(text) > MAX_LENGTH:
            raise ParamsError(f"--where: the expression is {len(text)} characters long, at most {MAX_LENGTH}")
        try:
            tree = ast.parse(text.strip(), mode="eval")
        except SyntaxError as exc:
            raise ParamsError(f"--where {text!r}: not an expression ({exc.msg})") from None
        except (ValueError, RecursionError, MemoryError):
            raise ParamsError(f"--where {text!r}: not an expression") from None
        names: list[str] = []
        _check(tree.body, known, names, text)
        return cls(text, tree, tuple(dict.fromkeys(names)))

    def __call__(self, values: Mapping[str, float | None]) -> bool:
        """Whether ``values`` meet the expression (a comparison with a missing value is false)."""
        return bool(_value(self.tree.body, values))


def _check(node: ast.AST, known: tuple[str, ...], names: list[str], text: str) -> None:
    """Refuse every node outside the whitelist, with the offending part of ``text``."""
    if isinstance(node, ast.BoolOp) and isinstance(node.op, (ast.And, ast.Or)):
        for value in node.values:
            _check(value, known, names, text)
    elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
        _check(node.operand, known, names, text)
    elif isinstance(node, ast.Compare):
        if not all(type(op) in _COMPARE for op in node.ops):
            raise ParamsError(f"--where {text!r}: only <, <=, >, >=, ==, != compare values")
        for side in (node.left, *node.comparators):
            _operand(side, known, names, text)
    else:
        raise ParamsError(
            f"--where {text!r}: {_describe(node)} is not allowed; write comparisons of metric names and numbers "
            "joined by and, or, not"
        )


def _operand(node: ast.AST, known: tuple[str, ...], names: list[str], text: str) -> None:
    if isinstance(node, ast.Name):
        if node.id not in known:
            raise ParamsError(f"--where {text!r}: unknown metric {node.id!r}; known: {', '.join(known)}")
        names.append(node.id)
        return
    number = node.operand if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub) else node
    if isinstance(number, ast.Constant) and type(number.value) in (int, float):
        return
    raise ParamsError(f"--where {text!r}: {_describe(node)} is not allowed; compare metric names with numbers")


def _operand_value(node: ast.AST, values: Mapping[str, float | None]) -> float | None:
    if isinstance(node, ast.Name):
        return values.get(node.id)
    number = node.operand if isinstance(node, ast.UnaryOp) else node  # -NUMBER or NUMBER (_operand admits no other)
    if not isinstance(number, ast.Constant) or not isinstance(number.value, (int, float)):
        raise TypeError(f"not a number: {ast.dump(node)}")
    return -float(number.value) if number is not node else float(number.value)


def _value(node: ast.AST, values: Mapping[str, float | None]) -> bool:
    if isinstance(node, ast.BoolOp):
        parts = (_value(v, values) for v in node.values)
        return all(parts) if isinstance(node.op, ast.And) else any(parts)
    if isinstance(node, ast.UnaryOp):
        return not _value(node.operand, values)
    assert isinstance(node, ast.Compare)
    left = _operand_value(node.left, values)
    for op, right_node in zip(node.ops, node.comparators):
        right = _operand_value(right_node, values)
        if left is None or right is None or not _COMPARE[type(op)](left, right):
            return False
        left = right
    return True
