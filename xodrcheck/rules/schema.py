"""Schema rules (``S0xx``): the file against the official XSD of the OpenDRIVE version it declares."""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared.context import Context
from xodrcheck.schema import validate as schema

#: Schema errors reported one by one per file; the rest are counted in one last finding.
MAX_REPORTED = 200

#: The element and attribute a validator's message is about: xmlschema's "Element 'road': attribute length='abc': ..."
#: and "'bogus' attribute not allowed", lxml's "Element 'road', attribute 'length': ..." and "The attribute 'x' is".
_ATTRIBUTE = re.compile(
    r"^Element '(?P<element>[^']+)'(?:: attribute (?P<a>[\w:.-]+)=|, attribute '(?P<b>[^']+)'"
    r"|: '(?P<c>[^']+)' attribute|: The attribute '(?P<d>[^']+)')"
)


def _cause(error: schema.SchemaError) -> tuple:
    """What an error is about: (line, element, attribute) when it names an attribute, else (line, message)."""
    found = _ATTRIBUTE.match(error.message)
    if found is None:
        return (error.line, error.message)
    attribute = found.group("a") or found.group("b") or found.group("c") or found.group("d")
    return (error.line, found.group("element"), attribute)


_PATTERN = "match any pattern"


def one_per_cause(errors: Iterable[schema.SchemaError]) -> Iterator[schema.SchemaError]:
    """The errors, one per cause: xmlschema reports one bad attribute value once per check it fails (a pattern, a
    conversion, an assertion...), three errors at one line for one ``length="abc"``. The first is kept, unless it only
    quotes the type's regular expression and a later one says more plainly what is wrong."""
    kept: dict[tuple, schema.SchemaError] = {}
    for error in errors:
        key = _cause(error)
        first = kept.get(key)
        if first is None or (_PATTERN in first.message and _PATTERN not in error.message):
            kept[key] = error
    return iter(kept.values())


@rule("S001", "schema-invalid", Category.SCHEMA, Severity.ERROR, basis=Basis.SCHEMA)
def schema_invalid(ctx: Context):
    """The file does not validate against the XSD of the OpenDRIVE version its header declares.

    1.1 to 1.7 are validated with lxml, 1.8 and 1.9 with an XSD 1.1 validator (their schemas use assertions and type
    alternatives; a fast verdict, :mod:`xodrcheck.schema.fast`, spares valid files the slow one). A 1.6 file is
    checked against the 1.6.1 schema, 1.7 against 1.7.0, 1.8 against 1.8.1, 1.9 against 1.9.0 (see
    :mod:`xodrcheck.schema.validate`; 1.8.1 and 1.9.0 with the corrections of :mod:`xodrcheck.schema.errata`, without
    which every multiBoard signal, vmsGroup and defaultRegulations would be invalid). Each schema error is one finding
    at its line, up to 200 per file; what the validator reports several times for one cause (one attribute of one
    element: xmlschema gives a bad number once per check it fails) is one finding.

    The elements are validated in the namespace the schema declares them in: a file whose elements are in another
    one (the 1.1 and 1.2 schemas put them in ``www.vires.com``, which the files those versions' tools wrote do not
    use) is validated as if they were, and ``schema-namespace-assumed`` says so.

    Passes (1.7: a lane with its required ``type``)::

        <lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>

    Fails (``type`` is required)::

        <lane id="-1" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
    """
    version = ctx.version
    tree = ctx.tree
    if version is None or tree is None or schema.schema_name(version) is None:
        return
    mismatch = schema.namespace_mismatch(tree, version)
    if mismatch is not None:  # validated as if in the schema's namespace: schema-namespace-assumed says so
        tree = schema.in_namespace(tree, *mismatch)
    namespace = schema.target_namespace(version)
    qualified = "" if namespace is None else "{" + namespace + "}"  # left out of the messages' element names
    count = 0
    for err in one_per_cause(schema.validate(tree, version)):
        count += 1
        if count <= MAX_REPORTED:
            message = err.message.replace(qualified, "") if qualified else err.message
            yield schema_invalid.finding(
                f"not valid against the OpenDRIVE {schema.schema_name(version)} schema: {message}",
                line=err.line or None,
            )
    if count > MAX_REPORTED:
        yield schema_invalid.finding(
            f"{count - MAX_REPORTED} more schema errors not listed ({count} in all)",
        )


@rule("S002", "schema-not-validated", Category.SCHEMA, Severity.INFO, basis=Basis.SCHEMA)
def schema_not_validated(ctx: Context):
    """The file could not be validated: its header declares no OpenDRIVE version that has a schema (1.1 to 1.9).

    The reader reports the missing or unknown version itself; this finding says that schema validation did not
    happen, so that an empty schema report is not mistaken for a valid file.

    Passes::

        <header revMajor="1" revMinor="7"/>

    Fails::

        <header revMajor="1" revMinor="10"/>
    """
    if ctx.tree is None:
        return
    version = ctx.version
    if version is None:
        yield schema_not_validated.finding("no schema validation: the header declares no OpenDRIVE version")
    elif schema.schema_name(version) is None:
        header = ctx.document.header
        yield schema_not_validated.finding(
            f"no schema validation: no schema for OpenDRIVE {version[0]}.{version[1]} (known: 1.1 to 1.9)",
            line=header.line if header is not None and header.line else None,
        )


def _namespace_words(namespace: str | None) -> str:
    return "in no namespace" if namespace is None else f"in namespace '{namespace}'"


@rule("S003", "schema-namespace-assumed", Category.SCHEMA, Severity.INFO, basis=Basis.SCHEMA)
def schema_namespace_assumed(ctx: Context):
    """The file's elements are not in the namespace the schema of its version declares: they were validated as if
    they were.

    The OpenDRIVE 1.1 and 1.2 schemas declare their elements in the namespace ``www.vires.com``
    (``targetNamespace``); the files of those versions, as tools write them, put theirs in none (or in another, such
    as ``http://www.opendrive.org``), and 1.3 on declare none. Validated as written, such a file fails at its root
    ("no matching global declaration"), which says nothing about its content; ``schema-invalid`` therefore
    validates the elements as if they were in the schema's namespace, and this finding says so.

    Passes (1.1 with the schema's namespace)::

        <OpenDRIVE xmlns="www.vires.com"><header revMajor="1" revMinor="1"/>...</OpenDRIVE>

    Fails (1.1 in no namespace: validated as if in ``www.vires.com``)::

        <OpenDRIVE><header revMajor="1" revMinor="1"/>...</OpenDRIVE>
    """
    version = ctx.version
    tree = ctx.tree
    if version is None or tree is None or schema.schema_name(version) is None:
        return
    mismatch = schema.namespace_mismatch(tree, version)
    if mismatch is None:
        return
    found, expected = mismatch
    name = schema.schema_name(version)
    yield schema_namespace_assumed.finding(
        f"the OpenDRIVE {name} schema's elements are {_namespace_words(expected)}; this file's are "
        f"{_namespace_words(found)}: validated as if they were {_namespace_words(expected)}",
        line=tree.getroot().sourceline or None,
    )
