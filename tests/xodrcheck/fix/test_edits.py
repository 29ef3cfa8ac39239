"""Edits of a file's bytes (:mod:`xodrcheck.fix.edits`): exact, never overlapping, keeping the file's layout."""

from __future__ import annotations

import pytest

from xodrcheck.fix.edits import (
    Edit,
    LineMap,
    OverlapError,
    apply,
    insert_child,
    remove_attribute,
    remove_element,
    set_attribute,
)
from xodrcheck.fix.xmltext import scan

DOC = b"""<OpenDRIVE>
    <road id="1" name='one'>
        <link/>
        <lanes><lane id="-1"><link/><width a="3"/></lane></lanes>
    </road>
</OpenDRIVE>
"""


def _first(text, tag):
    return next(e for e in text.elements if e.tag == tag)


def test_edits_apply_as_from_the_end_backwards_and_never_overlap():
    data = b"0123456789"
    assert apply(data, [Edit(8, 9, b"X"), Edit(0, 1), Edit(4, 4, b"--")]) == b"123--4567X9"
    with pytest.raises(OverlapError):
        apply(data, [Edit(2, 5, b"a"), Edit(4, 6, b"b")])
    with pytest.raises(OverlapError):
        apply(data, [Edit(3, 3, b"a"), Edit(3, 3, b"b")])  # two insertions at one place: their order is a guess
    assert apply(data, []) == data


def test_an_element_alone_on_its_line_goes_with_its_line_else_alone():
    text = scan(DOC)
    road_link = _first(text, "link")
    assert apply(DOC, [remove_element(text, road_link)]) == DOC.replace(b"        <link/>\n", b"")
    lane_link = [e for e in text.elements if e.tag == "link"][1]
    assert apply(DOC, [remove_element(text, lane_link)]) == DOC.replace(b'<lane id="-1"><link/>', b'<lane id="-1">')


def test_attributes_are_replaced_in_place_or_added_quoted_as_the_others():
    text = scan(DOC)
    road = _first(text, "road")
    assert apply(DOC, [set_attribute(text, road, "name", 'a"b')]) == DOC.replace(b"name='one'", b"name='a\"b'")
    assert apply(DOC, [set_attribute(text, road, "length", "5")]) == DOC.replace(
        b"name='one'>", b"name='one' length='5'>"
    )
    link = _first(text, "link")
    assert apply(DOC, [set_attribute(text, link, "x", "1")]) == DOC.replace(b"<link/>", b'<link x="1"/>', 1)
    assert apply(DOC, [remove_attribute(text, road, "name")]) == DOC.replace(b" name='one'", b"")
    assert remove_attribute(text, road, "absent") is None


def test_children_are_inserted_indented_as_their_siblings():
    text = scan(DOC)
    road = _first(text, "road")
    first = apply(DOC, [insert_child(text, road, b"<type/>", first=True)])
    assert first == DOC.replace(b"        <link/>\n", b"        <type/>\n        <link/>\n")
    last = apply(DOC, [insert_child(text, road, b"<objects/>")])
    assert last == DOC.replace(b"</lanes>\n", b"</lanes>\n        <objects/>\n")
    link = _first(text, "link")  # self-closing: opened and closed, its child indented one step further
    opened = apply(DOC, [insert_child(text, link, b'<successor id="2"/>')])
    assert opened == DOC.replace(b"<link/>\n", b'<link>\n            <successor id="2"/>\n        </link>\n', 1)
    lane_link = [e for e in text.elements if e.tag == "link"][1]  # not laid out in lines: kept on its line
    inline = apply(DOC, [insert_child(text, lane_link, b'<successor id="2"/>')])
    assert b'<lane id="-1"><link><successor id="2"/></link><width' in inline


def test_lines_of_the_edited_file_map_back_to_the_old_ones():
    text = scan(DOC)
    removed = remove_element(text, _first(text, "link"))  # line 3 goes
    lines = LineMap(text, [removed])
    assert [lines.old_line(n) for n in (1, 2, 3, 4, 5)] == [1, 2, 4, 5, 6]
    inserted = insert_child(text, _first(text, "road"), b"<type/>", first=True)  # a new line 3
    lines = LineMap(text, [inserted])
    assert [lines.old_line(n) for n in (2, 3, 4, 5)] == [2, 3, 3, 4]
    assert lines.old_line(None) is None
