"""Rule duplicate-element-id (R020): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "duplicate-element-id"


def test_object_and_signal_ids_repeated_on_another_road():
    path = fixture(RULE, "fail.xodr")
    obj, sig = sorted(findings(path, RULE), key=lambda f: f.line)
    assert obj.road == sig.road == "2"
    assert (
        obj.line == line_of(path, '<object id="7"', 2)
        and f"first at line {line_of(path, '<object id=')}" in obj.message
    )
    assert sig.line == line_of(path, 'id="5"', 2) and sig.message.startswith("signal id '5' is used again")


def test_ids_count_where_the_document_keeps_no_record(tmp_path):
    # a road without id (the reader skips it) and a road's second <objects> (the reader reads the first) still
    # write ids: R020 reads them from the reader's id table, as written
    from tests.xodrcheck.readerdocs import road, xodr

    obj = '<objects><object id="7" s="1" t="0" zOffset="0" orientation="none"/></objects>'
    path = tmp_path / "skipped.xodr"
    path.write_bytes(
        xodr(road(obj), road(obj, attrs='length="10" junction="-1"'), road(obj + obj, attrs='id="3" length="10"'))
    )
    found = sorted(findings(path, RULE), key=lambda f: f.line)
    assert [(f.road, f.line) for f in found] == [(None, 4), ("3", 5), ("3", 5)]
    assert all(f.message.startswith("object id '7' is used again (first at line 3)") for f in found)
