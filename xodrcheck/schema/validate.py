"""The OpenDRIVE XML schema of a declared version, compiled once per process, and validation with source lines.

Versions 1.1 to 1.7 use XSD 1.0 and compile in lxml in milliseconds. 1.8 and 1.9 use XSD 1.1 (``xs:assert``,
``xs:alternative``), which lxml cannot compile: xmlschema's ``XMLSchema11`` validator is used, and since building it
takes about half a second, the compiled schema is cached per version. xmlschema validates about 1 MB/s, so a file is
first given a fast verdict (:mod:`xodrcheck.schema.fast`: lxml on the XSD 1.0 part, with the alternatives made
explicit and the assertions evaluated one by one, from the schema's plan, without importing xmlschema). A file whose
only errors are false assertions gets them from there too, worded and ordered as xmlschema gives them (the fast path
knows them to be all when lxml finds the rest valid); any other file not shown valid goes through xmlschema, which
reports its errors.

Which schema a version gets (:data:`SCHEMA_FOLDERS`): the header has only ``revMajor`` and ``revMinor`` (its
``version`` attribute is the map's own version, not the standard's), so a patch release cannot be told apart from its
minor release. Each minor version therefore gets its latest patch release shipped here: 1.6 -> 1.6.1, 1.7 -> 1.7.0,
1.8 -> 1.8.1, 1.9 -> 1.9.0. 1.8.1 is the 1.8 errata release (it adds id-uniqueness asserts and fixes the signal-board
and outline definitions); a 1.8.0 map that 1.8.1 rejects is also wrong by 1.8.0's prose. 1.8.1 and 1.9.0 are used in
their corrected copies (``1.8.1-corrected``, ``1.9.0-corrected``: the official files with the edits of
:mod:`xodrcheck.schema.errata`, without which every multiBoard signal, vmsGroup and defaultRegulations is invalid).
"""

from __future__ import annotations

import contextlib
import pickle
import sys
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from functools import cache
from importlib import resources
from pathlib import Path

from xodrcheck.support import usercache

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
#: Bumped when what the XSD 1.1 cache file holds changes.
_XSD11_CACHE_FORMAT = "xodrcheck xsd11 1"


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
    if isinstance(source, Path):
        return _build(version, source)
    from importlib import resources

    with resources.as_file(source) as path:
        return _build(version, path)


def _build(version: tuple[int, int], path: Path):
    if version in XSD11:
        return xsd11(version, path)
    from lxml import etree

    parser = etree.XMLParser(resolve_entities=False, no_network=True)
    return etree.XMLSchema(etree.parse(str(path), parser))


def xsd11(version: tuple[int, int], path: Path):
    """xmlschema's XSD 1.1 schema of ``path``, from the user's cache when an identical build is there (building it
    takes seconds, loading it a tenth of that; :mod:`xodrcheck.support.usercache`), else built and stored."""
    import xmlschema

    cached = xsd11_cache_file(version, path)
    data = None if cached is None else usercache.read(cached)
    if data is not None:
        try:
            schema = pickle.loads(data)
        except Exception:  # damaged, or made by another xmlschema: build it again
            schema = None
        if isinstance(schema, xmlschema.XMLSchema11):
            return schema
    schema = xmlschema.XMLSchema11(str(path))
    if cached is not None and usercache.writable():
        # a schema that does not pickle is still used; it is only not cached
        with contextlib.suppress(pickle.PicklingError, TypeError, AttributeError, RecursionError):
            usercache.write(cached, pickle.dumps(schema, protocol=pickle.HIGHEST_PROTOCOL))
    return schema


def xsd11_cache_file(version: tuple[int, int], path: Path) -> Path | None:
    """Where the build of ``path`` is cached: named after what the build depends on (the schema files' bytes and
    location, xmlschema's and elementpath's versions, Python's), so any change is a new file, never a stale one."""
    import hashlib

    import elementpath
    import xmlschema

    folder = usercache.root()
    if folder is None:
        return None
    key = hashlib.sha256()
    for part in (_XSD11_CACHE_FORMAT, xmlschema.__version__, elementpath.__version__, sys.version, str(path)):
        key.update(part.encode() + b"\0")
    for file in sorted(path.parent.iterdir()):
        if file.is_file():
            key.update(file.name.encode() + b"\0" + file.read_bytes() + b"\0")
    return folder / "xsd11" / f"{version[0]}.{version[1]}-{key.hexdigest()[:32]}.pickle"


