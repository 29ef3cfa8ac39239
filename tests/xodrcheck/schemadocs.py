"""Small OpenDRIVE 1.8 / 1.9 documents for the schema tests: one road, plus whatever a test puts into it."""

from __future__ import annotations

from lxml import etree

ROAD_LANES = (
    '<lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center>'
    '<right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>'
    "</laneSection></lanes>"
)


def doc(minor: int, road: str = "", top: str = "", header: str = "", lanes: str = ROAD_LANES) -> bytes:
    """A document declaring OpenDRIVE 1.``minor`` with one 10 m road: ``road`` goes after the road's lanes
    (objects, signals, ...), ``top`` after the road (junctions, vmsGroup, ...), ``header`` into the header."""
    return (
        f'<?xml version="1.0" encoding="UTF-8"?>\n<OpenDRIVE>\n<header revMajor="1" revMinor="{minor}">{header}'
        '</header>\n<road id="1" length="10" junction="-1">\n'
        '<planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView>\n'
        f"{lanes}\n{road}\n</road>\n{top}\n</OpenDRIVE>\n"
    ).encode()


def tree(data: bytes) -> etree._ElementTree:
    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
    return etree.ElementTree(etree.fromstring(data, parser))


#: A multi board (14.7.3): dynamic, one static board and one variable message board.
MULTI_BOARD = (
    '<signals><signal s="4" t="-4" id="534" name="board" dynamic="yes" orientation="+" zOffset="5" '
    'country="OpenDRIVE" type="multiBoard" subtype="-1" hOffset="0" pitch="0" roll="0" height="3" width="7.5">'
    '<staticBoard><sign id="535" country="DE" type="386" subtype="32" countryRevision="2017" v="-7" z="0.2" '
    'width="0.5" height="0.2" dynamic="no" orientation="+"/></staticBoard>'
    '<vmsBoard displayHeight="2.5" displayWidth="7.0" v="0" z="0.5">'
    '<displayArea index="1" v="7" z="3" width="1.4" height="1.4"/></vmsBoard>'
    "</signal></signals>"
)

VMS_GROUP = '<vmsGroup id="27"><vmsBoardReference signalId="534" vmsIndex="1" groupIndex="1"/></vmsGroup>'

DEFAULT_REGULATIONS = (
    '<defaultRegulations><roadRegulations type="town"/><signalRegulations type="274" subtype="50"/>'
    "</defaultRegulations>"
)


def outline(outline_id: int) -> str:
    return (
        f'<outline id="{outline_id}" closed="true">'
        '<cornerLocal u="0" v="0" z="0" height="0.2" id="0"/><cornerLocal u="1" v="0" z="0" height="0.2" id="1"/>'
        '<cornerLocal u="1" v="1" z="0" height="0.2" id="2"/></outline>'
    )


def island(outlines: str, borders: str = "") -> str:
    """A traffic island object with ``outlines`` (inside ``<outlines>``) and ``borders`` (inside ``<borders>``)."""
    border_el = f"<borders>{borders}</borders>" if borders else ""
    return (
        '<objects><object id="o1" s="1" t="-5" zOffset="0" type="trafficIsland" orientation="none" height="0.2">'
        f"<outlines>{outlines}</outlines>{border_el}</object></objects>"
    )
