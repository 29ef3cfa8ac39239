"""The OpenDRIVE reader at the XML level: declarations, encodings, namespaces, DOCTYPEs and entities, broken XML."""

from __future__ import annotations

import pytest

from tests.xodrcheck.readerdocs import (
    DECL,
    clean,
    codes,
    only,
    road,
    xodr,
)
from xodrcheck.findings import Severity
from xodrcheck.reader import read


def test_comment_before_declaration_keeps_line_numbers():
    data = b"<!-- exported by a tool -->\n\n" + xodr(road())
    result = read(data)
    finding = only(result, "X103")
    assert finding.severity is Severity.WARNING and "a comment" in finding.message and "line 3" in finding.message
    assert result.document.roads[0].line == 5


def test_text_before_declaration():
    result = read(b"garbage\n" + xodr(road()))
    assert "text ('garbage')" in only(result, "X103").message
    assert result.document.roads[0].line == 4


def test_declaration_missing_is_fine():
    data = xodr(road()).replace(DECL.encode(), b"")
    assert clean(data).roads[0].line == 2


def test_utf8_bom_is_fine():
    assert clean(b"\xef\xbb\xbf" + xodr(road())).roads[0].id == "1"


@pytest.mark.parametrize("codec", ["utf-16", "utf-16-le", "utf-16-be", "utf-32"])
def test_wide_encodings_are_read_with_a_warning(codec):
    text = xodr(road(attrs='id="Straße" length="10" junction="-1"')).decode().replace("UTF-8", codec.upper())
    result = read(text.encode(codec))
    assert only(result, "X104").severity is Severity.WARNING
    assert result.document.roads[0].id == "Straße"


def test_declared_latin1_with_non_ascii_is_read_with_a_warning():
    text = xodr(road(attrs='id="Straße" length="10" junction="-1"')).decode().replace("UTF-8", "ISO-8859-1")
    result = read(text.encode("latin-1"))
    assert "ISO-8859-1" in only(result, "X104").message
    assert result.document.roads[0].id == "Straße"


def test_declared_latin1_with_ascii_only_passes():
    assert clean(xodr(road()).replace(b"UTF-8", b"ISO-8859-1")).roads[0].id == "1"


def test_namespaced_document_is_read_by_local_names():
    data = xodr(road(), version=(1, 1)).replace(b"<OpenDRIVE>", b'<OpenDRIVE xmlns="www.vires.com">')
    doc = clean(data)
    assert doc.version == (1, 1) and doc.roads[0].plan_view[0].length == 10.0


def test_bare_doctype_is_a_warning():
    data = xodr(road()).replace(b"<OpenDRIVE>", b"<!DOCTYPE OpenDRIVE>\n<OpenDRIVE>")
    result = read(data)
    assert only(result, "X102").severity is Severity.WARNING
    assert result.document.roads[0].line == 4


def test_doctype_with_entities_is_an_error_and_not_expanded():
    doctype = b'<!DOCTYPE OpenDRIVE [\n<!ENTITY len "10">\n]>\n'
    data = xodr(road(attrs='id="1" length="&len;" junction="-1"')).replace(b"<OpenDRIVE>", doctype + b"<OpenDRIVE>")
    result = read(data)
    x102 = only(result, "X102")
    assert x102.severity is Severity.ERROR
    # one finding for one cause: the reference is counted by X102, not reported again as "Entity 'len' not defined"
    assert "X101" not in codes(result)
    assert "the 1 reference to them, the first at line 6, was left out" in x102.message
    assert result.document is not None and result.document.roads  # the rest of the file is read
    assert result.not_whole() is not None and "X102" in result.not_whole()


def test_undefined_entity_not_declared_in_the_doctype_is_still_not_well_formed():
    doctype = b'<!DOCTYPE OpenDRIVE [\n<!ENTITY len "10">\n]>\n'
    data = xodr(road(attrs='id="1" length="&other;" junction="-1"')).replace(b"<OpenDRIVE>", doctype + b"<OpenDRIVE>")
    result = read(data)
    assert "X101" in codes(result) and "Entity 'other' not defined" in only(result, "X101").message
    assert "was left out" not in only(result, "X102").message


def test_external_entity_is_never_read(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("MARKER-7f3a9c-SECRET")
    doctype = f'<!DOCTYPE OpenDRIVE [<!ENTITY s SYSTEM "file://{secret}">]>'.encode()
    header = '<header revMajor="1" revMinor="6" name="&s;"/>'
    data = xodr(road(attrs='id="&s;" length="10" junction="-1"'), header=header)
    data = data.replace(b"<OpenDRIVE>", doctype + b"<OpenDRIVE>")
    result = read(data)
    assert "X102" in codes(result)
    dump = repr(result)
    assert "MARKER-7f3a9c" not in dump


def test_not_well_formed_gives_the_line_and_what_could_be_recovered():
    data = xodr(road(), road(attrs='id="2" length="10" junction="-1"'))
    result = read(data[: data.index(b'<road id="2"') + 40])
    finding = only(result, "X101")
    assert finding.line == 4 and "may be missing" in finding.message
    assert [r.id for r in result.document.roads][:1] == ["1"]


def test_wrong_root():
    result = read(DECL.encode() + b"<OpenSCENARIO><FileHeader/></OpenSCENARIO>")
    assert "<OpenSCENARIO>" in only(result, "X201").message
    assert result.document is None
