"""The corrected copies of the official 1.8.1 and 1.9.0 XSDs (xodrcheck.schema.errata): shipped exactly as the errata
make them, each correction lets valid documents through that the official file rejects (or catches what it meant to
catch and never did), and the defect each guards against stays an error, for the full validator and the fast verdict."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import pytest
import xmlschema

from tests.xodrcheck import schemadocs as D
from xodrcheck.schema import errata as schema_errata
from xodrcheck.schema import fast as schema_fast
from xodrcheck.schema import validate as schema

REPO = Path(__file__).resolve().parents[3]
MINORS = {"1.8.1": 8, "1.9.0": 9}


@cache
def _official(release: str) -> xmlschema.XMLSchema11:
    return xmlschema.XMLSchema11(str(REPO / "schemas" / release / "OpenDRIVE_Core.xsd"))


def _errors(validator, data: bytes) -> list[str]:
    return [str(e.reason or e.message) for e in validator.iter_errors(D.tree(data))]


def _corrected(minor: int, data: bytes) -> tuple[list[str], bool]:
    """(errors of the full validator, fast verdict) against the corrected schema S001 uses."""
    version = (1, minor)
    folder, main = schema.SCHEMA_FOLDERS[version]
    tree = D.tree(data)
    full = [str(e.reason or e.message) for e in schema.compiled(version).iter_errors(tree)]
    return full, schema_fast.is_valid(tree, folder, main)


@pytest.mark.parametrize("release", sorted(schema_errata.CORRECTED))
def test_shipped_copies_are_the_official_files_with_the_errata(release):
    target = REPO / "schemas" / schema_errata.CORRECTED[release]
    expected = schema_errata.corrected_files(release)
    assert (
        sorted(p.name for p in target.glob("*.xsd"))
        == sorted(expected)
        == sorted(p.name for p in (REPO / "schemas" / release).glob("*.xsd"))
    )
    for name, data in expected.items():
        assert (target / name).read_bytes() == data, f"{target / name}: run scripts/schema_errata.py"
    edited = {e.file for e in schema_errata.ERRATA}
    for name in expected:
        official = (REPO / "schemas" / release / name).read_bytes()
        assert (expected[name] != official) == (name in edited), name


def test_an_erratum_that_no_longer_matches_is_an_error():
    with pytest.raises(schema_errata.ErratumMismatch, match="multiboard-dynamic"):
        schema_errata.correct("OpenDRIVE_Signal.xsd", "<xs:schema/>")


def test_s001_names_the_official_release():
    assert schema.schema_name((1, 8)) == "1.8.1" and schema.schema_name((1, 9)) == "1.9.0"


MULTI_BOARD_STATIC_ONLY = D.MULTI_BOARD[: D.MULTI_BOARD.index("<vmsBoard")] + "</signal></signals>"
_BORDER_FALSE = '<border width="0.2" type="curb" outlineId="0" useCompleteOutline="false">{}</border>'
_BORDER_TRUE = '<border width="0.2" type="curb" outlineId="{}" useCompleteOutline="true"/>'
_CORNERS = '<cornerReference id="0"/><cornerReference id="1"/>'

#: erratum -> (valid documents the official schema gets wrong or misses, documents that stay invalid), as doc() args
CASES = {
    "multiboard-dynamic": (
        [{"road": D.MULTI_BOARD}],
        [
            {"road": D.MULTI_BOARD.replace('dynamic="yes"', 'dynamic="no"', 1)},
            {"road": MULTI_BOARD_STATIC_ONLY},
        ],
    ),
    "vmsgroup-abstract-child": ([{"road": D.MULTI_BOARD, "top": D.VMS_GROUP}], [{"top": '<vmsGroup id="27"/>'}]),
    "regulations-abstract-child": (
        [{"header": D.DEFAULT_REGULATIONS}],
        [{"header": D.DEFAULT_REGULATIONS.replace('type="town"', 'type="city"')}],
    ),
    "outline-id-key": (
        [{"road": D.island(D.outline(0) + D.outline(1))}],
        [{"road": D.island(D.outline(0) + D.outline(0))}],
    ),
    "border-outline-keyref": (
        [{"road": D.island(D.outline(0), _BORDER_TRUE.format(0))}],
        [{"road": D.island(D.outline(0), _BORDER_TRUE.format(7))}],
    ),
    "border-complete-outline": (
        [
            {"road": D.island(D.outline(0), '<border width="0.2" type="curb" outlineId="0"/>')},
            {"road": D.island(D.outline(0), _BORDER_FALSE.format(_CORNERS))},
        ],
        [
            {"road": D.island(D.outline(0), _BORDER_FALSE.format(""))},
            {
                "road": D.island(
                    D.outline(0),
                    f'<border width="0.2" type="curb" outlineId="0" useCompleteOutline="true">{_CORNERS}</border>',
                )
            },
        ],
    ),
}
#: errata whose official text lets an invalid document through (the others reject a valid one)
MISSED_BY_OFFICIAL = {"outline-id-key", "border-outline-keyref"}


def test_every_erratum_has_cases():
    assert set(CASES) == {e.key for e in schema_errata.ERRATA}


@pytest.mark.parametrize("release", sorted(schema_errata.CORRECTED))
@pytest.mark.parametrize("key", sorted(CASES))
def test_each_correction_passes_valid_documents_and_still_catches_its_defect(release, key):
    minor = MINORS[release]
    valid, invalid = CASES[key]
    for kwargs in valid:
        data = D.doc(minor, **kwargs)
        full, fast = _corrected(minor, data)
        assert full == [] and fast, (key, full)
        if key not in MISSED_BY_OFFICIAL:
            assert _errors(_official(release), data), f"{key}: the official schema accepts it already"
    for kwargs in invalid:
        data = D.doc(minor, **kwargs)
        full, fast = _corrected(minor, data)
        assert full and not fast, key
        if key in MISSED_BY_OFFICIAL:
            assert _errors(_official(release), data) == [], f"{key}: the official schema catches it already"
