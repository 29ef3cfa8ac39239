"""The fast XSD 1.1 verdict (xodrcheck.schema.fast) against the full validator (xmlschema), for OpenDRIVE 1.8 and 1.9:
it may only say "valid" where xmlschema finds no error, and it must say so for valid files, or the speed is lost."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree

import junctionart as ja
from junctionart.fuzz.documents import opendrive_documents
from junctionart.fuzz.mutations import damaged_documents
from xodrcheck.schema import fast as schema_fast
from xodrcheck.schema import validate as schema

V18 = (1, 8)
V19 = (1, 9)
XSD11_VERSIONS = pytest.mark.parametrize("version", [V18, V19], ids=["1.8", "1.9"])


def _tree(data: bytes):
    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
    return etree.ElementTree(etree.fromstring(data, parser))


def _version_of(tree) -> tuple[int, int]:
    """The declared version; 1.8 when the header does not declare one with a schema (a damaged ``revMinor``, say)."""
    header = tree.getroot().find("header")
    minor = "" if header is None else header.get("revMinor", "")
    version = (1, int(minor)) if minor.isdigit() else V18
    return version if version in schema.SCHEMA_FOLDERS else V18


def _fast(tree, version=None) -> bool:
    version = version or _version_of(tree)
    folder, main = schema.SCHEMA_FOLDERS[version]
    return schema_fast.is_valid(tree, folder, main)


def _full(tree, version=None) -> list[str]:
    """Errors of the full XSD 1.1 validator alone."""
    version = version or _version_of(tree)
    return [str(e.reason or e.message) for e in schema.compiled(version).iter_errors(tree)]


LANES = """<lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center>
      <right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
    </laneSection></lanes>"""


def _doc(junctions: str = "", objects: str = "", extra_root: str = "", minor: int = 8, lanes: str = LANES) -> bytes:
    """Three roads (the third inside junction 100) and ``junctions``; road 1 has ``lanes`` and ``objects``."""
    road = """<road id="{id}" length="10" junction="{junction}">{link}
    <planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView>
    {lanes}{objects}
  </road>"""
    roads = "".join(
        road.format(id=i, junction=j, link="", objects=objects if i == 1 else "", lanes=lanes if i == 1 else LANES)
        for i, j in ((1, "-1"), (2, "-1"), (3, "100"))
    )
    return (
        f'<?xml version="1.0" encoding="UTF-8"?>\n<OpenDRIVE{extra_root}><header revMajor="1" revMinor="{minor}"/>'
        f"{roads}{junctions}</OpenDRIVE>"
    ).encode()


COMMON = (
    '<junction id="100" name="j"><connection id="0" incomingRoad="1" connectingRoad="3" contactPoint="start">'
    '<laneLink from="-1" to="-1"/></connection></junction>'
)
DIRECT = (
    '<junction id="100" name="j" type="direct"><connection id="0" incomingRoad="1" linkedRoad="2" '
    'contactPoint="start"><laneLink from="-1" to="-1"/></connection></junction>'
)


@XSD11_VERSIONS
@pytest.mark.parametrize("junction", [COMMON, DIRECT], ids=["common", "direct"])
def test_valid_junctions_of_each_type_are_shown_valid(junction, version):
    tree = _tree(_doc(junction, minor=version[1]))
    assert _full(tree) == []
    assert _fast(tree)


_PERMANENT_WITH_LENGTH = (
    '<lanes layer="permanent"><laneSection s="0" length="10"><center><lane id="0" type="none" level="false"/>'
    '</center><right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>'
    "</lane></right></laneSection></lanes>"
)

#: name -> (minor versions, document builder): documents only an XSD 1.1 part of the schema rejects
XSD11_ONLY_ERRORS = {
    # an assertion (connection ids unique in a junction) is all that fails
    "assertion": (
        (8, 9),
        lambda minor: _doc(
            COMMON.replace(
                "</junction>", COMMON[COMMON.index("<connection") : COMMON.index("</junction>")] + "</junction>"
            ),
            minor=minor,
        ),
    ),
    # an alternative: a direct junction's connection needs linkedRoad, a common one's connectingRoad
    "alternative": ((8, 9), lambda minor: _doc(DIRECT.replace('linkedRoad="2"', 'connectingRoad="3"'), minor=minor)),
    # an object assertion: radius together with width and length
    "object-assertion": (
        (8, 9),
        lambda minor: _doc(
            COMMON,
            objects='<objects><object id="o" s="1" t="0" zOffset="0" radius="1" '
            'width="1" length="1" type="pole" orientation="none"/></objects>',
            minor=minor,
        ),
    ),
    # 1.9: a lane section of the permanent layer has no length (11.2)
    "lane-layer-assertion": ((9,), lambda minor: _doc(COMMON, minor=minor, lanes=_PERMANENT_WITH_LENGTH)),
}


@pytest.mark.parametrize(
    ("name", "minor"), [(name, minor) for name, (minors, _) in XSD11_ONLY_ERRORS.items() for minor in minors]
)
def test_xsd11_only_errors_are_not_shown_valid(name, minor):
    tree = _tree(XSD11_ONLY_ERRORS[name][1](minor))
    assert _full(tree), name  # the case is invalid for the full validator ...
    assert not _fast(tree)  # ... and the fast verdict does not hide it
    assert list(schema.validate(tree, (1, minor)))  # so validate() reports it


def test_where_libxml2_is_stricter_the_full_validator_decides():
    """A junction connection naming a road that does not exist breaks keyref r_junction_connection_incomingRoad;
    libxml2 sees it, xmlschema 4 does not. S001 stays the XSD 1.1 validator's verdict (rule R011 reports the missing
    road)."""
    tree = _tree(_doc(COMMON.replace('incomingRoad="1"', 'incomingRoad="9"')))
    assert not _fast(tree)
    assert list(schema.validate(tree, V18)) == _full(tree) == []


def test_xsi_attributes_go_to_the_full_validator():
    tree = _tree(
        _doc(
            COMMON,
            extra_root=' xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="x.xsd"',
        )
    )
    assert not _fast(tree)


def test_comments_and_processing_instructions_are_skipped():
    tree = _tree(_doc(COMMON.replace("<laneLink", "<!-- a comment --><?pi x?><laneLink")))
    assert _full(tree) == [] and _fast(tree)


@pytest.mark.parametrize("seed", [1, 2])
def test_generated_maps_are_shown_valid(seed):
    params = ja.Params(
        width=500, height=500, randomize_lanes=True, u_turn_probability=1.0, median_probability=0.6, median_width=8.0
    )
    tree = _tree(ja.to_bytes(ja.generate(params, seed)))
    assert _full(tree) == []
    assert _fast(tree)


def _corpus_18(corpus: Path) -> list[Path]:
    found = []
    for path in sorted(corpus.rglob("*.xodr")):
        head = path.read_bytes()[:4000]
        if b'revMinor="8"' in head or b"revMinor='8'" in head:
            found.append(path)
    return found


@pytest.mark.corpus
def test_corpus_18_files_get_the_same_verdict(corpus_dir):
    paths = _corpus_18(corpus_dir)
    if not paths:
        pytest.fail(f"no OpenDRIVE 1.8 file found under {corpus_dir}")
    for path in paths:
        tree = etree.parse(str(path), etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True))
        full = _full(tree)
        assert _fast(tree) == (not full), (path.name, full[:3])


_V18_DOCS = opendrive_documents(versions=(V18,), max_roads_per_chain=2, max_elements=2, max_lanes=2)
_V19_DOCS = opendrive_documents(versions=(V19,), max_roads_per_chain=2, max_elements=2, max_lanes=2)


def _takes_the_fast_path(data: bytes) -> None:
    tree = _tree(data)
    assert _full(tree) == []
    assert _fast(tree)


def _damaged_is_not_shown_valid(data: bytes) -> None:
    try:
        tree = _tree(data)
    except etree.XMLSyntaxError:
        return  # not well-formed: no schema validation at all
    full = _full(tree)
    assert not (_fast(tree) and full), full[:3]


@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(_V18_DOCS)
def test_valid_documents_take_the_fast_path(data):
    _takes_the_fast_path(data)


@settings(max_examples=200, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(base=_V18_DOCS, min_mutations=1, max_mutations=3))
def test_damaged_documents_are_never_shown_valid_when_they_are_not(data):
    _damaged_is_not_shown_valid(data)


@settings(max_examples=20, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(_V19_DOCS)
def test_valid_19_documents_take_the_fast_path(data):
    assert b'revMinor="9"' in data
    _takes_the_fast_path(data)


@settings(max_examples=100, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(base=_V19_DOCS, min_mutations=1, max_mutations=3))
def test_damaged_19_documents_are_never_shown_valid_when_they_are_not(data):
    _damaged_is_not_shown_valid(data)


def _full_messages(tree, version) -> list[schema.SchemaError]:
    """What schema.validate gives when it takes the full validator's path."""
    errors = []
    for err in schema.compiled(version).iter_errors(tree):
        reason = err.reason or str(err.message)
        if type(err.validator).__name__ == "XsdAssert":
            reason = f"{reason}: {' '.join(str(err.validator.path).split())}"
        errors.append(schema.SchemaError(int(err.sourceline or 0), f"{schema.xpath_hint(err)}{reason}"))
    return errors


