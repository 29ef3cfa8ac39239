"""OpenDRIVE 1.9 acceptance: every element and attribute 1.9 introduced (the XSD diff 1.8.1 -> 1.9.0, which covers the
revision history G.2) occurs in a test document that validates and checks clean, on the fast path; a 1.9 file with
a 1.9-only error is caught by S001."""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from tests.xodrcheck import schemadocs as D
from xodrcheck import check
from xodrcheck.schema import fast as schema_fast
from xodrcheck.schema import validate as schema

HERE = Path(__file__).parent
REPO = HERE.parents[1]
DOCUMENTS = sorted((HERE / "opendrive19").glob("*.xodr"))
REVISION_HISTORY = REPO.parent / "shared" / "reference" / "opendrive-1.9" / "ASAM-OpenDRIVE-revision-history-V1-9-0.md"
V19 = (1, 9)


@cache
def _official(release: str) -> xmlschema.XMLSchema11:
    return xmlschema.XMLSchema11(str(REPO / "schemas" / release / "OpenDRIVE_Core.xsd"))


def _enumeration(simple_type) -> tuple[str, ...]:
    return tuple(getattr(simple_type, "enumeration", None) or ())


def _members(validator: xmlschema.XMLSchema11) -> set[tuple[str, str]]:
    """(type, member) of every named type: ``@attribute`` and ``child`` of complex types, ``=value`` of enumerations."""
    found = set()
    for name, xsd_type in validator.types.items():
        if xsd_type.is_simple():
            found.update((name, f"={value}") for value in _enumeration(xsd_type))
            continue
        found.update((name, f"@{attribute}") for attribute in xsd_type.attributes if attribute)
        content = xsd_type.content
        if hasattr(content, "iter_elements"):
            found.update((name, element.local_name) for element in content.iter_elements() if element.local_name)
    return found


@cache
def introduced_in_19() -> frozenset[tuple[str, str]]:
    """What the official 1.9.0 schema has and 1.8.1 has not: (type, ``@attribute`` | ``child`` | ``=value``)."""
    return frozenset(_members(_official("1.9.0")) - _members(_official("1.8.1")))


def _lineage(xsd_type) -> list[str]:
    """The names of a type and of the types it derives from (a member a type inherits is used through it)."""
    names = []
    while xsd_type is not None and xsd_type.name and xsd_type.name not in names:
        names.append(xsd_type.name)
        xsd_type = getattr(xsd_type, "base_type", None)
    return names


def _used(tree: etree._ElementTree, validator: xmlschema.XMLSchema11) -> set[tuple[str, str]]:
    """(type, member) a document uses, its elements typed by walking the schema's declarations along it (the type
    alternatives resolved), as :func:`_members` names them, for the element's type and the types it derives from."""
    used = set()
    root = tree.getroot()
    stack = [(root, validator.elements[root.tag])]
    while stack:
        elem, decl = stack.pop()
        xsd_type = decl.type
        for alternative in getattr(decl, "alternatives", ()):
            if alternative.token is None or alternative.test(elem):
                xsd_type = alternative.type
                break
        names = _lineage(xsd_type)
        if xsd_type.is_simple():
            used.add((xsd_type.name, f"={(elem.text or '').strip()}"))
            continue
        for attribute, value in elem.attrib.items():
            used.update((name, f"@{attribute}") for name in names)
            attribute_decl = xsd_type.attributes.get(attribute)
            if attribute_decl is not None and attribute_decl.type.name:
                used.add((attribute_decl.type.name, f"={value}"))
        children = {e.local_name: e for e in xsd_type.content.iter_elements()} if xsd_type.has_complex_content() else {}
        for child in elem:
            if isinstance(child.tag, str) and child.tag in children:
                used.update((name, child.tag) for name in names)
                stack.append((child, children[child.tag]))
    return used


def test_the_diff_finds_what_1_9_introduced():
    """The diff is not empty and holds what the standard's text names (sanity of the walk itself)."""
    new = introduced_in_19()
    for expected in [
        ("t_road_lanes", "@layer"),
        ("t_road_lanes_laneSection", "@length"),
        ("t_junction_connection_laneLink", "@fromLayer"),
        ("t_road_objects_object_outlines_outline", "curveLocal"),
        ("e_signals_semantics_lane", "=other"),
    ]:
        assert expected in new, expected
    assert ("t_road", "lanes") not in new  # a changed multiplicity, not a new member


