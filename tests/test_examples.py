"""The maps in examples/ are valid OpenDRIVE: schema-valid for the version they declare, and read without findings."""

from __future__ import annotations

from pathlib import Path

import pytest
import xmlschema

from xodrcheck.reader import read

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((REPO / "examples").glob("*.xodr"))


def test_there_is_an_example():
    assert EXAMPLES


@pytest.fixture(scope="module")
def schema_1_8_1() -> xmlschema.XMLSchema11:
    return xmlschema.XMLSchema11(str(REPO / "schemas" / "1.8.1" / "OpenDRIVE_Core.xsd"))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_is_schema_valid_opendrive_1_8(path: Path, schema_1_8_1):
    result = read(path)
    assert result.document is not None and result.document.version == (1, 8)
    errors = [str(e.reason) for e in schema_1_8_1.iter_errors(str(path))]
    assert not errors, errors[:3]
    assert result.findings == ()
