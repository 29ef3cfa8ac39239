"""``xodrcheck.structures``: every junction of a map is in exactly one structure, of a registered kind, measured from
the file."""

from __future__ import annotations

import math

import pytest

import junctionart
from junctionart.params import Params
from xodrcheck import structures
from xodrcheck.metrics import junction_legs, smallest_leg_angle
from xodrcheck.reader import read


@pytest.fixture(scope="module")
def paper_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("structures") / "m.xodr"
    junctionart.write(junctionart.generate(Params(width=500.0, height=500.0, randomize_lanes=True), 4), path)
    return read(path).document


def test_every_junction_is_in_exactly_one_structure_of_a_known_kind(paper_map):
    found = structures.map_structures(paper_map)
    ids = [j for s in found for j in s.junctions]
    assert sorted(ids) == sorted(j.id for j in paper_map.junctions) and len(ids) == len(set(ids)) > 3
    known = {k.name for k in structures.KINDS}
    assert all(s.kind in known for s in found)
    for s in found:  # each structure carries exactly its kind's measures, in its order
        assert tuple(n for n, _ in s.values) == structures.kind(s.kind).names


def test_a_paper_map_holds_ordinary_junctions_measured_by_their_legs(paper_map):
    found = structures.map_structures(paper_map)
    assert {s.kind for s in found} == {"junction"}
    by_id = paper_map.junction_by_id
    for s in found:
        legs = junction_legs(paper_map, by_id[s.junctions[0]])
        assert s.measures["legs"] == len(legs)
        angle = smallest_leg_angle(legs)
        assert (
            s.measures["min_angle"] == pytest.approx(angle)
            if angle is not None
            else math.isnan(s.measures["min_angle"])
        )


def test_kinds_are_listed_with_unique_measure_names():
    names = structures.measure_names()
    assert len(names) == len(set(names)) and "legs" in names
    assert structures.KINDS[-1].name == "junction"  # what no other recogniser claims
    with pytest.raises(KeyError, match=r"unknown kind 'tunnel'; kinds: .*junction"):
        structures.kind("tunnel")
