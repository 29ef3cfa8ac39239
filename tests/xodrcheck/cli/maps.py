"""Small OpenDRIVE maps written inline for the CLI tests, with numbers that can be worked out by hand."""

from __future__ import annotations

HEADER = '<?xml version="1.0" encoding="UTF-8"?>\n<OpenDRIVE>\n  <header revMajor="1" revMinor="{minor}" name="t"/>\n'


def lane(lane_id: int, width: float = 3.5, lane_type: str = "driving") -> str:
    if lane_id == 0:
        return '<lane id="0" type="none"/>'
    return f'<lane id="{lane_id}" type="{lane_type}"><width sOffset="0" a="{width}" b="0" c="0" d="0"/></lane>'


def section(s: float, left=(), right=()) -> str:
    """A lane section; ``left``/``right`` are sequences of ``(id, width, type)``."""
    parts = [f'<laneSection s="{s}">']
    if left:
        parts.append("<left>" + "".join(lane(*spec) for spec in left) + "</left>")
    parts.append("<center>" + lane(0) + "</center>")
    if right:
        parts.append("<right>" + "".join(lane(*spec) for spec in right) + "</right>")
    parts.append("</laneSection>")
    return "".join(parts)


def road(
    road_id: str,
    length: float,
    geometry: str,
    sections: str,
    junction: str = "-1",
    elevation: str = "",
    link: str = "",
) -> str:
    return (
        f'  <road id="{road_id}" length="{length}" junction="{junction}">\n'
        f"    <link>{link}</link>\n"
        f"    <planView>{geometry}</planView>\n"
        f"    <elevationProfile>{elevation}</elevationProfile>\n"
        f"    <lanes>{sections}</lanes>\n"
        "  </road>\n"
    )


def line(x: float, y: float, hdg: float, length: float, s: float = 0.0) -> str:
    return f'<geometry s="{s}" x="{x}" y="{y}" hdg="{hdg}" length="{length}"><line/></geometry>'


def arc(x: float, y: float, hdg: float, length: float, curvature: float, s: float = 0.0) -> str:
    return f'<geometry s="{s}" x="{x}" y="{y}" hdg="{hdg}" length="{length}"><arc curvature="{curvature}"/></geometry>'


def document(*roads: str, junctions: str = "", minor: int = 8) -> str:
    return HEADER.format(minor=minor) + "".join(roads) + junctions + "</OpenDRIVE>\n"


TWO_LANES = section(0, left=[(1, 3.5, "driving")], right=[(-1, 3.5, "driving")])

#: A 100 m straight road along x with one 3.5 m driving lane each side.
STRAIGHT = document(road("1", 100, line(0, 0, 0, 100), TWO_LANES))

#: The same road rising 1 m + 2 % (z = 1 + 0.02 s).
STRAIGHT_RISING = document(
    road("1", 100, line(0, 0, 0, 100), TWO_LANES, elevation='<elevation s="0" a="1" b="0.02" c="0" d="0"/>')
)

#: A left arc of radius 100 m (curvature 0.01) from the origin heading along x, a quarter circle long.
ARC_RADIUS = 100.0
ARC_LENGTH = 157.07963267948966
ARC = document(road("1", ARC_LENGTH, arc(0, 0, 0, ARC_LENGTH, 1 / ARC_RADIUS), TWO_LANES))

#: Two lane sections: [0, 40) has a driving lane and a 2 m sidewalk on the right, [40, 100] the driving lane only.
TWO_SECTIONS = document(
    road(
        "7",
        100,
        line(0, 0, 0, 100),
        section(0, right=[(-1, 3.5, "driving"), (-2, 2.0, "sidewalk")]) + section(40, right=[(-1, 3.0, "driving")]),
    )
)


def _links(pred: str, succ: str) -> str:
    return (
        f'<predecessor elementType="road" elementId="{pred}" contactPoint="end"/>'
        f'<successor elementType="road" elementId="{succ}" contactPoint="start"/>'
    )


def _connection(cid: int, incoming: str, connecting: str) -> str:
    return (
        f'    <connection id="{cid}" incomingRoad="{incoming}" connectingRoad="{connecting}" contactPoint="start">'
        '<laneLink from="-1" to="-1"/></connection>\n'
    )


#: A direct junction joining road 1 to roads 2 and 3 (three legs), and a default junction 20 with incoming roads 4 and
#: 5 whose connecting roads lead 4 -> 5, 4 -> 9 and 5 -> 10: four legs, although only two roads are "incoming".
JUNCTIONS = document(
    road("1", 10, line(0, 0, 0, 10), TWO_LANES),
    road("2", 10, line(10, 0, 0, 10), TWO_LANES),
    road("3", 10, line(10, 0, 0.1, 10), TWO_LANES),
    road("4", 10, line(30, 0, 0, 10), TWO_LANES),
    road("5", 10, line(50, 0, 0, 10), TWO_LANES),
    road("9", 10, line(50, 10, 0, 10), TWO_LANES),
    road("10", 10, line(50, 20, 0, 10), TWO_LANES),
    road("6", 10, line(40, 0, 0, 10), TWO_LANES, junction="20", link=_links("4", "5")),
    road("8", 10, line(40, 0, 0.5, 10), TWO_LANES, junction="20", link=_links("4", "9")),
    road("11", 10, line(40, 0, 1.0, 10), TWO_LANES, junction="20", link=_links("5", "10")),
    junctions=(
        '  <junction id="10" type="direct">\n'
        '    <connection id="0" incomingRoad="1" linkedRoad="2" contactPoint="start"><laneLink from="-1" to="-1"/>'
        "</connection>\n"
        '    <connection id="1" incomingRoad="1" linkedRoad="3" contactPoint="start"><laneLink from="-1" to="-1"/>'
        "</connection>\n"
        "  </junction>\n"
        '  <junction id="20" type="default">\n'
        + _connection(0, "4", "6")
        + _connection(1, "4", "8")
        + _connection(2, "5", "11")
        + "  </junction>\n"
    ),
)

#: The same circle continued to a half circle: its rightmost point is inside the road, not at an end.
HALF_CIRCLE_LENGTH = 314.1592653589793
HALF_CIRCLE = document(road("1", HALF_CIRCLE_LENGTH, arc(0, 0, 0, HALF_CIRCLE_LENGTH, 1 / ARC_RADIUS), TWO_LANES))
