"""Rule schema-invalid: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "schema-invalid"


def test_unexpected_element_is_reported_at_its_line():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<bogus/>")
    assert "1.7.0" in f.message and "bogus" in f.message


def test_opendrive_18_assertion_is_checked_with_xsd11():
    path = fixture(RULE, "fail_18.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<object ")
    assert "1.8.1" in f.message and "assertion" in f.message


def test_11_and_12_files_in_no_namespace_are_validated_as_if_in_the_schemas():
    """The 1.1 and 1.2 schemas declare their elements in www.vires.com; files of those versions, as tools write them,
    use no namespace. Validated as written every one failed at its root ("No matching global declaration")."""
    for name in ("pass_11_no_namespace.xodr", "pass_12_no_namespace.xodr"):
        assert findings(fixture(RULE, name), RULE) == []
    path = fixture(RULE, "fail_11_no_namespace.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<header ")
    assert "Element 'header', attribute 'north'" in f.message and "www.vires.com" not in f.message


def test_one_finding_per_cause():
    """xmlschema reports length="abc" three times at one line (the pattern twice, the conversion once)."""
    path = fixture(RULE, "fail_18_one_cause.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<road id="1" length="abc"')
    assert "attribute length='abc': could not convert string to float" in f.message


def test_causes_are_told_apart_by_line_element_and_attribute():
    from xodrcheck.rules.schema import one_per_cause
    from xodrcheck.schema.validate import SchemaError

    errors = [
        SchemaError(5, "Element 'road': attribute length='abc': value doesn't match any pattern of ['x']"),
        SchemaError(5, "Element 'road': attribute length='abc': could not convert string to float: 'abc'"),
        SchemaError(5, "Element 'road': attribute id='': value is empty"),
        SchemaError(9, "Element 'road': attribute length='abc': could not convert string to float: 'abc'"),
        SchemaError(7, "Element 'lane', attribute 'type': [facet 'enumeration'] The value 'x' is not an element"),
        SchemaError(7, "Element 'lane', attribute 'type': 'x' is not a valid value of the atomic type 'e_laneType'."),
        SchemaError(7, "Element 'lane': The attribute 'level' is not allowed."),
        SchemaError(8, "Element 'lane': Missing child element(s)."),
        SchemaError(8, "Element 'lane': This element is not expected."),
    ]
    kept = [(e.line, e.message[:40]) for e in one_per_cause(errors)]
    assert kept == [
        (5, "Element 'road': attribute length='abc': "),
        (5, "Element 'road': attribute id='': value i"),
        (9, "Element 'road': attribute length='abc': "),
        (7, "Element 'lane', attribute 'type': [facet"),
        (7, "Element 'lane': The attribute 'level' is"),
        (8, "Element 'lane': Missing child element(s)"),
        (8, "Element 'lane': This element is not expe"),
    ]
    assert "could not convert" in next(one_per_cause(errors)).message