def _failures_are_the_full_errors(data: bytes) -> bool:
    """Where the fast path gives the errors itself (assertions only), they are the full validator's, in its order and
    words; returns whether it did."""
    try:
        tree = _tree(data)
    except etree.XMLSyntaxError:
        return False
    version = _version_of(tree)
    folder, main = schema.SCHEMA_FOLDERS[version]
    if schema_fast.assertion_failures(tree, folder, main) is None:
        return False
    assert list(schema.validate(tree, version)) == _full_messages(tree, version)
    return True


@pytest.mark.parametrize(
    ("name", "minor"), [(name, minor) for name, (minors, _) in XSD11_ONLY_ERRORS.items() for minor in minors]
)
def test_assertion_errors_are_given_as_the_full_validator_gives_them(name, minor):
    data = XSD11_ONLY_ERRORS[name][1](minor)
    # an alternative's error is in the XSD 1.0 part (lxml): only the full validator words it
    assert _failures_are_the_full_errors(data) is (name != "alternative")


_OBJECT = '<object id="{i}" s="1" t="0" zOffset="0" {size} type="{kind}" orientation="none">{inner}</object>'


@pytest.mark.parametrize("minor", [8, 9])
def test_several_false_assertions_come_in_the_full_validators_order(minor):
    """Several objects, one failing two assertions, in document order; a junction with a repeated connection id."""
    objects = "".join(
        _OBJECT.format(i=i, size=size, kind=kind, inner=inner)
        for i, (size, kind, inner) in enumerate(
            [
                ('radius="1" width="1" length="1"', "barrier", ""),  # both the size and the barrier assertion
                ('width="1"', "pole", ""),
                ('radius="1"', "pole", ""),  # valid
                (
                    'width="1" length="1"',
                    "building",
                    '<repeat s="0" length="1" distance="0" tStart="0" tEnd="0" '
                    'heightStart="1" heightEnd="1" zOffsetStart="0" zOffsetEnd="0"/>',
                ),
            ]
        )
    )
    junction = COMMON.replace(
        "</junction>", COMMON[COMMON.index("<connection") : COMMON.index("</junction>")] + "</junction>"
    )
    data = _doc(junction, objects=f"<objects>{objects}</objects>", minor=minor)
    assert _failures_are_the_full_errors(data)
    assert len(list(schema.validate(_tree(data), (1, minor)))) >= 4


