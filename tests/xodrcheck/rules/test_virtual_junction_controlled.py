"""Rule virtual-junction-controlled: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "virtual-junction-controlled"


def test_controller_in_a_virtual_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<controller id="1"/>')


def test_traffic_light_on_the_main_road_inside_the_junction():
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    light = (
        '    <signals>\n      <signal s="{s}" t="-6" id="9" name="light" dynamic="yes" orientation="+" zOffset="0" '
        'country="DE" type="1000001" subtype="-1" value="-1" height="1" width="0.3"/>\n    </signals>\n'
    )
    at = text.index("    </lanes>\n", text.index('<road id="1"')) + len("    </lanes>\n")
    for s, expected in (("60", 1), ("20", 0)):  # junction 555 spans s 50..70 of road 1
        variant = fixture(RULE, "pass.xodr").with_name(f"variant_{s}.xodr")
        try:
            variant.write_text(text[:at] + light.format(s=s) + text[at:], encoding="utf-8")
            assert len(findings(variant, RULE)) == expected
        finally:
            variant.unlink()
