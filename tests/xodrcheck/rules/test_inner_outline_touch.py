"""Rule inner-outline-touch: the finding each fail fixture gives."""

from tests.xodrcheck import schemadocs as D
from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "inner-outline-touch"


def test_inner_point_on_the_outer_edge():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<cornerLocal u="0" v="-1"') and "u=0.000, v=-1.000" in f.message
    assert f.rule_uid.endswith("inner_outline_touches_outer")


def _island(outer: str, inner: str) -> bytes:
    def outline(oid: int, flag: str, points: str) -> str:
        corners = "".join(
            f'<cornerLocal u="{u}" v="{v}" z="0" height="0.1" id="{k}"/>'
            for k, (u, v) in enumerate(p.split(",") for p in points.split())
        )
        return f'<outline id="{oid}" outer="{flag}" closed="true">{corners}</outline>'

    return D.doc(
        9,
        road='<objects><object id="i" type="trafficIsland" s="5" t="-10" zOffset="0" orientation="none" length="4" '
        f'width="2" height="0.1" hdg="0"><outlines>{outline(0, "true", outer)}{outline(1, "false", inner)}'
        "</outlines></object></objects>",
    )


def test_outer_corner_on_the_inner_edge():
    """The outer outline has a point at (0, -1) in the middle of its bottom edge; the inner triangle's edge runs along
    that edge from (-1, -1) to (1, -1) without a point at (0, -1) - and its own corners lie on the outer edge too."""
    data = _island("-2,-1 0,-1 2,-1 2,1 -2,1", "-1,-1 1,-1 0,0.5")
    found = [f.message for f in check(data, select=("B019",)).findings if f.code == "B019"]
    assert len(found) == 2
    assert "at its point u=-1.000, v=-1.000" in found[0]
    assert "at the outer outline's point u=0.000, v=-1.000" in found[1] and "the inner outline has no point" in found[1]


def test_outlines_sharing_their_touching_point_pass():
    data = _island("-2,-1 0,-1 2,-1 2,1 -2,1", "0,-1 1,0 -1,0")
    assert [f for f in check(data, select=("B019",)).findings if f.code == "B019"] == []


def test_inner_outline_outside_the_outer_one():
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8").replace('u="-1.5" v="0"', 'u="-1.5" v="3"')
    found = [f for f in check(text.encode(), select=("B019",)).findings if f.code == "B019"]
    assert [f.rule_uid for f in found if "is not inside" in f.message] == [None]
