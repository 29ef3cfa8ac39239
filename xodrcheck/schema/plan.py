"""The plan of an XSD 1.1 schema that the fast verdict (:mod:`xodrcheck.schema.fast`) walks, so that showing an
OpenDRIVE 1.8 or 1.9 file valid needs neither xmlschema nor elementpath (importing them and loading the compiled
schema cost several times the check of a small file).

What the fast verdict needs from the compiled XSD 1.1 schema is small: the global elements; for each element
declaration reachable from them, its type and its type alternatives (test, type); for each type, its name, its
assertions and the declarations of the children its content model names (by local name, the first one declared).
:func:`build` walks xmlschema's compiled schema and writes that down, with each XPath 2.0 test translated by
:func:`translate` into an XPath 1.0 expression lxml evaluates in C. ``scripts/schema_plan.py`` writes the plans beside
the schema files (``schemas/<folder>/fast-plan.json``); a test checks that they are what :func:`build` gives now.

The translation is exact for the fast verdict's evaluation (untyped, on the element as the root of a fragment, as
``XPathContext(root=elem, fragment=True)``) on the subset it accepts: child, attribute and descendant steps,
``parent::`` from the element itself (empty: the fragment has no parent), ``and``/``or``/``not``/``if``
(``if (c) then a else b`` -> ``(c and a) or (not(c) and b)``, as an assertion takes the effective boolean value),
``exists``, ``count``, ``count(distinct-values(@...))``, ``name(parent::*)``, ``true``/``false``, string ``=``/``!=`` on
attributes, and numeric comparisons of counts with integers. An attribute compared with a number goes to the
extension function ``x:compare`` (:func:`xodrcheck.schema.fast.compare`), which raises on a value that is not a
plain decimal number instead of comparing NaN as XPath 1.0 would: an error is "not shown valid", never "valid". A
test outside the subset is kept untranslated (``null``); an element whose type needs it goes to the full validator.
"""

from __future__ import annotations

import json
import re
from typing import Any

from xodrcheck.findings import XodrError

#: Namespace of the extension functions the translated expressions call (prefix ``x``).
EXTENSIONS = "urn:xodrcheck:schema-fast"
#: The plan's file name in each XSD 1.1 schema folder.
PLAN_FILE = "fast-plan.json"
#: Bumped when the plan's layout changes.
FORMAT = 1
#: An empty node-set in XPath 1.0.
EMPTY = "self::node()[false()]"

_NCNAME = re.compile(r"[A-Za-z_][A-Za-z0-9_.\-]*\Z")
_GENERAL = {"=": "=", "!=": "!=", "<": "<", ">": ">", "<=": "<=", ">=": ">="}
_VALUE = {"eq": "=", "ne": "!=", "lt": "<", "gt": ">", "le": "<=", "ge": ">="}
_SWAPPED = {"=": "=", "!=": "!=", "<": ">", ">": "<", "<=": ">=", ">=": "<="}
_NODES = ("elements", "attributes", "empty")


class Untranslatable(XodrError):
    """The expression is outside the subset :func:`translate` maps exactly."""


def translate(token: Any) -> str | None:
    """The XPath 1.0 boolean expression equal to the effective boolean value of the elementpath ``token`` (an
    XPath 2.0 parse tree), or ``None`` when the expression is outside the translated subset."""
    if token is None:
        return None
    try:
        _, text = _expression(token)
    except Untranslatable:
        return None
    return f"boolean({text})"


def _expression(tok: Any) -> tuple[str, str]:
    """(kind, XPath 1.0 text) of ``tok``; kinds: elements, attributes, empty (node-sets), boolean, number, string
    (values), integer-literal, string-literal."""
    symbol, n = tok.symbol, len(tok)
    if symbol in ("(name)", "*", "@", ".", "parent") or (symbol in ("/", "//") and n == 2):
        return _path(tok)
    if symbol == "(" and n == 1:
        kind, text = _expression(tok[0])
        return kind, f"({text})"
    if symbol in ("and", "or") and n == 2:
        return "boolean", f"({_expression(tok[0])[1]}) {symbol} ({_expression(tok[1])[1]})"
    if symbol == "if" and n == 3:
        cond, then, other = (_expression(t)[1] for t in tok)
        return "boolean", f"(({cond}) and ({then})) or (not({cond}) and ({other}))"
    if symbol in _GENERAL and n == 2:
        return "boolean", _general(symbol, _expression(tok[0]), _expression(tok[1]))
    if symbol in _VALUE and n == 2:
        left, right = _expression(tok[0]), _expression(tok[1])
        if {left[0], right[0]} <= {"number", "integer-literal"}:
            return "boolean", f"({left[1]}) {_VALUE[symbol]} ({right[1]})"
        raise Untranslatable(symbol)
    if symbol == "(integer)" and n == 0 and isinstance(tok.value, int) and 0 <= tok.value <= 2**53:
        return "integer-literal", str(tok.value)
    if symbol == "(string)" and n == 0 and isinstance(tok.value, str):
        return "string-literal", _quoted(tok.value)
    return _function(tok)


