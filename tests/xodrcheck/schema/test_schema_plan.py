"""The fast verdict's schema plans (xodrcheck.schema.plan): shipped as xmlschema's compiled schemas give them, every
test of OpenDRIVE 1.8 and 1.9 translated, and each translated XPath 1.0 test gives elementpath's result on the same
element (untyped, the element as the root of a fragment), or an error, which the fast verdict reads as "not shown
valid"; a plain check of a valid 1.8 file imports neither xmlschema nor elementpath."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from functools import cache
from pathlib import Path
from typing import Any

import pytest
from elementpath import XPath2Parser, XPathContext
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree

from xodrcheck.schema import fast as schema_fast
from xodrcheck.schema import plan as schema_plan
from xodrcheck.schema import validate as schema

REPO = Path(__file__).resolve().parents[3]
VERSIONS = sorted(schema.XSD11)


@cache
def _plan(version: tuple[int, int]) -> dict[str, Any]:
    return schema_plan.build(schema.compiled(version))


@pytest.mark.parametrize("version", VERSIONS, ids=[f"{v[0]}.{v[1]}" for v in VERSIONS])
def test_shipped_plans_are_what_the_compiled_schemas_give(version):
    folder, _ = schema.SCHEMA_FOLDERS[version]
    shipped = REPO / "schemas" / folder / schema_plan.PLAN_FILE
    assert shipped.read_text(encoding="utf-8") == schema_plan.dumps(_plan(version)), "run scripts/schema_plan.py"


def _tests(version: tuple[int, int]) -> list[dict[str, Any]]:
    plan = _plan(version)
    found = [a for t in plan["types"] for a in t["assertions"]]
    found += [a for d in plan["decls"] for a in d["alternatives"] if a["test"] is not None]
    return found


@pytest.mark.parametrize("version", VERSIONS, ids=[f"{v[0]}.{v[1]}" for v in VERSIONS])
def test_every_test_of_the_opendrive_schemas_is_translated(version):
    tests = _tests(version)
    assert len(tests) >= 25  # 19 (1.8) or 21 (1.9) assertions and the junction alternatives
    assert [t["test"] for t in tests if t["xpath"] is None] == []


def _parsed(test: str) -> Any:
    return XPath2Parser().parse(test)


@pytest.mark.parametrize(
    "test",
    [
        "@a < 'x'",  # strings compared by number in XPath 1.0
        "@a = @b",
        "a = 'x'",  # an element's string value
        "count(@a) gt @b",
        "count(distinct-values(a))",
        "name(.) = 'a'",
        "/a",
        "a/parent::*",
        "@a/b",
        "sum(a)",
        "@a = 1.5",
        "@a = 'it''s \"quoted\"'",
    ],
)
def test_expressions_outside_the_subset_are_not_translated(test):
    assert schema_plan.translate(_parsed(test)) is None


def test_parent_of_the_fragment_root_is_empty():
    assert schema_plan.translate(_parsed("name(parent::*) = 'a'")) == "boolean(('') = 'a')"
    assert schema_plan.translate(_parsed("exists(parent::*/parent::*/b)")) == f"boolean(boolean({schema_plan.EMPTY}))"


def _names(token: Any, elements: set[str], attributes: set[str], strings: set[str]) -> None:
    if token.symbol == "@":
        attributes.update(str(t.value) for t in token if t.symbol == "(name)")
        return
    if token.symbol == "(name)":
        elements.add(str(token.value))
    elif token.symbol == "(string)":
        strings.add(str(token.value))
    for child in token:
        _names(child, elements, attributes, strings)


_NUMBERS = ["0", "1", "2", "0.0", "-0", "0e0", "1e3", "-1", "+0", ".5", "5.", " 1", "1 ", "", "NaN", "INF", "1_0", "x"]
_CASES = [(test["test"], test["xpath"]) for version in VERSIONS for test in _tests(version)]


@st.composite
def _cases(draw: Any) -> tuple[str, str, etree._Element]:
    """A test of the plans and an element built from the names and strings it mentions."""
    test, xpath = draw(st.sampled_from(_CASES))
    elements: set[str] = set()
    attributes: set[str] = set()
    strings: set[str] = set()
    _names(_parsed(test), elements, attributes, strings)
    numbers = st.sampled_from(_NUMBERS)
    values = st.one_of(st.sampled_from(sorted(strings)), numbers) if strings else numbers

    def element(tag: str, depth: int) -> etree._Element:
        elem = etree.Element(tag)
        for name in sorted(attributes):
            if draw(st.booleans()):
                elem.set(name, draw(values))
        if depth < 2 and elements:
            for child in draw(st.lists(st.sampled_from(sorted(elements)), max_size=3)):
                elem.append(element(child, depth + 1))
        return elem

    parent = etree.Element(draw(st.sampled_from(["object", "outline", "road"])))
    parent.append(element("e", 0))
    return test, xpath, parent[0]


def _same_or_error(test: str, xpath: str, elem: etree._Element) -> str:
    """Asserts that the translation gives elementpath's result or raises; says which ("true", "false", "error")."""
    try:
        expected = bool(_parsed(test).evaluate(XPathContext(root=elem, fragment=True)))
    except Exception:
        expected = False  # the fast verdict's reading of an error
    try:
        got = schema_fast.compiled_test(xpath)(elem)
    except Exception:
        return "error"  # "not shown valid", never "valid"
    assert got is expected, (test, etree.tostring(elem))
    return str(got).lower()


