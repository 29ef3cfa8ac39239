"""Fixtures of the generator's tests: schemas loaded once, small maps generated once per session."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import junctionart as ja
from junctionart.params import Params

REPO = Path(__file__).resolve().parents[2]
SCHEMA_18 = REPO / "schemas" / "1.8.1" / "OpenDRIVE_Core.xsd"
SCHEMA_17 = REPO / "schemas" / "1.7.0" / "opendrive_17_core.xsd"
SCHEMA_19 = REPO / "schemas" / "1.9.0" / "OpenDRIVE_Core.xsd"  # the official file, not xodrcheck's corrected copy


@pytest.fixture(scope="session")
def schema18():
    import xmlschema

    return xmlschema.XMLSchema11(str(SCHEMA_18))


@pytest.fixture(scope="session")
def schema19():
    import xmlschema

    return xmlschema.XMLSchema11(str(SCHEMA_19))


@pytest.fixture(scope="session")
def schema17():
    return etree.XMLSchema(etree.parse(str(SCHEMA_17)))


@pytest.fixture(scope="session")
def random_500():
    """Five random-lane 500 m maps with curved roads (stage values and document)."""
    p = Params(randomize_lanes=True, curved_roads=True)
    return [ja.generate_layout(p, seed) for seed in range(5)]
