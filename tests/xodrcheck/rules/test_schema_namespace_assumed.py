"""Rule schema-namespace-assumed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "schema-namespace-assumed"


def test_11_file_in_no_namespace():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.INFO
    assert f.line == line_of(path, "<OpenDRIVE>")
    assert f.message == (
        "the OpenDRIVE 1.1 schema's elements are in namespace 'www.vires.com'; this file's are in no namespace: "
        "validated as if they were in namespace 'www.vires.com'"
    )


def test_17_file_in_a_namespace_the_schema_does_not_declare():
    (f,) = findings(fixture(RULE, "fail_17_namespaced.xodr"), RULE)
    assert "in namespace 'http://www.opendrive.org': validated as if they were in no namespace" in f.message
    assert findings(fixture(RULE, "fail_17_namespaced.xodr"), "schema-invalid") == []
