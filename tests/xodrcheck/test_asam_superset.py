"""On the same files, xodrcheck reports every error ASAM's ``asam-qc-opendrive`` reports (matched by kind and road).

ASAM runs from its own virtual environment at ``$ASAM_VENV`` (default ``<repo>/.venv-asam``); ``.ci/run`` creates it.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import corpus_root
from tests.interop.asam_harness import COVERED_BY, AsamUnavailable, asam_command, covered, run_asam
from xodrcheck.check import check

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

FILES = [
    "esmini/resources/xodr/e6mini.xodr",  # paramPoly3 arcLength whose length is 1.6 mm off
    "esmini/resources/xodr/parking_demo.xodr",  # 1.7: junction connection semantics, zero-width lane links
    "esmini/EnvironmentSimulator/Unittest/xodr/straight_2x100m_opposite.xodr",  # 9 mm gaps at a road link
    "ika-roadgeneration/test/gt/junction_m2a.xodr",  # many gaps, kinks and lane-link problems
    "esmini/resources/xodr/soderleden.xodr",  # a horizontal gap between linked lanes (ASAM error)
]


@pytest.fixture(scope="module")
def qc_opendrive() -> Path:
    try:
        return asam_command()
    except AsamUnavailable as error:
        pytest.fail(str(error))


def test_every_asam_rule_is_mapped():
    assert len(COVERED_BY) == 23


@pytest.mark.parametrize("name", FILES)
def test_asam_errors_are_found_by_xodrcheck(corpus_dir, qc_opendrive, name):
    path = corpus_root() / name
    issues = run_asam(qc_opendrive, path)
    report = check(path)
    unknown = {i.rule for i in issues} - set(COVERED_BY)
    assert not unknown, f"ASAM rules without a mapping: {unknown}"
    missed = [i for i in issues if i.is_error and not covered(i, report.findings)]
    assert missed == [], "\n".join(f"{i.rule} roads={sorted(i.roads)}: {i.description}" for i in missed)
