"""Schema rules (``S0xx``): the file against the official XSD of the OpenDRIVE version it declares."""

from __future__ import annotations

from xodrcheck import schema
from xodrcheck.findings import Category, Severity
from xodrcheck.rules.context import Context
from xodrcheck.rules.registry import rule

#: Schema errors reported one by one per file; the rest are counted in one last finding.
MAX_REPORTED = 200


@rule("S001", "schema-invalid", Category.SCHEMA, Severity.ERROR, xml=True)
def schema_invalid(ctx: Context):
    """The file does not validate against the XSD of the OpenDRIVE version its header declares.

    1.1 to 1.7 are validated with lxml, 1.8 and 1.9 with an XSD 1.1 validator (their schemas use assertions and type
    alternatives; a fast verdict, :mod:`xodrcheck.schema_fast`, spares valid files the slow one). A 1.6 file is
    checked against the 1.6.1 schema, 1.7 against 1.7.0, 1.8 against 1.8.1, 1.9 against 1.9.0 (see
    :mod:`xodrcheck.schema`; 1.8.1 and 1.9.0 with the corrections of :mod:`xodrcheck.schema_errata`, without which
    every multiBoard signal, vmsGroup and defaultRegulations would be invalid). Each schema error is one finding at
    its line, up to 200 per file.

    Passes (1.7: a lane with its required ``type``)::

        <lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>

    Fails (``type`` is required)::

        <lane id="-1" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
    """
    version = ctx.version
    tree = ctx.tree
    if version is None or tree is None or schema.schema_name(version) is None:
        return
    count = 0
    for err in schema.validate(tree, version):
        count += 1
        if count <= MAX_REPORTED:
            yield schema_invalid.finding(
                f"not valid against the OpenDRIVE {schema.schema_name(version)} schema: {err.message}",
                line=err.line or None,
            )
    if count > MAX_REPORTED:
        yield schema_invalid.finding(
            f"{count - MAX_REPORTED} more schema errors not listed ({count} in all)",
        )


@rule("S002", "schema-not-validated", Category.SCHEMA, Severity.INFO, xml=True)
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
