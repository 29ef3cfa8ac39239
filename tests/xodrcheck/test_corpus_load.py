"""Acceptance: the reader loads every third-party corpus file and builds what a plain lxml count says is there."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from tests.conftest import CORPUS_SIZE, corpus_files, corpus_root
from xodrcheck.findings import Severity
from xodrcheck.model import Arc, Line, ParamPoly3, Poly3, Spiral
from xodrcheck.reader import read

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

_KIND_TAGS = {Line: "line", Arc: "arc", Spiral: "spiral", Poly3: "poly3", ParamPoly3: "paramPoly3"}


def _plain(path: Path) -> etree._Element:
    """The file as lxml alone sees it (no model), for counting."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=True)
    return etree.parse(str(path), parser).getroot()


def test_corpus_is_complete(corpus_dir: Path):
    assert len(list(corpus_dir.rglob("*.xodr"))) == CORPUS_SIZE, f"expected {CORPUS_SIZE} .xodr files in {corpus_dir}"


@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.relative_to(corpus_root()).as_posix())
def test_loads_with_the_counts_lxml_sees(path: Path, corpus_dir: Path):
    result = read(path)
    document = result.document
    assert document is not None
    assert result.path == str(path)
    errors = [f"{f.code} line {f.line}: {f.message}" for f in result.findings if f.severity >= Severity.ERROR]
    assert errors == []

    root = _plain(path)
    assert len(document.roads) == len(root.findall("road"))
    assert len(document.junctions) == len(root.findall("junction"))
    assert [r.id for r in document.roads] == [r.get("id") for r in root.iterfind("road")]
    assert sum(len(j.connections) for j in document.junctions) == len(root.findall("junction/connection"))
    assert sum(len(r.lane_sections) for r in document.roads) == len(root.findall("road/lanes/laneSection"))
    lanes = sum(len(s.lanes) for r in document.roads for s in r.lane_sections)
    assert lanes == len(root.findall("road/lanes/laneSection/*/lane"))
    for kind, tag in _KIND_TAGS.items():
        built = sum(isinstance(g, kind) for r in document.roads for g in r.plan_view)
        assert built == len(root.findall(f"road/planView/geometry/{tag}")), tag
    assert document.version == (int(root.find("header").get("revMajor")), int(root.find("header").get("revMinor")))


@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.relative_to(corpus_root()).as_posix())
def test_read_without_blank_text_builds_the_same_model(path: Path, corpus_dir: Path):
    """``read()`` parses without the whitespace between elements (only schema validation's tree needs it): the model and
    the findings, lines included, are those of the reader that keeps the checker's tree."""
    from xodrcheck.reader import read_keeping_tree

    kept, _tree = read_keeping_tree(path)
    plain = read(path)
    assert plain.document == kept.document
    assert plain.findings == kept.findings
