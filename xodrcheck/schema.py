"""The OpenDRIVE XML schema of a declared version, compiled once per process, and validation with source lines.

Versions 1.1 to 1.7 use XSD 1.0 and compile in lxml in milliseconds. 1.8 and 1.9 use XSD 1.1 (``xs:assert``,
``xs:alternative``), which lxml cannot compile: xmlschema's ``XMLSchema11`` validator is used, and since building it
takes about half a second, the compiled schema is cached per version. xmlschema validates about 1 MB/s, so a file is
first given a fast verdict (:mod:`xodrcheck.schema_fast`: lxml on the XSD 1.0 part, with the alternatives made
explicit and the assertions evaluated one by one); only a file not shown valid that way goes through xmlschema,
which reports its errors.

Which schema a version gets (:data:`SCHEMA_FOLDERS`): the header has only ``revMajor`` and ``revMinor`` (its
``version`` attribute is the map's own version, not the standard's), so a patch release cannot be told apart from its
minor release. Each minor version therefore gets its latest patch release shipped here: 1.6 -> 1.6.1, 1.7 -> 1.7.0,
1.8 -> 1.8.1, 1.9 -> 1.9.0. 1.8.1 is the 1.8 errata release (it adds id-uniqueness asserts and fixes the signal-board
and outline definitions); a 1.8.0 map that 1.8.1 rejects is also wrong by 1.8.0's prose. 1.8.1 and 1.9.0 are used in
their corrected copies (``1.8.1-corrected``, ``1.9.0-corrected``: the official files with the edits of
:mod:`xodrcheck.schema_errata`, without which every multiBoard signal, vmsGroup and defaultRegulations is invalid).
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from functools import cache
from importlib import resources

from xodrcheck import schema_fast
from xodrcheck.classcache import dataclass

#: (revMajor, revMinor) -> (folder under the package data ``xodrcheck.schemas``, main file).
SCHEMA_FOLDERS: dict[tuple[int, int], tuple[str, str]] = {
    (1, 1): ("1.1", "OpenDRIVE_1.1.xsd"),
    (1, 2): ("1.2", "OpenDRIVE_1.2.xsd"),
    (1, 3): ("1.3", "OpenDRIVE_1.3.xsd"),
    (1, 4): ("1.4", "OpenDRIVE_1.4H.xsd"),
    (1, 5): ("1.5", "OpenDRIVE_1.5M.xsd"),
    (1, 6): ("1.6.1", "opendrive_16_core.xsd"),
    (1, 7): ("1.7.0", "opendrive_17_core.xsd"),
    (1, 8): ("1.8.1-corrected", "OpenDRIVE_Core.xsd"),
    (1, 9): ("1.9.0-corrected", "OpenDRIVE_Core.xsd"),
}

#: Versions whose schema needs an XSD 1.1 processor.
XSD11 = frozenset({(1, 8), (1, 9)})

_lock = threading.Lock()


@dataclass(frozen=True, slots=True)
class SchemaError:
    """One way the document breaks the schema: where (source line, 0 when unknown) and what."""

    line: int
    message: str


def schema_name(version: tuple[int, int]) -> str | None:
    """The schema release used for a declared version, e.g. ``"1.8.1"`` (``None``: no schema for it)."""
    entry = SCHEMA_FOLDERS.get(version)
    return None if entry is None else entry[0].removesuffix("-corrected")


def _schema_file(version: tuple[int, int]):
    folder, main = SCHEMA_FOLDERS[version]
    return resources.files("xodrcheck.schemas") / folder / main


@cache
def _compiled(version: tuple[int, int]):
    source = _schema_file(version)
    with resources.as_file(source) as path:
        if version in XSD11:
            import xmlschema

            return xmlschema.XMLSchema11(str(path))
        from lxml import etree

        parser = etree.XMLParser(resolve_entities=False, no_network=True)
        return etree.XMLSchema(etree.parse(str(path), parser))


def compiled(version: tuple[int, int]):
    """The compiled schema of a declared version (cached; ``KeyError`` when there is none)."""
    if version not in SCHEMA_FOLDERS:
        raise KeyError(version)
    with _lock:  # xmlschema's build is not re-entrant; one build per version per process
        return _compiled(version)


def validate(tree, version: tuple[int, int]) -> Iterator[SchemaError]:
    """Validate an lxml tree against the schema of ``version``, yielding each error with its source line."""
    schema = compiled(version)
    if version in XSD11:
        folder, main = SCHEMA_FOLDERS[version]
        if schema_fast.is_valid(tree, schema, folder, main):
            return  # shown valid by lxml on the XSD 1.0 part plus the alternatives and assertions (schema_fast)
        for err in schema.iter_errors(tree):
            line = getattr(err, "sourceline", None) or 0
            reason = err.reason or str(err.message)
            test = getattr(err.validator, "path", None) if type(err.validator).__name__ == "XsdAssert" else None
            if test:
                reason = f"{reason}: {' '.join(str(test).split())}"
            yield SchemaError(int(line), f"{_xpath_hint(err)}{reason}")
        return
    schema.validate(tree)
    for entry in schema.error_log:
        yield SchemaError(entry.line or 0, entry.message)


def _xpath_hint(err) -> str:
    elem = getattr(err, "elem", None)
    tag = getattr(elem, "tag", None)
    return f"Element '{tag}': " if isinstance(tag, str) else ""
