"""Run ASAM's ``asam-qc-opendrive`` (in its own virtual environment) and map its issues to xodrcheck's codes.

Used by ``bench_asam.py`` and by ``tests/xodrcheck/test_asam_superset.py``.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

#: ASAM rule name (the part of the UID after the version) -> the xodrcheck codes that report the same defect.
COVERED_BY: dict[str, frozenset[str]] = {
    "xml.valid_xml_document": frozenset({"X101"}),
    "xml.root_tag_is_opendrive": frozenset({"X201"}),
    "xml.fileheader_is_present": frozenset({"X203"}),
    "xml.version_is_defined": frozenset({"X202", "X205", "X206"}),
    "xml.valid_schema": frozenset({"S001"}),
    "road.lane.level_true_one_side": frozenset({"L014"}),
    "road.lane.access.no_mix_of_deny_or_allow": frozenset({"L016"}),
    "road.lane.link.lanes_across_lane_sections": frozenset({"L010", "L011", "R015"}),
    "road.linkage.is_junction_needed": frozenset({"K003"}),
    "road.lane.link.zero_width_at_start": frozenset({"L013"}),
    "road.lane.link.zero_width_at_end": frozenset({"L013"}),
    "road.lane.link.new_lane_appear": frozenset({"L013", "L010", "L101"}),
    "junctions.connection.connect_road_no_incoming_road": frozenset({"J008"}),
    "junctions.connection.one_connection_element": frozenset({"J007"}),
    "junctions.connection.one_link_to_incoming": frozenset({"J007", "J004"}),
    "junctions.connection.start_along_linkage": frozenset({"J002"}),
    "junctions.connection.end_opposite_linkage": frozenset({"J002"}),
    "road.geometry.parampoly3.length_match": frozenset({"G005"}),
    "road.geometry.parampoly3.arclength_range": frozenset({"G005"}),
    "road.geometry.parampoly3.normalized_range": frozenset({"G005"}),
    "road.lane.border.overlap_with_inner_lanes": frozenset({"G010", "G011"}),
    "performance.avoid_redundant_info": frozenset({"G901"}),
    # L013: a lane that closes to zero width yet names a successor (its borders jump to the successor's);
    # L101 leaves that case to L013 (esmini soderleden road 0 lane -3).
    "lane_smoothness.contact_point_no_horizontal_gaps": frozenset({"K101", "K103", "L101", "G001", "L013"}),
}

_CONFIG = """<?xml version="1.0" encoding="UTF-8"?>
<Config>
  <Param name="InputFile" value="{input}"/>
  <CheckerBundle application="xodrBundle">
    <Param name="resultFile" value="{result}"/>
  </CheckerBundle>
</Config>
"""


@dataclass(frozen=True)
class AsamIssue:
    rule: str  # e.g. "road.geometry.parampoly3.length_match"
    level: int  # 1 error, 2 warning, 3 information
    roads: frozenset[str]  # roads the issue's XML locations lie in (junction connections: their roads)
    description: str

    @property
    def is_error(self) -> bool:
        return self.level == 1


def ensure_venv(venv: Path) -> Path:
    """The ``qc_opendrive`` command of ``venv``, creating the environment (python -m venv + pip) when missing."""
    command = venv / "bin" / "qc_opendrive"
    if not command.exists():
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
        subprocess.run([str(venv / "bin" / "pip"), "install", "-q", "asam-qc-opendrive"], check=True)
    return command


def _roads_at(tree: etree._ElementTree, xpath: str) -> set[str]:
    try:
        hits = tree.xpath(xpath)
    except etree.XPathError:
        return set()
    out: set[str] = set()
    for node in hits if isinstance(hits, list) else []:
        if not isinstance(node, etree._Element):
            continue
        for element in (node, *node.iterancestors()):
            if element.tag == "road" and element.get("id") is not None:
                out.add(element.get("id"))
                break
            if element.tag == "connection":
                out.update(v for k in ("incomingRoad", "connectingRoad", "linkedRoad") if (v := element.get(k)))
                break
    return out


def run_asam(command: Path, path: Path) -> list[AsamIssue]:
    """ASAM's issues on one file (its checker always exits 0; the result file says what it found)."""
    with tempfile.TemporaryDirectory() as tmp:
        result = Path(tmp) / "result.xqar"
        config = Path(tmp) / "config.xml"
        config.write_text(config_text(path, result), encoding="utf-8")
        subprocess.run(
            [str(Path(command).absolute()), "-c", str(config)], cwd=tmp, capture_output=True, check=False, timeout=600
        )
        if not result.exists():
            raise RuntimeError(f"asam-qc-opendrive wrote no result for {path}")
        return read_result(result, path)


def config_text(input_file: Path, result_file: Path) -> str:
    """The configuration ``qc_opendrive -c`` reads: check ``input_file``, write the result to ``result_file``."""
    return _CONFIG.format(input=Path(input_file).resolve(), result=Path(result_file).resolve())


def checker_statuses(result: Path) -> dict[str, str]:
    """Each checker's id -> its status in a ``result.xqar`` ("completed", "skipped" or "error")."""
    results = etree.parse(str(result), etree.XMLParser(resolve_entities=False, no_network=True))
    return {c.get("checkerId", ""): c.get("status", "") for c in results.iter("Checker")}


def read_result(result: Path, path: Path) -> list[AsamIssue]:
    """The issues of a ``result.xqar`` written for the file ``path`` (whose roads the issues' locations name)."""
    results = etree.parse(str(result), etree.XMLParser(resolve_entities=False, no_network=True))
    source = etree.parse(str(path), etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True))
    issues = []
    for issue in results.iter("Issue"):
        uid = issue.get("ruleUID") or ""
        roads: set[str] = set()
        for location in issue.iter("XMLLocation"):
            roads |= _roads_at(source, location.get("xpath") or "")
        issues.append(
            AsamIssue(uid.split(":")[-1], int(issue.get("level", "0")), frozenset(roads), issue.get("description", ""))
        )
    return issues


def covered(issue: AsamIssue, findings) -> bool:
    """Whether an xodrcheck finding reports the same defect: a mapped code, on one of the issue's roads (or anywhere
    when the issue names no road)."""
    codes = COVERED_BY.get(issue.rule, frozenset())
    return any(f.code in codes and (not issue.roads or f.road in issue.roads) for f in findings)
