"""A fast "valid" verdict for XSD 1.1 schemas (OpenDRIVE 1.8), so that a valid file need not go through a pure-Python
XSD 1.1 validator (about 1 MB/s) to be found valid.

OpenDRIVE 1.8 needs XSD 1.1 for two things only: type alternatives (``xs:alternative``: a ``junction`` is common,
direct, virtual or crossing by its ``@type``) and assertions (``xs:assert``: 21 co-occurrence tests). Everything else
is XSD 1.0, which libxml2 (lxml) validates in C. So, on the document itself (not a copy: a parsed tree is about 14
times the file's size, and a 50 MB map's copy alone cost gigabytes):

1. every element whose declaration has alternatives gets the type they select as an explicit ``xsi:type`` (XSD 1.1
   requires alternative types to derive from the declared type, so XSD 1.0 accepts exactly that choice), and every
   assertion of every element's type is evaluated with elementpath on the element as a fragment, as xmlschema does,
   but untyped (OpenDRIVE's assertions test existence, counts and string or numeric comparisons, where typing does
   not change the result; one that cannot be evaluated counts as failed);
2. the document is validated by lxml against a *derived* XSD 1.0 schema: the shipped files with their assertions and
   alternatives removed (identity constraints, which reach into junctions, keep working);
3. the ``xsi:type`` attributes (and the namespace declarations they brought) are removed again, whatever happened,
   so the caller's tree is as it was.

The declarations and types come from the compiled xmlschema schema, walked along the instance, so nothing here knows
OpenDRIVE. :func:`is_valid` only ever says "valid" or "don't know": when it says False (or anything goes wrong, or
the file already uses ``xsi:`` attributes), :mod:`xodrcheck.schema` runs the full XSD 1.1 validator, which gives the
errors with their lines. Both are compared on the corpus, generated maps and damaged documents in
``tests/xodrcheck/test_schema_fast.py``.
"""

from __future__ import annotations

from functools import cache
from importlib import resources

from lxml import etree

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
    """The XSD 1.0 schema derived from the files of ``folder_name``: no assertions, no alternatives."""
    texts = {}
    for entry in sorted(resources.files("xodrcheck.schemas").joinpath(folder_name).iterdir(), key=lambda e: e.name):
        if not entry.name.endswith(".xsd"):
            continue
        root = etree.fromstring(entry.read_bytes(), etree.XMLParser(resolve_entities=False, no_network=True))
        for node in list(root.iter(f"{{{XS}}}assert", f"{{{XS}}}alternative")):
            node.getparent().remove(node)
        texts[entry.name] = etree.tostring(root)
    parser = etree.XMLParser(resolve_entities=False, no_network=True)
    parser.resolvers.add(_Files(texts))
    return etree.XMLSchema(etree.fromstring(texts[main], parser, base_url=main))


def _children(xsd_type, known: dict) -> dict[str, object]:
    """Local name -> element declaration of the children ``xsd_type``'s content model declares (``known``: the
    answers so far, by the type's id, each kept with its type so that the id stays that type's)."""
    entry = known.get(id(xsd_type))
    if entry is None:
        found: dict[str, object] = {}
        content = getattr(xsd_type, "content", None)
        if content is not None and hasattr(content, "iter_elements"):
            for decl in content.iter_elements():
                name = getattr(decl, "local_name", None)
                if name and hasattr(decl, "type"):
                    found.setdefault(name, decl)
        entry = known[id(xsd_type)] = (xsd_type, found)
    return entry[1]


def _selected_type(decl, elem):
    """The type ``decl``'s alternatives select for ``elem`` (the first whose test holds, else the default one)."""
    for alt in decl.alternatives:
        if alt.token is None or alt.test(elem):
            return alt.type
    return decl.type


def is_valid(tree, xsd11_schema, folder_name: str, main: str) -> bool:
    """True when ``tree`` is certainly valid against ``xsd11_schema`` (the compiled xmlschema XSD 1.1 schema of the
    files ``folder_name``/``main``); False means "not shown valid here": validate it fully. ``tree`` is typed in
    place for the check and restored before this returns."""
    typed: list[tuple[etree._Element, list[str] | None]] = []
    try:
        schema10 = derived(folder_name, main)
        root = tree.getroot()
        if root.xpath("boolean(//@*[namespace-uri() = $ns])", ns=XSI):
            return False  # xsi:type and friends: their interplay with alternatives is the full validator's job
        top = xsd11_schema.elements.get(etree.QName(root).localname)
        if top is None:
            return False
        return _typed_and_asserted(root, top, typed) and bool(schema10.validate(tree))
    except Exception:
        return False
    finally:
        _untype(typed)


def _typed_and_asserted(root, top, typed: list) -> bool:
    """Walk the instance along its declarations: False at the first assertion that fails; every element with
    alternatives gets its selected type as ``xsi:type`` (recorded in ``typed`` with, when the element had no
    ``xsi`` namespace in scope, the prefixes it had, for :func:`_untype`)."""
    kids: dict = {}
    stack = [(root, top)]
    while stack:
        elem, decl = stack.pop()
        xsd_type = _selected_type(decl, elem) if decl.alternatives else decl.type
        for assertion in getattr(xsd_type, "assertions", ()):
            if not _holds(assertion, elem):
                return False
        if decl.alternatives:  # after the tests and assertions that read the element
            prefixes = elem.nsmap
            typed.append((elem, None if XSI in prefixes.values() else [p for p in prefixes if p]))
            elem.set(f"{{{XSI}}}type", xsd_type.name)
        declared = _children(xsd_type, kids)
        for child in elem:
            if isinstance(child.tag, str):  # not comments or processing instructions
                sub = declared.get(etree.QName(child).localname)
                if sub is not None:
                    stack.append((child, sub))
    return True


def _untype(typed: list) -> None:
    """Remove the ``xsi:type`` attributes :func:`_typed_and_asserted` set, and the ``xsi`` declarations lxml added
    for them (the element's other prefixes are kept)."""
    for elem, kept in reversed(typed):
        elem.attrib.pop(f"{{{XSI}}}type", None)
        if kept is not None:
            etree.cleanup_namespaces(elem, keep_ns_prefixes=kept)


def _holds(assertion, elem) -> bool:
    from elementpath import XPathContext

    token = getattr(assertion, "token", None)
    if token is None:
        return False
    try:
        return bool(token.evaluate(XPathContext(root=elem, fragment=True)))
    except Exception:
        return False