def test_whitespace_typing_could_normalise_goes_to_the_full_validator():
    data = _doc(
        COMMON,
        objects=_OBJECT.join(("<objects>", "</objects>")).format(
            i=1, size='radius="1" width=" 1" length="1"', kind="pole", inner=""
        ),
    )
    assert not _failures_are_the_full_errors(data)


_KINDS = ("none", "barrier", "building", "crosswalk", "gantry", "obstacle", "parkingSpace", "pole", "tree", "roadMark")
_REPEAT = (
    '<repeat s="0" length="1" distance="{}" tStart="0" tEnd="0" heightStart="1" heightEnd="1" zOffsetStart="0" '
    'zOffsetEnd="0"/>'
)


@st.composite
def _objects(draw) -> str:
    """Objects with any mix of sizes, types, repeats (distances of several spellings) and materials: most break one
    assertion or more, nothing else."""
    out = []
    for i in range(draw(st.integers(1, 4))):
        size = " ".join(
            f'{a}="{draw(st.sampled_from(("1", "0.5", "2e0")))}"'
            for a in ("radius", "width", "length")
            if draw(st.booleans())
        )
        repeats = "".join(
            _REPEAT.format(draw(st.sampled_from(("0", "1", "0.0", "2.5", "1e1", "+0", "-0"))))
            for _ in range(draw(st.integers(0, 2)))
        )
        material = '<material friction="0.5"/>' if draw(st.booleans()) else ""
        kind = draw(st.sampled_from(_KINDS))
        out.append(_OBJECT.format(i=i, size=size, kind=kind, inner=repeats + material))
    return "".join(out)


