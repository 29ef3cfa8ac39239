"""``--format xqar``: ASAM's own result library loads what xodrcheck writes, with the same issues per rule UID.

ASAM's ``qc_baselib`` runs in its own environment (``$ASAM_VENV``, default ``<repo>/.venv-asam``; it pins lxml < 6),
in a subprocess that prints the issue count per rule UID of each checker bundle.
"""

from __future__ import annotations

import json
import re
import subprocess
from collections import Counter
from pathlib import Path

import pytest
from lxml import etree

from tests.interop.asam_harness import AsamUnavailable, asam_python
from xodrcheck.check import check
from xodrcheck.cli import main
from xodrcheck.report import render
from xodrcheck.report.xqar import conform_uid, issue_uid, own_uid
from xodrcheck.rules import load_rules

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

MAPS = [
    "esmini/resources/xodr/e6mini.xodr",
    "ika-roadgeneration/test/gt/junction_m2a.xodr",
    "carla-towns/OpenDrive/Town01.xodr",
]

_LOAD = """
import json, sys
from collections import Counter
from qc_baselib import Result
result = Result()
result.load_from_file(sys.argv[1])
out = {}
for bundle in result.get_checker_bundle_results():
    counts = Counter()
    for checker in bundle.checkers:
        for issue in checker.issues:
            counts[issue.rule_uid] += 1
    out[bundle.name] = dict(counts)
print(json.dumps(out))
"""


@pytest.fixture(scope="module", name="asam_python")
def asam_python_fixture() -> Path:
    try:
        return asam_python()
    except AsamUnavailable as error:
        pytest.fail(str(error))


def _load_with_baselib(python: Path, path: Path) -> dict[str, dict[str, int]]:
    done = subprocess.run([str(python), "-c", _LOAD, str(path)], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout)


@pytest.mark.parametrize("name", MAPS)
def test_baselib_loads_it_with_our_counts_per_uid(name, corpus_dir, asam_python, tmp_path):
    path = corpus_dir / name
    out = tmp_path / "result.xqar"
    assert main(["check", str(path), "--format", "xqar", "-o", str(out)]) in (0, 1)
    loaded = _load_with_baselib(asam_python, out)
    report = check(path)
    assert report.findings, "the maps are chosen to have findings"
    assert loaded == {"xodrcheck": dict(Counter(issue_uid(f) for f in report.findings))}


def test_several_files_give_one_bundle_each(corpus_dir, asam_python, tmp_path):
    paths = [corpus_dir / name for name in MAPS[:2]]
    out = tmp_path / "two.xqar"
    out.write_text(render("xqar", [check(p) for p in paths]), encoding="utf-8")
    loaded = _load_with_baselib(asam_python, out)
    assert set(loaded) == {f"xodrcheck: {p}" for p in paths}


def test_locations_name_row_xpath_and_place(corpus_dir):
    path = corpus_dir / MAPS[1]
    report = check(path)
    root = etree.fromstring(render("xqar", [report]).encode())
    tree = etree.parse(str(path))
    issues = root.findall(".//Issue")
    assert len(issues) == len(report.findings)
    located = [issue for issue in issues if issue.find(".//XMLLocation") is not None]
    assert len(located) == len([f for f in report.findings if f.line])
    for issue in located:
        (element,) = tree.xpath(issue.find(".//XMLLocation").get("xpath"))
        assert element.sourceline == int(issue.find(".//FileLocation").get("row"))
    placed = [f for f in report.findings if f.x is not None]
    assert len(root.findall(".//InertialLocation")) == len(placed)


def test_uids_the_framework_would_reject_are_written_conform():
    assert conform_uid("asam.net:xodr:1.x.0:road.corner_local.no_mixing_road_local") == (
        "asam.net:xodr:1.9.0:road.corner_local.no_mixing_road_local"
    )
    assert conform_uid("asam.net:xodr:1.9.0:road.geometry.s-value_sum").endswith(":road.geometry.s_value_sum")


def test_every_own_rule_uid_matches_the_frameworks_pattern():
    """qc_baselib rejects a result file whose rule UID breaks its pattern (a hyphen in a category or a name)."""
    # the pattern of qc_baselib's rule_uid: entity:standard:version:dotted name of letter-led words
    pattern = re.compile(r"^(\w+(\.\w+)+):([a-z]+):([0-9]+(\.[0-9]+)+):(([^\W\d_][\w]*)\.)*[^\W\d_]\w*$")
    rules = load_rules().values()
    bad = [uid for r in rules if not pattern.match(uid := own_uid(r.name, r.category.value))]
    assert not bad, bad


_BASES = """
import json, sys
from qc_baselib import Result
result = Result()
result.load_from_file(sys.argv[1])
out = []
for bundle in result.get_checker_bundle_results():
    for checker in bundle.checkers:
        meta = {m.key: m.value for m in checker.metadata}
        for issue in checker.issues:
            infos = result.get_domain_specific_info(bundle.name, checker.checker_id, issue.issue_id)
            bases = [e.get("value") for info in infos if info.name == "xodrcheck" for e in info.content]
            out.append([issue.rule_uid, bases, meta.get("basis", "")])
print(json.dumps(out))
"""


def test_baselib_reads_each_issues_basis(corpus_dir, asam_python, tmp_path):
    """Issue 26: the basis (an Annex F UID, or schema, reading, plausibility) reaches ASAM's library intact, in each
    issue's domain-specific info and its checker's metadata."""
    path = corpus_dir / MAPS[1]
    report = check(path)
    out = tmp_path / "basis.xqar"
    out.write_text(render("xqar", [report]), encoding="utf-8")
    done = subprocess.run([str(asam_python), "-c", _BASES, str(out)], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    loaded = json.loads(done.stdout)
    expected = Counter((issue_uid(f), f.basis) for f in report.findings)
    assert Counter((uid, bases[0]) for uid, bases, _ in loaded) == expected
    assert all(len(bases) == 1 and bases[0] in meta.split() for _, bases, meta in loaded)
    kinds = {b.startswith("asam.net:") for _, b in expected}
    assert kinds == {True, False}, "the map is chosen to have findings with and without a UID"
