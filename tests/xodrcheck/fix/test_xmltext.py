"""The byte-span scanner fixes edit with (:mod:`xodrcheck.fix.xmltext`): the same elements, lines and attribute values
lxml reads, and spans that cut the file exactly where its markup is."""

from __future__ import annotations

import pytest
from lxml import etree

from tests.conftest import corpus_files
from xodrcheck.fix.xmltext import ScanError, decode_value, encode_value, scan


def _lxml_view(data: bytes) -> list[tuple[str, int, dict[str, str]]]:
    parser = etree.XMLParser(resolve_entities=False, huge_tree=True, no_network=True)
    root = etree.fromstring(data, parser)
    return [(etree.QName(e).localname, e.sourceline, dict(e.attrib)) for e in root.iter() if isinstance(e.tag, str)]


def _ours(data: bytes) -> list[tuple[str, int, dict[str, str]]]:
    """As lxml shows them: namespace declarations are not attributes there."""
    return [
        (e.tag, e.line, {k: a.value for k, a in e.attributes.items() if not k.startswith("xmlns")})
        for e in scan(data).elements
    ]


def test_every_corpus_file_scans_as_lxml_reads_it(corpus_dir):
    files = corpus_files()
    for path in files:
        data = path.read_bytes()
        assert _ours(data) == _lxml_view(data), path


TRICKY = b"""<?xml version="1.0" encoding="UTF-8"?>
<!-- a <road id="fake"> in a comment -->
<OpenDRIVE xmlns:x="urn:x">
  <?pi <road id="in a processing instruction"/> ?>
  <header revMajor='1' revMinor="7" name="a &gt; b &amp; &#x41;"
          vendor="multi-line start tag"/>
  <road id="1" name="x > y" length="1"><x:userData><![CDATA[ <road id="cdata"/> ]]></x:userData></road>
</OpenDRIVE>
"""


def test_comments_cdata_instructions_and_quoted_gt_are_skipped():
    assert _ours(TRICKY) == _lxml_view(TRICKY)
    text = scan(TRICKY)
    road = text.root.find("road")
    assert road is not None and road.get("name") == "x > y"
    assert text.data[road.start : road.head_end] == b'<road id="1" name="x > y" length="1">'
    assert text.data[road.inner_end : road.end] == b"</road>"
    header = text.root.find("header")
    assert header is not None and header.self_closing and header.get("name") == "a > b & A"
    assert header.attributes["revMajor"].quote == b"'"
    assert text.data[header.attributes["revMinor"].start : header.attributes["revMinor"].end] == b"7"
    assert [e.tag for e in text.at_line(7)] == ["road", "userData"]


def test_lines_end_at_newlines_as_libxml2_counts_them():
    data = b'<?xml version="1.0"?>\r\n<OpenDRIVE>\r<header revMajor="1"\r\n revMinor="4"/>\n<road id="1"/></OpenDRIVE>'
    assert _ours(data) == _lxml_view(data)
    assert scan(data).newline == b"\r\n"


@pytest.mark.parametrize(
    "data",
    [
        b"<OpenDRIVE><road></OpenDRIVE>",
        b"<OpenDRIVE><road/>",
        b"<OpenDRIVE/><OpenDRIVE/>",
        b"<OpenDRIVE><!-- never closed </OpenDRIVE>",
        b"<OpenDRIVE a=1/>",
        b"no markup at all",
        "<OpenDRIVE/>".encode("utf-16"),
        b'<?xml version="1.0" encoding="no-such-codec"?><OpenDRIVE/>',
        b'<OpenDRIVE a="1" a="2"/>',
    ],
)
def test_what_cannot_be_edited_safely_is_refused(data):
    with pytest.raises(ScanError):
        text = scan(data)
        for element in text.elements:
            element.attributes  # noqa: B018 (attributes are read when asked for)


def test_values_decode_and_encode_as_xml_does():
    assert decode_value(b"a&lt;b&amp;&#65;&#x42;&quot;", "utf-8") == 'a<b&AB"'
    assert encode_value("a<b&\"c'", "utf-8", b'"') == b"a&lt;b&amp;&quot;c'"
    assert encode_value("a\"b'", "latin-1", b"'") == b'a"b&apos;'
    assert encode_value("\u20ac", "iso8859-1") == b"&#8364;"
