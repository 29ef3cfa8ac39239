"""Numbers in messages: metres without float noise."""

from __future__ import annotations

import pytest

from xodrcheck.support.quantities import metres


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (99.9999999, "100"),
        (0.1 + 0.2, "0.3"),
        (12.5, "12.5"),
        (100.0, "100"),
        (-3.5, "-3.5"),
        (0.0720863, "0.072086"),
        (1.68793e-06, "0.000002"),
        (1.71e-05, "0.000017"),
        (1234567.891, "1234567.891"),
        (0.0, "0"),
        (-0.0, "0"),
        (-1e-9, "-1e-09"),
        (3e-7, "3e-07"),
        (float("inf"), "inf"),
        (None, "?"),
    ],
)
def test_metres_round_to_the_micrometre_without_trailing_zeros(value, text):
    assert metres(value) == text


def test_messages_carry_no_float_noise():
    """A lane section starting at s=0.30000000000000004 (as a tool wrote 0.1 + 0.2) is named s=0.3 in messages."""
    from tests.xodrcheck.readerdocs import CENTER, lanes_of, road, section, xodr
    from xodrcheck.reader import read

    lanes = lanes_of(section(CENTER, '<right><lane id="-1" type="driving" level="maybe"/></right>', attrs='s="0.1"'))
    data = xodr(road(lanes=lanes)).replace(b's="0.1"', b's="0.30000000000000004"')
    (finding,) = read(data).findings
    assert "lane section s=0.3," in finding.message