@settings(max_examples=60, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(_objects(), st.sampled_from([8, 9]))
def test_objects_breaking_assertions_get_the_full_validators_errors(objects, minor):
    _failures_are_the_full_errors(_doc(COMMON, objects=f"<objects>{objects}</objects>", minor=minor))


@settings(max_examples=200, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(base=_V18_DOCS, min_mutations=1, max_mutations=3))
def test_damaged_documents_get_the_full_validators_errors(data):
    _failures_are_the_full_errors(data)


@settings(max_examples=100, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(base=_V19_DOCS, min_mutations=1, max_mutations=3))
def test_damaged_19_documents_get_the_full_validators_errors(data):
    _failures_are_the_full_errors(data)


class _Recording:
    """Stands for the derived XSD 1.0 schema: records the tree it is asked to validate, then validates it."""

    def __init__(self, schema10) -> None:
        self.schema10 = schema10
        self.seen: list = []
        self.typed: list[str | None] = []

    def validate(self, tree) -> bool:
        self.seen.append(tree)
        junction = tree.getroot().find("junction")
        self.typed.append(None if junction is None else junction.get(f"{{{schema_fast.XSI}}}type"))
        return self.schema10.validate(tree)


@XSD11_VERSIONS
@pytest.mark.parametrize("verdict", ["valid", "invalid"])
def test_the_fast_path_validates_the_tree_in_place_and_restores_it(version, verdict, monkeypatch):
    """No copy of the document (a parsed 50 MB map is gigabytes): the caller's tree itself is typed, validated, and
    given back unchanged, with no xsi:type and no xsi namespace declaration left, valid or not."""
    junction = COMMON if verdict == "valid" else COMMON.replace('contactPoint="start"', 'contactPoint="middle"')
    tree = _tree(_doc(junction, minor=version[1]))
    before = etree.tostring(tree)
    folder, main = schema.SCHEMA_FOLDERS[version]
    recording = _Recording(schema_fast.derived(folder, main))
    monkeypatch.setattr(schema_fast, "derived", lambda *_: recording)
    assert schema_fast.is_valid(tree, folder, main) is (verdict == "valid")
    assert [t is tree for t in recording.seen] == [True]
    assert recording.typed[0] is not None  # the junction carried its selected type while validated
    assert etree.tostring(tree) == before
    assert schema_fast.XSI not in tree.getroot().find("junction").nsmap.values()
