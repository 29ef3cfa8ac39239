"""The public strategies of ``fuzz``: arguments are validated when the strategy is built, before anything is drawn,
and what they draw respects their bounds."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.errors import InvalidArgument
from lxml import etree

from junctionart.fuzz import DEFECTS, Mutation
from junctionart.fuzz.documents import KINDS, document_specs, opendrive_documents
from junctionart.fuzz.generator import (
    RELATIONS,
    control_line_groups,
    control_lines,
    generator_params,
)
from junctionart.fuzz.mutations import damaged_documents, defective_documents, document_mutations

BAD = [
    (control_lines, {"min_points": 1}),
    (control_lines, {"max_points": 2.5}),
    (control_lines, {"min_points": 4, "max_points": 3}),
    (control_lines, {"min_length": math.nan}),
    (control_lines, {"min_length": 100.0, "max_length": 50.0}),
    (control_lines, {"max_lanes": 4}),
    (control_line_groups, {"min_lines": 1}),
    (control_line_groups, {"min_lines": 6, "max_lines": 4}),
    (control_line_groups, {"extent": 10.0}),
    (control_line_groups, {"extent": math.inf}),
    (control_line_groups, {"relations": "parallel"}),
    (control_line_groups, {"relations": ("bogus",)}),
    (control_line_groups, {"relations": ()}),
    (generator_params, {"min_size": 10.0}),
    (generator_params, {"max_size": 1e6}),
    (generator_params, {"min_size": 300.0, "max_size": 200.0}),
    (opendrive_documents, {"kinds": ("clothoid",)}),
    (opendrive_documents, {"kinds": "line"}),
    (opendrive_documents, {"min_length": -1.0}),
    (opendrive_documents, {"min_length": 50.0, "max_length": 10.0}),
    (opendrive_documents, {"max_length": 5000.0}),
    (opendrive_documents, {"max_lanes": 0}),
    (opendrive_documents, {"max_roads_per_chain": True}),
    (opendrive_documents, {"versions": ((2, 0),)}),
    (opendrive_documents, {"versions": (1, 8)}),
    (document_specs, {"max_elements": 21}),
    (document_mutations, {"defects": ("no-such-defect",)}),
    (document_mutations, {"defects": (), "damage": ()}),
    (document_mutations, {"damage": "drop"}),
    (damaged_documents, {"min_mutations": -1}),
    (damaged_documents, {"min_mutations": 3, "max_mutations": 1}),
    (damaged_documents, {"max_mutations": 51}),
    (damaged_documents, {"base": b"<OpenDRIVE/>"}),
    (defective_documents, {"defects": ("no-such-defect",)}),
    (defective_documents, {"base": "not a strategy"}),
]


@pytest.mark.parametrize(("strategy", "kwargs"), BAD, ids=[f"{s.__name__}-{sorted(k)}" for s, k in BAD])
def test_bad_arguments_are_refused_when_the_strategy_is_built(strategy, kwargs):
    with pytest.raises(InvalidArgument):
        strategy(**kwargs)  # no draw: the error comes from building the strategy


@settings(max_examples=15, database=None)
@given(control_lines(min_points=3, max_points=5, min_length=40.0, max_length=90.0, max_lanes=2))
def test_control_lines_respect_their_bounds(line):
    assert 3 <= len(line.points) <= 5
    start, end = line.points[0], line.points[-1]
    assert 40.0 - 1e-6 <= math.dist(start, end) <= 90.0 + 1e-6
    assert line.lanes is None or all(0 <= n <= 2 for n in line.lanes)


@settings(max_examples=10, database=None)
@given(control_line_groups(min_lines=4, max_lines=6, relations=("crossing",), max_lanes=1))
def test_control_line_groups_come_in_pairs(lines):
    assert 4 <= len(lines.lines) <= 6 and len(lines.lines) % 2 == 0
    assert all(len(pair) == 2 for pair in lines.pairs)


def test_relations_are_all_known():
    assert set(RELATIONS) >= {"nearly-parallel", "sharp-crossing", "short"}


@settings(max_examples=10, database=None)
@given(opendrive_documents(kinds=("arc",), max_roads_per_chain=1, max_elements=1, versions=((1, 6),)))
def test_documents_use_only_the_kinds_and_versions_asked_for(data):
    root = etree.fromstring(data)
    assert root.find("header").get("revMinor") == "6"
    kinds = {child.tag for g in root.iter("geometry") for child in g}
    # the junction's straight connections are lines whatever the kinds; the chains use arcs (or lines where an arc
    # would leave the heading band)
    assert kinds <= {"arc", "line"} and set(KINDS) >= kinds


@settings(max_examples=20, database=None)
@given(document_mutations(defects=("road-gap",), damage=("drop",)))
def test_mutations_draw_only_the_kinds_asked_for(m):
    assert isinstance(m, Mutation) and m.kind in ("road-gap", "drop")


@settings(max_examples=10, database=None)
@given(defective_documents(defects=("duplicate-road-id",)))
def test_defective_documents_carry_their_defect(case):
    data, kind = case
    ids = [r.get("id") for r in etree.fromstring(data).iter("road")]
    assert kind == "duplicate-road-id" and len(ids) != len(set(ids))


@settings(max_examples=10, database=None)
@given(
    damaged_documents(
        base=st.just(b"<OpenDRIVE><header revMajor='1' revMinor='8'/></OpenDRIVE>"),
        min_mutations=1,
        max_mutations=1,
        damage=("rename",),
        defects=(),
    )
)
def test_damage_applies_to_any_base(data):
    assert isinstance(data, bytes) and data


@pytest.mark.parametrize("kind", sorted(DEFECTS))
def test_every_defect_kind_applies_to_a_document(kind):
    @settings(max_examples=3, database=None)
    @given(defective_documents(defects=(kind,)))
    def prop(case):
        assert case[1] == kind

    prop()
