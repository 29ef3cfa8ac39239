"""A fast "valid" verdict for XSD 1.1 schemas (OpenDRIVE 1.8, 1.9), so that a valid file need not go through a
pure-Python XSD 1.1 validator (about 1 MB/s, and about half a second to import and load) to be found valid.

OpenDRIVE 1.8 needs XSD 1.1 for two things only: type alternatives (``xs:alternative``: a ``junction`` is common,
direct, virtual or crossing by its ``@type``) and assertions (``xs:assert``: 21 co-occurrence tests). Everything else
is XSD 1.0, which libxml2 (lxml) validates in C. So, on the document itself (not a copy: a parsed tree is about 14
times the file's size, and a 50 MB map's copy alone cost gigabytes):

1. every element whose declaration has alternatives gets the type they select as an explicit ``xsi:type`` (XSD 1.1
   requires alternative types to derive from the declared type, so XSD 1.0 accepts exactly that choice), and every
   assertion of every element's type is evaluated on the element as the root of a fragment, as xmlschema does, but
   untyped (OpenDRIVE's assertions test existence, counts and string or numeric comparisons, where typing does not
   change the result; one that cannot be evaluated counts as failed);
2. the document is validated by lxml against a *derived* XSD 1.0 schema: the shipped files with their assertions and
   alternatives removed (identity constraints, which reach into junctions, keep working);
3. the ``xsi:type`` attributes (and the namespace declarations they brought) are removed again, whatever happened,
   so the caller's tree is as it was.

The declarations, types and tests come from the schema's plan (:mod:`xodrcheck.schema.plan`: written from xmlschema's
compiled schema, shipped beside the schema files, tests translated to XPath 1.0), walked along the instance, so
nothing here knows OpenDRIVE and neither xmlschema nor elementpath is imported. :func:`assertion_failures` says
"valid", "only these assertions are false" (the XSD 1.0 part valid: then they are all the full validator's errors,
which :mod:`xodrcheck.schema.validate` words as it does) or "don't know": then (anything goes wrong, a test is not
translated, or the file already uses ``xsi:`` attributes) :mod:`xodrcheck.schema.validate` runs the full XSD 1.1
validator, which gives the errors with their lines. Both are compared on the corpus, generated maps, documents breaking
assertions and damaged documents in ``tests/xodrcheck/schema/test_schema_fast.py``.
"""

from __future__ import annotations

import json
import operator
import re
from functools import cache
from importlib import resources
from typing import Any, NamedTuple

from lxml import etree

from xodrcheck.findings import XodrError
from xodrcheck.schema.plan import EXTENSIONS, FORMAT, PLAN_FILE

XS = "http://www.w3.org/2001/XMLSchema"
XSI = "http://www.w3.org/2001/XMLSchema-instance"


class _Files(etree.Resolver):
    """Serves the derived schema files from memory (the includes of the main file resolve here, not on disk)."""

    def __init__(self, texts: dict[str, bytes]) -> None:
        super().__init__()
        self.texts = texts

    def resolve(self, system_url, public_id, context):
        name = system_url.rsplit("/", 1)[-1]
        if name in self.texts:
            return self.resolve_string(self.texts[name], context, base_url=name)
        return None


@cache
def derived(folder_name: str, main: str) -> etree.XMLSchema:
    """The XSD 1.0 schema derived from the files of ``folder_name``: no assertions, no alternatives (and, as they
    change nothing in validation but take a third of the compilation, no annotations, comments or blank text)."""
    texts = {}
    reading = etree.XMLParser(resolve_entities=False, no_network=True, remove_blank_text=True, remove_comments=True)
    for entry in sorted((resources.files("xodrcheck.schemas") / folder_name).iterdir(), key=lambda e: e.name):
        if not entry.name.endswith(".xsd"):
            continue
        root = etree.fromstring(entry.read_bytes(), reading)
        for node in list(root.iter(f"{{{XS}}}assert", f"{{{XS}}}alternative", f"{{{XS}}}annotation")):
            node.getparent().remove(node)
        texts[entry.name] = etree.tostring(root)
    parser = etree.XMLParser(resolve_entities=False, no_network=True)
    parser.resolvers.add(_Files(texts))
    return etree.XMLSchema(etree.fromstring(texts[main], parser, base_url=main))


