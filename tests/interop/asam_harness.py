"""ASAM's ``asam-qc-opendrive``: run it, read its ``result.xqar`` files, and map its issues to xodrcheck's codes.

Shared by the interoperability tests, ``tests/xodrcheck/test_asam_superset.py``, ``test_xqar.py`` and
``benchmarks/bench_asam.py``. The checker lives in its own virtual environment, ``$ASAM_VENV`` (default
``<repo>/.venv-asam``; ``scripts/setup`` creates it). The bundle's own command takes one file per call and spends about
2 s starting up, so :func:`run_asam_many` runs the bundle's checks (``qc_opendrive.main.run_checks``, exactly as
``qc_opendrive -c`` runs them) over a batch of files in one worker process (``_asam_worker.py``); :func:`run_asam`
runs the command on one file, as users run it.
"""

from __future__ import annotations

import os
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

REPO = Path(__file__).resolve().parents[2]
WORKER = Path(__file__).with_name("_asam_worker.py")

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


class AsamUnavailable(RuntimeError):
    """There is no ASAM virtual environment where the harness looks for it."""


@dataclass(frozen=True)
class AsamReport:
    """ASAM's verdict on one file: its issues and each checker's status (completed / skipped / error)."""

    path: Path
    issues: tuple[AsamIssue, ...]
    statuses: dict[str, str]

    @property
    def errors(self) -> tuple[AsamIssue, ...]:
        return tuple(i for i in self.issues if i.is_error)

    @property
    def failed_checkers(self) -> tuple[str, ...]:
        return tuple(sorted(c for c, status in self.statuses.items() if status == "error"))


def asam_venv() -> Path:
    """The ASAM virtual environment; raises :class:`AsamUnavailable` naming how to create it."""
    venv = Path(os.environ.get("ASAM_VENV", REPO / ".venv-asam"))
    if not (venv / "bin" / "qc_opendrive").is_file() or not (venv / "bin" / "python").is_file():
        raise AsamUnavailable(
            f"asam-qc-opendrive not found in {venv}: run scripts/setup (it creates .venv-asam with "
            "asam-qc-opendrive==1.0.0), or set ASAM_VENV to an environment that has it"
        )
    return venv


def asam_python() -> Path:
    """The ASAM environment's interpreter (it also has ASAM's ``qc_baselib``)."""
    return asam_venv() / "bin" / "python"


def asam_command() -> Path:
    """The ASAM environment's ``qc_opendrive`` command."""
    return asam_venv() / "bin" / "qc_opendrive"


class AsamRun:
    """ASAM running over a batch of files in ``workers`` background processes; :meth:`reports` waits for them."""

    def __init__(self, paths: list[Path], work: Path, workers: int = 2) -> None:
        python = asam_python()
        work.mkdir(parents=True, exist_ok=True)
        self.paths = list(paths)
        self.results: list[Path] = []
        configs = []
        for n, path in enumerate(self.paths):
            result = work / f"{n}-{path.stem}.xqar"
            config = work / f"{n}-{path.stem}.config.xml"
            config.write_text(config_text(path, result), encoding="utf-8")
            result.unlink(missing_ok=True)
            configs.append(config)
            self.results.append(result)
        # largest files first, dealt round-robin, so the workers finish at about the same time
        order = sorted(range(len(configs)), key=lambda n: -self.paths[n].stat().st_size)
        batches = [[configs[n] for n in order[w::workers]] for w in range(workers)]
        self.procs = [
            subprocess.Popen(
                [str(python), "-I", str(WORKER), *map(str, batch)],
                cwd=work,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE,
                text=True,
            )
            for batch in batches
            if batch
        ]

    def reports(self, timeout: float = 900) -> dict[Path, AsamReport]:
        """ASAM's report on each file (waits for the workers)."""
        errors = []
        for proc in self.procs:
            try:
                _, err = proc.communicate(timeout=timeout)
            except subprocess.TimeoutExpired:
                proc.kill()
                _, err = proc.communicate()
            errors.append("\n".join(err.strip().splitlines()[-5:]))
        out = {}
        for path, result in zip(self.paths, self.results):
            if not result.is_file():
                codes = [p.returncode for p in self.procs]
                raise RuntimeError(f"asam-qc-opendrive wrote no result for {path} (exits {codes}): {errors}")
            out[path] = AsamReport(path, tuple(read_result(result, path)), checker_statuses(result))
        return out


def run_asam_many(paths: list[Path], work: Path, workers: int = 2) -> dict[Path, AsamReport]:
    """ASAM's report on each of ``paths`` (config and result files go to the folder ``work``)."""
    return AsamRun(paths, work, workers).reports()