def test_the_diff_covers_the_revision_history():
    """Every element and attribute of the revision history (G.2) is in the diff (which also has what G.2 leaves
    out: lane layers, lane-section length, junction lane-link layers, outline markings)."""
    text = REVISION_HISTORY.read_text(encoding="utf-8")
    named_members = {member for _, member in introduced_in_19()}
    elements = set(re.findall(r"XML element: <(\w+)>\nIntroduced:", text))
    attributes = set(re.findall(r"^\| (\w+) \| 1\.9\.0 \|$", text, re.MULTILINE))
    assert elements >= {"curveLocal", "line", "arc", "paramPoly3", "person", "animal", "vehicle"}
    assert {"layer", "invalidated", "temporary", "bT", "cT", "dT", "xOffset", "yOffset", "other"} <= attributes
    for tag in elements:
        assert tag in named_members, tag
    for attribute in attributes:
        assert f"@{attribute}" in named_members or f"={attribute}" in named_members, attribute


def test_every_member_1_9_introduced_occurs_in_a_test_document():
    validator = schema.compiled(V19)
    used: set[tuple[str, str]] = set()
    for path in DOCUMENTS:
        used |= _used(etree.parse(str(path)), validator)
    new = introduced_in_19()
    new_enum_types = {t for t, m in new if m.startswith("=")} - {t for t, m in _members(_official("1.8.1"))}
    required = {(t, m) for t, m in new if not (m.startswith("=") and t in new_enum_types)}
    missing = sorted(required - used)
    assert not missing, f"introduced in 1.9 but in no test document: {missing}"
    for enum_type in new_enum_types:  # a new enumeration: at least one of its values
        assert any(t == enum_type for t, _ in used), enum_type


@pytest.mark.parametrize("path", DOCUMENTS, ids=lambda p: p.name)
def test_each_test_document_validates_on_the_fast_path_and_checks_clean(path):
    tree = etree.parse(str(path))
    folder, main = schema.SCHEMA_FOLDERS[V19]
    assert [e.reason for e in schema.compiled(V19).iter_errors(tree)] == []
    assert schema_fast.is_valid(tree, folder, main)
    # Both documents route their two roads through a junction, to carry 1.9's junction attributes (laneLink
    # fromLayer/toLayer, the junction's own elements) on the smallest map; J019 junction-unneeded rightly says such a
    # junction is not needed (junctions.common.when_to_use / not_only_two), and nothing else may be found.
    report = check(path)
    assert {f.code for f in report.findings} <= {"J019"}, [f"{f.code} {f.message}" for f in report.findings]
    assert check(path, ignore=("J019",)).ok


#: 1.9-only errors: name -> (what goes into doc(), the text on the line S001 must point at)
ERRORS_19 = {
    "unknown lane layer": (
        {"lanes": D.ROAD_LANES.replace("<lanes>", '<lanes layer="provisional">')},
        '<lanes layer="provisional">',
    ),
    # (the schema's assertion sees only an explicit layer="permanent", not the default: that is a rule's job)
    "section length on the permanent layer": (
        {
            "lanes": D.ROAD_LANES.replace("<lanes>", '<lanes layer="permanent">').replace(
                '<laneSection s="0">', '<laneSection s="0" length="5">'
            )
        },
        '<lanes layer="permanent">',
    ),
    "object temporary not a boolean": (
        {
            "road": '<objects><object id="o1" s="1" t="-5" zOffset="0" type="pole" orientation="none" '
            'temporary="maybe"/></objects>'
        },
        'temporary="maybe"',
    ),
    "curveLocal without its shape": (
        {"road": D.island('<outline id="0"><curveLocal u="0" v="0" z="0" height="0.2" hdg="0" length="1"/></outline>')},
        "<curveLocal",
    ),
    "vehicle category unknown": (
        {
            "road": '<signals><signal id="s1" s="1" t="-4" zOffset="1" dynamic="no" orientation="+" type="x" '
            'subtype="-1"><semantics><prohibited><vehicle><type>spaceship</type></vehicle></prohibited>'
            "</semantics></signal></signals>"
        },
        "<type>spaceship</type>",
    ),
}


@pytest.mark.parametrize("name", sorted(ERRORS_19))
def test_a_1_9_only_error_is_caught_by_s001(name, tmp_path):
    kwargs, marker = ERRORS_19[name]
    path = tmp_path / "map.xodr"
    path.write_bytes(D.doc(9, **kwargs))
    findings = [f for f in check(path).findings if f.code == "S001"]
    assert findings, name
    assert all("1.9.0 schema" in f.message for f in findings)
    lines = path.read_text().splitlines()
    assert any(marker in lines[f.line - 1] for f in findings if f.line), [(f.line, f.message) for f in findings]