def compiled(version: tuple[int, int]):
    """The compiled schema of a declared version (cached; ``KeyError`` when there is none)."""
    if version not in SCHEMA_FOLDERS:
        raise KeyError(version)
    with _lock:  # xmlschema's build is not re-entrant; one build per version per process
        return _compiled(version)


@cache
def target_namespace(version: tuple[int, int]) -> str | None:
    """The namespace the schema of ``version`` puts the file's elements in (its ``targetNamespace``: 1.1 and 1.2
    ``www.vires.com``), ``None`` when it has none (1.3 on). ``KeyError`` when there is no schema for it."""
    from lxml import etree

    if version not in SCHEMA_FOLDERS:
        raise KeyError(version)
    with _schema_file(version).open("rb") as source:
        for _, root in etree.iterparse(source, events=("start",), resolve_entities=False, no_network=True):
            return root.get("targetNamespace") or None
    return None


def namespace_mismatch(tree, version: tuple[int, int]) -> tuple[str | None, str | None] | None:
    """``(the file's namespace, the schema's)`` when the root element is not in the namespace the schema of
    ``version`` declares its elements in (a 1.1 file without ``xmlns="www.vires.com"``, as every tool writes them),
    else ``None``."""
    from lxml import etree

    found = etree.QName(tree.getroot()).namespace
    expected = target_namespace(version)
    return None if found == expected else (found, expected)


def in_namespace(tree, found: str | None, namespace: str | None):
    """A copy of ``tree`` whose elements in namespace ``found`` (the root's) are in ``namespace`` instead (``None``:
    in none); elements of other namespaces (vendor data) and source lines are kept."""
    import copy

    from lxml import etree

    root = copy.deepcopy(tree.getroot())
    prefix = "" if found is None else "{" + found + "}"
    target = "" if namespace is None else "{" + namespace + "}"
    for el in root.iter():
        tag = el.tag
        if not isinstance(tag, str):
            continue
        if found is None and tag[0] != "{":
            el.tag = target + tag
        elif found is not None and tag.startswith(prefix):
            el.tag = target + tag[len(prefix) :]
    etree.cleanup_namespaces(root)
    return etree.ElementTree(root)


def validate(tree, version: tuple[int, int]) -> Iterator[SchemaError]:
    """Validate an lxml tree against the schema of ``version``, yielding each error with its source line."""
    if version in XSD11:
        from xodrcheck.schema import fast as schema_fast

        folder, main = SCHEMA_FOLDERS[version]
        failures = schema_fast.assertion_failures(tree, folder, main)
        if failures is not None:
            # valid by lxml on the XSD 1.0 part plus the alternatives, and these assertions false (schema_fast): the
            # full validator's errors, worded as it words them
            for failure in failures:
                elem = failure.elem
                yield SchemaError(
                    elem.sourceline or 0,
                    f"Element '{elem.tag}': assertion test is false: {' '.join(failure.test.split())}",
                )
            return
        for err in compiled(version).iter_errors(tree):
            line = getattr(err, "sourceline", None) or 0
            reason = err.reason or str(err.message)
            test = getattr(err.validator, "path", None) if type(err.validator).__name__ == "XsdAssert" else None
            if test:
                reason = f"{reason}: {' '.join(str(test).split())}"
            yield SchemaError(int(line), f"{xpath_hint(err)}{reason}")
        return
    schema = compiled(version)
    schema.validate(tree)
    for entry in schema.error_log:
        yield SchemaError(entry.line or 0, entry.message)


def xpath_hint(err) -> str:
    elem = getattr(err, "elem", None)
    tag = getattr(elem, "tag", None)
    return f"Element '{tag}': " if isinstance(tag, str) else ""