def _function(tok: Any) -> tuple[str, str]:
    symbol, n = tok.symbol, len(tok)
    if symbol in ("true", "false") and n == 0:
        return "boolean", f"{symbol}()"
    if symbol == "not" and n == 1:
        return "boolean", f"not({_expression(tok[0])[1]})"
    if symbol in ("exists", "empty") and n == 1:
        kind, text = _expression(tok[0])
        if kind in _NODES:
            return "boolean", f"boolean({text})" if symbol == "exists" else f"not({text})"
    if symbol == "count" and n == 1:
        if tok[0].symbol == "distinct-values" and len(tok[0]) == 1:
            kind, text = _expression(tok[0][0])
            if kind in ("attributes", "empty"):
                return "number", f"x:count-distinct({text})"
            raise Untranslatable("distinct-values")
        kind, text = _expression(tok[0])
        if kind in _NODES:
            return "number", f"count({text})"
    if symbol == "name" and n == 1 and _expression(tok[0])[0] == "empty":
        return "string", "''"
    raise Untranslatable(symbol)


def _path(tok: Any) -> tuple[str, str]:
    """A relative path from the context element: (kind, text); a path that starts with ``parent::`` is empty."""
    symbol = tok.symbol
    if symbol in ("/", "//"):
        left_kind, left = _path(tok[0])
        if left_kind == "empty":
            return "empty", EMPTY
        if left_kind != "elements":
            raise Untranslatable("a step after an attribute")
        right_kind, right = _step(tok[1])
        return right_kind, f"{left}{symbol}{right}"
    if symbol == "parent" and len(tok) == 1 and tok[0].symbol in ("*", "(name)"):
        return "empty", EMPTY
    return _step(tok)


def _step(tok: Any) -> tuple[str, str]:
    symbol, n = tok.symbol, len(tok)
    if symbol == "(name)" and n == 0 and _NCNAME.match(str(tok.value)):
        return "elements", str(tok.value)
    if symbol == "*" and n == 0:
        return "elements", "*"
    if symbol == "." and n == 0:
        return "elements", "."
    if symbol == "@" and n == 1 and tok[0].symbol == "(name)" and _NCNAME.match(str(tok[0].value)):
        return "attributes", f"@{tok[0].value}"
    raise Untranslatable(f"step {symbol}")


def _general(symbol: str, left: tuple[str, str], right: tuple[str, str]) -> str:
    """A general comparison (existential over node-sets, as in both XPath versions)."""
    op = _GENERAL[symbol]
    if left[0].endswith("literal") and not right[0].endswith("literal"):
        left, right, op = right, left, _SWAPPED[op]
    kinds = (left[0], right[0])
    if kinds[0] in ("attributes", "empty", "string") and kinds[1] == "string-literal" and op in ("=", "!="):
        return f"({left[1]}) {op} {right[1]}"  # strings compared as strings in both versions
    if kinds[0] in ("attributes", "empty") and kinds[1] == "integer-literal":
        return f"x:compare({left[1]}, '{op}', {right[1]})"  # untyped values cast to double, or an error
    if kinds[0] == "number" and kinds[1] in ("number", "integer-literal"):
        return f"({left[1]}) {op} ({right[1]})"
    raise Untranslatable(f"comparison of {kinds[0]} with {kinds[1]}")


def _quoted(value: str) -> str:
    if "'" not in value:
        return f"'{value}'"
    if '"' not in value:
        return f'"{value}"'
    raise Untranslatable("a string literal with both quotes")


def _children(xsd_type: Any) -> dict[str, Any]:
    """Local name -> declaration of the children ``xsd_type``'s content model declares (the first one per name)."""
    found: dict[str, Any] = {}
    content = getattr(xsd_type, "content", None)
    if content is not None and hasattr(content, "iter_elements"):
        for decl in content.iter_elements():
            name = getattr(decl, "local_name", None)
            if name and hasattr(decl, "type"):
                found.setdefault(name, decl)
    return found


def build(xsd11_schema: Any) -> dict[str, Any]:
    """The plan of xmlschema's compiled ``xsd11_schema``: every declaration and type reachable from its global
    elements (numbered in the order they are met), with their tests translated."""
    decl_ids: dict[int, int] = {}
    type_ids: dict[int, int] = {}
    decls: list[Any] = []
    types: list[Any] = []

    def number(obj: Any, ids: dict[int, int], found: list[Any]) -> int:
        if id(obj) not in ids:
            ids[id(obj)] = len(found)
            found.append(obj)
        return ids[id(obj)]

    top = {name: number(decl, decl_ids, decls) for name, decl in xsd11_schema.elements.items()}
    plan_decls: list[dict[str, Any]] = []
    plan_types: list[dict[str, Any]] = []
    while len(plan_decls) < len(decls) or len(plan_types) < len(types):
        for decl in decls[len(plan_decls) :]:
            alternatives = [
                {
                    "test": None if alt.token is None else alt.path,
                    "xpath": None if alt.token is None else translate(alt.token),
                    "type": number(alt.type, type_ids, types),
                }
                for alt in decl.alternatives
            ]
            plan_decls.append({"type": number(decl.type, type_ids, types), "alternatives": alternatives})
        for xsd_type in types[len(plan_types) :]:
            assertions = [
                {"test": getattr(a, "path", None), "xpath": translate(getattr(a, "token", None))}
                for a in getattr(xsd_type, "assertions", ())
            ]
            children = {name: number(d, decl_ids, decls) for name, d in _children(xsd_type).items()}
            plan_types.append({"name": xsd_type.name, "assertions": assertions, "children": children})
    return {"format": FORMAT, "top": top, "decls": plan_decls, "types": plan_types}


def dumps(plan: dict[str, Any]) -> str:
    """The plan as the text of its file."""
    return json.dumps(plan, indent=1, ensure_ascii=False) + "\n"