class _Type(NamedTuple):
    name: str | None
    #: Compiled assertions; ``None``: an assertion the plan could not translate.
    assertions: tuple[etree.XPath | None, ...]
    #: Local name -> declaration number of the children the content model declares.
    children: dict[str, int]
    #: The assertions' XPath 2.0 tests as the schema writes them (the full validator's error messages quote them).
    tests: tuple[str, ...]


class _Decl(NamedTuple):
    type: int
    #: (compiled test, is the default one, type number); a test of ``None`` that is not the default: not translated.
    alternatives: tuple[tuple[etree.XPath | None, bool, int], ...]


class _Plan(NamedTuple):
    top: dict[str, int]
    decls: list[_Decl]
    types: list[_Type]


class _NotTranslated(XodrError):
    """A type alternative's test that the plan has no XPath 1.0 translation for."""


_DECIMAL = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?\Z")
_OPERATORS = {"=": operator.eq, "!=": operator.ne, "<": operator.lt, ">": operator.gt, "<=": operator.le}
_OPERATORS[">="] = operator.ge


def _strings(values: Any) -> list[str]:
    if not isinstance(values, list) or not all(isinstance(v, str) for v in values):
        raise TypeError("an attribute node-set was expected")
    return [str(v) for v in values]


def compare(_context: Any, values: Any, op: str, number: float) -> bool:
    """XPath extension ``x:compare(@a, op, n)``: XPath 2.0's untyped general comparison of attribute values with a
    number (true when one value compares true), where a value that is not a plain decimal number is an error (XPath
    1.0 would compare it as NaN; XPath 2.0 fails to cast it or reads more forms than this accepts)."""
    numbers = []
    for value in _strings(values):
        if not _DECIMAL.match(value):
            raise ValueError(f"not a plain number: {value!r}")
        numbers.append(float(value))
    test = _OPERATORS[op]
    return any(test(x, number) for x in numbers)


def count_distinct(_context: Any, values: Any) -> int:
    """XPath extension ``x:count-distinct(@a)``: ``count(distinct-values(@a))`` of untyped attribute values, which
    are compared as strings."""
    return len(set(_strings(values)))


def compiled_test(text: str | None) -> etree.XPath | None:
    """A schema test as the plan translates it (XPath 1.0 text, ``None`` for none) compiled by lxml with the
    ``x:`` extension functions (:func:`compare`, :func:`count_distinct`): what the fast verdict evaluates on an element,
    and what the tests hold against elementpath's reading of the XSD 1.1 original."""
    if text is None:
        return None
    functions = {(EXTENSIONS, "compare"): compare, (EXTENSIONS, "count-distinct"): count_distinct}
    return etree.XPath(text, namespaces={"x": EXTENSIONS}, extensions=functions)


@cache
def plan(folder_name: str) -> _Plan:
    """The plan of the schema in ``folder_name`` (:mod:`xodrcheck.schema.plan`), its tests compiled by lxml."""
    source = resources.files("xodrcheck.schemas") / folder_name / PLAN_FILE
    data = json.loads(source.read_bytes())
    if data.get("format") != FORMAT:
        raise ValueError(f"{folder_name}/{PLAN_FILE}: format {data.get('format')}, expected {FORMAT}")
    decls = [
        _Decl(d["type"], tuple((compiled_test(a["xpath"]), a["test"] is None, a["type"]) for a in d["alternatives"]))
        for d in data["decls"]
    ]
    types = [
        _Type(
            t["name"],
            tuple(compiled_test(a["xpath"]) for a in t["assertions"]),
            dict(t["children"]),
            tuple(str(a["test"]) for a in t["assertions"]),
        )
        for t in data["types"]
    ]
    return _Plan(dict(data["top"]), decls, types)


def _selected_type(decl: _Decl, elem: etree._Element) -> int:
    """The type ``decl``'s alternatives select for ``elem`` (the first whose test holds, else the default one)."""
    for test, default, xsd_type in decl.alternatives:
        if default:
            return xsd_type
        if test is None:
            raise _NotTranslated
        if test(elem):
            return xsd_type
    return decl.type


def is_valid(tree: etree._ElementTree, folder_name: str, main: str) -> bool:
    """True when ``tree`` is certainly valid against the XSD 1.1 schema of the files ``folder_name``/``main``; False
    means "not shown valid here": validate it fully. ``tree`` is typed in place for the check and restored before
    this returns."""
    return assertion_failures(tree, folder_name, main) == []


