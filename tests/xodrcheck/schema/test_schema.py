"""Schema selection by declared version, compilation once per process, errors with source lines."""

from __future__ import annotations

import pytest
from lxml import etree

from xodrcheck.schema import validate as schema


@pytest.mark.parametrize("version", sorted(schema.SCHEMA_FOLDERS))
def test_every_shipped_schema_compiles_once(version):
    first = schema.compiled(version)
    assert schema.compiled(version) is first


def test_minor_versions_map_to_their_latest_patch_release():
    assert schema.schema_name((1, 4)) == "1.4"
    assert schema.schema_name((1, 6)) == "1.6.1"
    assert schema.schema_name((1, 7)) == "1.7.0"
    assert schema.schema_name((1, 8)) == "1.8.1"
    assert schema.schema_name((1, 9)) == "1.9.0"
    assert schema.schema_name((1, 10)) is None and schema.schema_name((2, 0)) is None
    with pytest.raises(KeyError):
        schema.compiled((1, 10))


def _doc(minor: int, header_extra: str = "") -> etree._ElementTree:
    text = f"""<OpenDRIVE>
  <header revMajor="1" revMinor="{minor}"{header_extra}/>
  <road id="1" length="10" junction="-1">
    <planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView>
    <lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center></laneSection></lanes>
  </road>
</OpenDRIVE>"""
    return etree.ElementTree(etree.fromstring(text.encode()))


@pytest.mark.parametrize("minor", [6, 7, 8, 9])
def test_a_minimal_map_is_valid(minor):
    assert list(schema.validate(_doc(minor), (1, minor))) == []


@pytest.mark.parametrize("minor", [6, 7, 8, 9])
def test_an_error_carries_its_line(minor):
    (err,) = list(schema.validate(_doc(minor, ' bogus="1"'), (1, minor)))
    assert err.line == 2 and "bogus" in err.message
