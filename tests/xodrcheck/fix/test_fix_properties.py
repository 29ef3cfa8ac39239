"""Property: on damaged documents (the fuzz campaign's mutations, over generated documents and over the rules'
failing fixtures, which hold what the fixes repair), ``fix`` never crashes, never leaves more errors than there were,
and a second run changes nothing."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from junctionart.fuzz.documents import opendrive_documents
from junctionart.fuzz.mutations import damaged_documents
from tests.xodrcheck.fix.test_fixes import FIXED_FIXTURES, FIXTURES, T_JUNCTION
from xodrcheck.check import check
from xodrcheck.fix.result import fix

#: Documents with something to fix, before any damage.
FIXABLE = [T_JUNCTION, *((FIXTURES / name).read_bytes() for name, _, _ in FIXED_FIXTURES)]

BASES = st.one_of(st.sampled_from(FIXABLE), opendrive_documents(max_roads_per_chain=2, max_elements=2, max_lanes=2))


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # damaged numbers overflow in numpy: findings, not noise
@settings(max_examples=60, derandomize=True, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(damaged_documents(base=BASES, min_mutations=0, max_mutations=3), st.booleans())
def test_fixing_damaged_documents_never_crashes_nor_adds_errors(data, unsafe):
    before = check(data)
    result = fix(data, unsafe=unsafe)
    assert result.report.errors <= before.errors, result.diff()
    assert result.changed or result.data is data or result.data == data
    event("fixed something" if result.changed else "nothing fixed")
    if result.changed:
        assert result.applied and check(result.data).errors == result.report.errors
    assert fix(result.data, unsafe=unsafe).data == result.data