class Failure(NamedTuple):
    """An assertion that is false on an element: the full validator's error ``assertion test is false``."""

    elem: etree._Element
    #: The assertion's XPath 2.0 test as the schema writes it.
    test: str


def assertion_failures(tree: etree._ElementTree, folder_name: str, main: str) -> list[Failure] | None:
    """The errors the full XSD 1.1 validator finds in ``tree`` when they are certainly assertions only: the XSD 1.0
    part valid (lxml, with the alternatives' types), every test met translated and evaluated without error, and no
    attribute in a failing element's fragment with whitespace that typing would normalise. Then each false assertion
    is one :class:`Failure`, in the full validator's order (elements in document order, each element's assertions
    before its children's, in its type's order); ``[]``: valid. ``None``: not known here: validate it fully.
    ``tree`` is typed in place for the check and restored before this returns."""
    typed: list[tuple[etree._Element, list[str] | None]] = []
    failures: list[Failure] = []
    try:
        schema10 = derived(folder_name, main)
        schema_plan = plan(folder_name)
        root = tree.getroot()
        if root.xpath("boolean(//@*[namespace-uri() = $ns])", ns=XSI):
            return None  # xsi:type and friends: their interplay with alternatives is the full validator's job
        top = schema_plan.top.get(etree.QName(root).localname)
        if top is None or not _typed_and_asserted(root, top, schema_plan, typed, failures):
            return None
        if not all(_plain(f.elem) for f in failures) or not schema10.validate(tree):
            return None
        return failures
    except Exception:
        return None
    finally:
        _untype(typed)


def _plain(elem: etree._Element) -> bool:
    """No attribute value of ``elem``'s fragment has leading, trailing, repeated or non-space whitespace (where a
    typed value, whitespace-collapsed, could differ from the untyped string the assertions were evaluated on)."""
    return all(value == " ".join(value.split()) for e in elem.iter("*") for value in e.attrib.values())


def _typed_and_asserted(
    root: etree._Element, top: int, schema_plan: _Plan, typed: list, failures: list[Failure]
) -> bool:
    """Walk the instance along its declarations in document order, adding each false assertion to ``failures``;
    False ("don't know") at a test that is not translated or that raises. Every element with alternatives gets its
    selected type as ``xsi:type`` (recorded in ``typed`` with, when the element had no ``xsi`` namespace in scope,
    the prefixes it had, for :func:`_untype`)."""
    decls, types = schema_plan.decls, schema_plan.types
    stack = [(root, top)]
    while stack:
        elem, number = stack.pop()
        decl = decls[number]
        xsd_type = types[_selected_type(decl, elem) if decl.alternatives else decl.type]
        for assertion, test in zip(xsd_type.assertions, xsd_type.tests):
            holds = _holds(assertion, elem)
            if holds is None:
                return False
            if not holds:
                failures.append(Failure(elem, test))
        if decl.alternatives:  # after the tests and assertions that read the element
            prefixes = elem.nsmap
            typed.append((elem, None if XSI in prefixes.values() else [p for p in prefixes if p]))
            elem.set(f"{{{XSI}}}type", xsd_type.name)  # None (an anonymous type) raises: "don't know"
        declared = xsd_type.children
        children = []
        for child in elem:
            if isinstance(child.tag, str):  # not comments or processing instructions
                sub = declared.get(etree.QName(child).localname)
                if sub is not None:
                    children.append((child, sub))
        stack.extend(reversed(children))  # popped in document order
    return True


def _untype(typed: list) -> None:
    """Remove the ``xsi:type`` attributes :func:`_typed_and_asserted` set, and the ``xsi`` declarations lxml added
    for them (the element's other prefixes are kept)."""
    for elem, kept in reversed(typed):
        elem.attrib.pop(f"{{{XSI}}}type", None)
        if kept is not None:
            etree.cleanup_namespaces(elem, keep_ns_prefixes=kept)


def _holds(assertion: etree.XPath | None, elem: etree._Element) -> bool | None:
    """Whether a compiled assertion holds on ``elem``; ``None`` (not known) for one not translated or that raises."""
    if assertion is None:
        return None
    try:
        return bool(assertion(elem))
    except Exception:
        return None
