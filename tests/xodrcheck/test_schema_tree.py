"""The schema rules validate the file's XML tree and run first; the tree is then dropped before the geometry rules (a
51 MB map's tree is ~750 MB, and it would lie under every geometry cache). Every other rule reads the document only."""

from __future__ import annotations

import gc
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from tests.conftest import corpus_root
from xodrcheck.check import Selection, run_rules
from xodrcheck.findings import Category
from xodrcheck.reader import read
from xodrcheck.rules import load_rules
from xodrcheck.rules.shared.context import Context

FIXTURES = Path(__file__).parent / "rules" / "fixtures"
#: A small corpus map with junctions, signals, controllers and objects.
MAP = "esmini/resources/xodr/fabriksgatan_traffic_lights.xodr"


def _context(path: Path) -> Context:
    data = path.read_bytes()
    document = read(data).document
    assert document is not None
    return Context(document, path=str(path), data=data)


def _opendrive_elements() -> int:
    """Live lxml elements of an OpenDRIVE document (the tree or any view holding its elements)."""
    gc.collect()
    return sum(
        1
        for o in gc.get_objects()
        if isinstance(o, etree._Element) and str(o.getroottree().getroot().tag).endswith("OpenDRIVE")
    )


def test_the_tree_is_gone_after_the_schema_rules_and_the_findings_are_unchanged():
    path = corpus_root() / MAP
    ctx = _context(path)
    assert ctx.tree is not None and _opendrive_elements() > 0
    with np.errstate(all="ignore"):
        findings, ran = run_rules(ctx, Selection())
    assert _opendrive_elements() == 0  # nothing holds the tree or an element of it
    assert ctx.tree is None and ctx.data is None
    assert not [f for f in findings if f.code.startswith("X9")], findings  # no rule crashed
    # the same rules, each alone in registry order on a context that keeps its tree: the same findings
    rules = load_rules()
    assert ran == [code for code in rules if code in set(ran)]
    kept = _context(path)
    with np.errstate(all="ignore"):
        alone = [f for code in ran for f in rules[code].check(kept)]
    assert sorted(map(repr, findings)) == sorted(map(repr, alone))
    assert {"S001", "R020", "J012"} <= set(ran)


class _TreeRead(Exception):
    """A rule other than a schema rule read the XML tree."""


@pytest.mark.parametrize("path", sorted(FIXTURES.rglob("*.xodr")), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_only_the_schema_rules_read_the_tree(path: Path, monkeypatch: pytest.MonkeyPatch):
    """Every other rule runs on a context whose tree cannot be read: none reads it."""
    data = path.read_bytes()
    document = read(data).document
    if document is None:
        return  # an unreadable fixture: the reader's findings only, no rule runs
    ctx = Context(document, path=str(path), data=data)

    def tree(self):
        raise _TreeRead

    monkeypatch.setattr(Context, "tree", property(tree))
    with np.errstate(all="ignore"):
        for rule in load_rules().values():
            if rule.check is not None and rule.category is not Category.SCHEMA and rule.runs_on(ctx.version):
                try:
                    list(rule.check(ctx))
                except _TreeRead:  # pragma: no cover - the failure this test looks for
                    pytest.fail(f"rule {rule.code} reads the XML tree; only the schema rules may")
                except Exception:
                    pass  # a crash of its own is another test's business (the runner reports it as X900)


def _findings(report) -> list[str]:
    return [repr(f) for f in report.findings]


def test_check_parses_a_well_formed_file_once(monkeypatch):
    """The reader's tree is schema validation's: the context never parses again, and the findings are those of a
    check whose context parses the file itself."""
    import importlib

    from xodrcheck.check import check

    reader = importlib.import_module("xodrcheck.reader")

    path = corpus_root() / MAP
    parses: list[int] = []
    own_parse = reader.parse_tree
    monkeypatch.setattr(reader, "parse_tree", lambda data: parses.append(1) or own_parse(data))
    with np.errstate(all="ignore"):
        once = check(path)
    assert parses == [] and once.complete
    own_read = reader.read_keeping_tree
    monkeypatch.setattr(reader, "read_keeping_tree", lambda *a, **k: (own_read(*a, **k)[0], None))
    with np.errstate(all="ignore"):
        twice = check(path)
    assert parses == [1] and _findings(once) == _findings(twice)


def test_a_namespaced_or_broken_file_gets_a_tree_of_its_own():
    """The reader strips a default namespace and recovers what it can from bad XML; schema validation's tree is
    neither."""
    from xodrcheck.reader import read_keeping_tree

    data = (FIXTURES / "link-not-reciprocal" / "pass_junction.xodr").read_bytes()
    result, tree = read_keeping_tree(data)
    assert result.document is not None and tree is not None and tree.getroot().tag == "OpenDRIVE"
    spaced = data.replace(b"<OpenDRIVE", b'<OpenDRIVE xmlns="http://www.opendrive.org"', 1)
    result, tree = read_keeping_tree(spaced)
    assert result.document is not None and tree is None
    result, tree = read_keeping_tree(data[: len(data) // 2])
    assert result.document is not None and tree is None
