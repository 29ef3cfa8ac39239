"""Rule junction-priority-with-signals: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import code_of, findings, fixture, line_of
from xodrcheck.check import check
from xodrcheck.config import Config, Tolerances
from xodrcheck.findings import Severity

RULE = "junction-priority-with-signals"


def test_priority_beside_a_stop_sign():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING
    assert f.line == line_of(path, "<priority")
    assert f"signal 7 on its road 17 (line {line_of(path, '<signal s=')})" in f.message


def test_signal_far_up_an_incoming_road_does_not_count():
    """With signal_reach 20 m, a sign 10 m before road 1's end at the junction counts, one 40 m before it does not."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    signal = (
        '    <signals>\n      <signal s="{s}" t="-2" id="8" name="yield" dynamic="no" orientation="+" zOffset="0" '
        'country="DE" type="205" subtype="-1" value="-1" height="1" width="0.6"/>\n    </signals>\n'
    )
    at = text.index("    </lanes>\n", text.index('<road id="1"')) + len("    </lanes>\n")
    config = Config(tolerances=Tolerances(signal_reach=20.0))
    for s, expected in (("40", 1), ("10", 0)):
        data = (text[:at] + signal.format(s=s) + text[at:]).encode()
        found = [f for f in check(data, config, select=(code_of(RULE),)).findings if f.code == code_of(RULE)]
        assert len(found) == expected, s