@settings(max_examples=1500, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(_cases())
def test_translated_tests_give_elementpaths_result_or_an_error(case):
    _same_or_error(*case)


_COMPARED = re.compile(r"x:compare\(([\w.-]+)/@([\w.-]+)")


def test_translated_numeric_comparisons_give_elementpaths_result_or_an_error():
    # each numeric comparison with every number form, the element's attributes set to each literal of the test (so
    # that the branch holding the comparison is taken)
    outcomes = []
    for test, xpath in _CASES:
        compared = _COMPARED.search(xpath)
        if compared is None:
            continue
        elements: set[str] = set()
        attributes: set[str] = set()
        strings: set[str] = set()
        _names(_parsed(test), elements, attributes, strings)
        for name in sorted(attributes - {compared.group(2)}):
            for literal in sorted(strings):
                for number in _NUMBERS:
                    elem = etree.SubElement(etree.Element("object"), "e", {name: literal})
                    etree.SubElement(elem, compared.group(1), {compared.group(2): number})
                    outcomes.append(_same_or_error(test, xpath, elem))
    assert {"true", "false", "error"} <= set(outcomes)


def test_numbers_the_comparison_accepts_read_as_xpath_2_reads_them():
    accepted = ["0", "12", "-3", "+4", "0.5", ".5", "5.", "1e3", "1E-3", "-2.5e+2"]
    for value in accepted:
        elem = etree.Element("e", a=value)
        assert schema_fast.compare(None, [elem.attrib["a"]], "=", float(value)) is True
        assert _parsed(f"@a = {float(value)!r}e0").evaluate(XPathContext(root=elem, fragment=True)) is True
    for value in ["", " 1", "1 ", "1_0", "NaN", "INF", "0x1", "1e", "e1", "\u0661"]:
        with pytest.raises(ValueError):
            schema_fast.compare(None, [value], "=", 0.0)


def test_distinct_values_are_counted_as_strings():
    assert schema_fast.count_distinct(None, ["1", "01", "1.0", "1", " 1"]) == 4
    with pytest.raises(TypeError):
        schema_fast.count_distinct(None, [etree.Element("a")])


VALID_18 = """<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE><header revMajor="1" revMinor="8"/>
  <road id="1" length="10" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>
  </planView><lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center>
  <right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
  </laneSection></lanes>
  <objects><object id="o1" s="2" t="-5" type="pole" radius="0.2" height="3" zOffset="0"/></objects></road>
</OpenDRIVE>
"""


def test_checking_an_18_file_imports_the_xsd11_validator_only_for_errors_outside_assertions(tmp_path: Path):
    path = tmp_path / "valid18.xodr"
    path.write_text(VALID_18)
    out = tmp_path / "modules.json"
    probe = (
        "import json, sys; from xodrcheck.check import check; r = check(sys.argv[1]); "
        "json.dump([sorted(sys.modules), [f.code for f in r.findings]], open(sys.argv[2], 'w'))"
    )
    subprocess.run([sys.executable, "-c", probe, str(path), str(out)], check=True, timeout=300)
    modules, codes = json.loads(out.read_text())
    assert "S001" not in codes and "xodrcheck.schema.fast" in modules
    assert {m.split(".")[0] for m in modules}.isdisjoint({"xmlschema", "elementpath"})
    path.write_text(VALID_18.replace('type="pole"', 'type="crosswalk"'))
    subprocess.run([sys.executable, "-c", probe, str(path), str(out)], check=True, timeout=300)
    modules, codes = json.loads(out.read_text())
    # only an assertion fails: the fast path gives the full validator's error itself
    assert "S001" in codes and "xmlschema" not in modules
    path.write_text(VALID_18.replace(' type="driving"', ""))
    subprocess.run([sys.executable, "-c", probe, str(path), str(out)], check=True, timeout=300)
    modules, codes = json.loads(out.read_text())
    assert "S001" in codes and "xmlschema" in modules  # a required attribute missing: the full validator reports it
