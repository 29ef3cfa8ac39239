"""Junction control (issue 16): traffic lights in signal groups that never let crossing connection lanes go green
together (proved from the written file alone, with xodrcheck's geometry), stop lines, signs, validity."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest
import shapely
from lxml import etree

import junctionart as ja
from junctionart.params import Params
from junctionart.writer import write
from xodrcheck.analysis.sample import sample_lanes
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.reader import read

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")

#: the generator's clearance between connection lanes of one signal group is 2 m; read back, allow 5 cm of sampling
MIN_GAP = 1.95
CASES = [(0, "RHT"), (1, "LHT"), (2, "RHT"), (3, "RHT"), (4, "LHT"), (5, "RHT")]


@pytest.fixture(scope="module")
def lit(tmp_path_factory) -> list[Path]:
    """Every junction signalised: random lanes, curved roads, turn lanes, both traffic rules."""
    out = []
    folder = tmp_path_factory.mktemp("lit")
    for seed, rule in CASES:
        p = Params.create(
            "scenario", junction_control="traffic-lights", randomize_lanes=True, curved_roads=True, traffic_rule=rule
        )
        out.append(write(ja.generate(p, seed), folder / f"{seed}.xodr"))
    return out


def _centres(path: Path) -> dict[str, shapely.LineString]:
    """Connecting road id -> centre line of its driving lane, sampled by xodrcheck from the file."""
    doc = read(path).document
    junction_roads = {r.id for r in doc.roads if r.junction not in (None, "-1")}
    return {
        line.road: shapely.LineString(list(zip(line.x, line.y)))
        for line in sample_lanes(doc, 0.25)
        if line.road in junction_roads and line.lane_type == "driving"
    }


def _groups(path: Path):
    """Per junction: [(controller id, sequence, {signal id: set of connecting road ids it lets go})], read from XML."""
    root = etree.parse(str(path)).getroot()
    signals = {}
    for road in root.iter("road"):
        for sig in road.iterfind("signals/signal"):
            (v,) = sig.findall("validity")
            lanes = range(int(v.get("fromLane")), int(v.get("toLane")) + 1)
            signals[sig.get("id")] = (road.get("id"), set(lanes), sig)
    controllers = {c.get("id"): [x.get("signalId") for x in c.iter("control")] for c in root.iterfind("controller")}
    out = {}
    for j in root.iter("junction"):
        moves: dict[tuple[str, int], set[str]] = {}
        for c in j.iterfind("connection"):
            for ll in c.iterfind("laneLink"):
                moves.setdefault((c.get("incomingRoad"), int(ll.get("from"))), set()).add(c.get("connectingRoad"))
        groups = []
        for ref in j.iterfind("controller"):
            lets = {}
            for sid in controllers[ref.get("id")]:
                road, lanes, _ = signals[sid]
                lets[sid] = set().union(*(moves.get((road, lane), set()) for lane in lanes))
            groups.append((ref.get("id"), int(ref.get("sequence")), lets))
        out[j.get("id")] = (groups, moves)
    return out, signals


def test_no_two_conflicting_connection_lanes_are_green_together(lit):
    """From the file alone: within each signal group (controller), connection lanes let go by different signals keep
    their centre lines at least 1.95 m apart; groups of one junction have distinct sequence numbers (they take turns)
    and together let every driving connection lane go, each signal in exactly one group."""
    pairs = groups_seen = 0
    for path in lit:
        centres = _centres(path)
        junctions, signals = _groups(path)
        controlled = Counter()
        for groups, moves in junctions.values():
            if not groups:
                continue
            assert len({seq for _, seq, _ in groups}) == len(groups)
            let_go = set()
            for _, _, lets in groups:
                groups_seen += 1
                controlled.update(list(lets))
                items = sorted(lets.items())
                for i, (_, roads_a) in enumerate(items):
                    let_go |= roads_a
                    for _, roads_b in items[i + 1 :]:
                        for a in roads_a:
                            for b in roads_b:
                                assert shapely.distance(centres[a], centres[b]) >= MIN_GAP, (path.name, a, b)
                                pairs += 1
            driving = {r for rs in moves.values() for r in rs if r in centres}
            assert driving and driving <= let_go
        lights = {sid for sid, (_, _, el) in signals.items() if el.get("type") == "1000001"}
        assert set(controlled) == lights and set(controlled.values()) == {1}
    assert groups_seen > 20 and pairs > 50


def test_conflicting_movements_exist_so_the_proof_is_not_vacuous(lit):
    """Some junction has connection lanes that cross (closer than 1.95 m) and are let go by different groups."""
    crossing = 0
    for path in lit[:2]:
        centres = _centres(path)
        junctions, _ = _groups(path)
        for groups, _ in junctions.values():
            per_group = [set().union(*lets.values()) for _, _, lets in groups]
            for i, a in enumerate(per_group):
                for b in per_group[i + 1 :]:
                    crossing += any(shapely.distance(centres[x], centres[y]) < MIN_GAP for x in a for y in b)
    assert crossing > 5


def test_lights_stop_lines_and_validity(lit):
    """Each light hangs over the one lane it is valid for, faces traffic entering the junction, refers to a stop line
    of its road whose validity covers its lane; all within the road."""
    lights = 0
    for path in lit[:3]:
        doc = read(path).document
        roads = {r.id: r for r in doc.roads}
        _, signals = _groups(path)
        for road_id, lanes, el in signals.values():
            road = roads[road_id]
            s = float(el.get("s"))
            assert 0.0 <= s <= road.length
            if el.get("type") != "1000001":
                continue
            lights += 1
            (lane,) = lanes
            along_s = (lane < 0) == (road.rule.value == "RHT")  # traffic on this lane drives along s
            assert el.get("orientation") == ("+" if along_s else "-")
            assert el.get("dynamic") == "yes" and el.get("country") == "OpenDRIVE" and float(el.get("zOffset")) >= 4.5
            (ref,) = el.findall("reference")
            line_road, line_lanes, line = signals[ref.get("elementId")]
            assert line.get("type") == "294" and line_road == road_id and lane in line_lanes
            assert line.get("s") == el.get("s")
            # over its lane: t between the lane's borders, its sign that of the lane id
            assert (float(el.get("t")) > 0) == (lane > 0)
    assert lights > 50


def test_auto_control_mixes_types_and_signs_sit_on_the_minor_legs(tmp_path):
    """The scenario profile draws lights, stop and yield junctions; stop and yield signs are never on both legs of
    the priority road (two approaches of each such junction carry the priority sign 306)."""
    kinds: Counter[str] = Counter()
    for seed in range(4):
        path = write(ja.generate(Params.create("scenario", randomize_lanes=True), seed), tmp_path / f"{seed}.xodr")
        _, signals = _groups(path)
        kinds.update(el.get("type") for _, _, el in signals.values())
        report = check(path, GENERATOR)
        assert [f.code for f in report.findings if f.severity.name in ("ERROR", "WARNING")] == []
    assert kinds["1000001"] > 10 and kinds["294"] > 5 and kinds["306"] >= 2
    assert kinds["206"] + kinds["205"] >= 2


def test_signalised_maps_are_valid_against_every_schema_and_clean(lit, schema18, schema19, schema17, tmp_path):
    for k, path in enumerate(lit):
        assert list(schema18.iter_errors(str(path))) == []
        report = check(path, GENERATOR)
        assert [f.code for f in report.findings if f.severity.name in ("ERROR", "WARNING")] == []
        if k < 2:
            doc = ja.generate(
                Params.create("scenario", junction_control="traffic-lights", randomize_lanes=True, curved_roads=True),
                CASES[k][0],
            )
            assert list(schema19.iter_errors(str(write(doc, tmp_path / "a.xodr", "1.9")))) == []
            tree = etree.parse(str(write(doc, tmp_path / "b.xodr", "1.7")))
            assert schema17.validate(tree), schema17.error_log


def test_signals_leave_the_roads_as_they_were():
    """Junction control adds signals, crosswalk objects, controllers and junction controller references only: with it
    off, the same roads."""
    with_signals = ja.generate(Params.create("scenario"), 2)
    without = ja.generate(Params.create("scenario", junction_control="none"), 2)
    strip = [r.__class__(**{**r.__dict__, "signals": (), "objects": ()}) for r in with_signals.roads]
    assert tuple(strip) == without.roads
    assert with_signals.controllers and not without.controllers
    with pytest.raises(ja.ParamsError, match="junction_control"):
        Params.create(junction_control="roundabout")
    with pytest.raises(ja.ParamsError, match="country"):
        Params.create(country="XX")


def test_crosswalks_lie_across_the_carriageway_behind_the_junction_and_before_the_stop_line(lit):
    """Read back: each crosswalk's corners sit on the kerbs (the outer borders of the outermost non-roadside lanes) at
    their s, within 1..5 m of a junction end; the road's stop lines stand farther from that end than its crosswalk."""
    walks = 0
    for path in lit[:3]:
        root = etree.parse(str(path)).getroot()
        doc = read(path).document
        roads = {r.id: r for r in doc.roads}
        for road_el in root.iter("road"):
            road = roads[road_el.get("id")]
            lines = [float(x.get("s")) for x in road_el.iterfind("signals/signal[@type='294']")]
            for obj in road_el.iterfind("objects/object[@type='crosswalk']"):
                walks += 1
                corners = [(float(c.get("s")), float(c.get("t"))) for c in obj.iter("cornerRoad")]
                ss = sorted({s for s, _ in corners})
                near_end = ss[-1] > road.length / 2
                gap = road.length - ss[-1] if near_end else ss[0]
                assert len(ss) == 2 and ss[1] - ss[0] == pytest.approx(4.0) and gap == pytest.approx(1.0)
                for s, t in corners:
                    assert _kerb_distance(road, s, t) < 1e-6
                for s_line in lines:
                    if (s_line > road.length / 2) == near_end:
                        assert abs(s_line - (road.length if near_end else 0.0)) > 5.0
    assert walks > 30


def _kerb_distance(road, s: float, t: float) -> float:
    """Distance in t from (s, t) to the nearer kerb of ``road`` read by xodrcheck (outer border of the outermost
    carriageway lane on either side; the reference line on a side without lanes)."""
    index = max(k for k, sec in enumerate(road.lane_sections) if sec.s <= s + 1e-9)
    sec = road.lane_sections[index]
    kerbs = []
    for sign, lanes in ((1, sec.left), (-1, sec.right)):
        kerb = 0.0
        for lane in sorted(lanes, key=lambda ln: abs(ln.id)):
            if lane.type.value in ("curb", "sidewalk", "shoulder", "border"):
                break
            (w,) = lane.widths  # the generator writes one width record per lane and section
            ds = s - sec.s - w.s
            kerb += w.a + ds * (w.b + ds * (w.c + ds * w.d))
        kerbs.append(sign * kerb)
    return min(abs(t - k) for k in kerbs)


def test_xodrcheck_finds_the_conflicts_when_a_junction_s_signal_groups_are_merged(lit, tmp_path):
    """The checker's V001 (conflicting-signals-same-controller) agrees with the proof above: the generated groups give
    no finding (checked in the test above with every warning), and putting all lights of one junction in its first
    controller does, naming that junction and controller."""
    merged = 0
    for path in lit[:3]:
        root = etree.parse(str(path)).getroot()
        controllers = {c.get("id"): c for c in root.iterfind("controller")}
        for j in root.iter("junction"):
            refs = [ref.get("id") for ref in j.iterfind("controller")]
            if len(refs) < 2:
                continue
            first = controllers[refs[0]]
            for other in refs[1:]:
                for control in controllers[other].findall("control"):
                    first.append(control)
                controllers[other].getparent().remove(controllers[other])
                j.remove(next(r for r in j.iterfind("controller") if r.get("id") == other))
            out = tmp_path / f"{path.stem}-{j.get('id')}.xodr"
            etree.ElementTree(root).write(str(out), xml_declaration=True, encoding="UTF-8")
            report = check(out, GENERATOR, select=("V001",))
            codes = {f.code for f in report.findings}
            assert codes == {"V001"}, (out.name, codes)
            assert all(f"junction {j.get('id')}, controller {refs[0]}:" in f.message for f in report.findings)
            merged += 1
            break
    assert merged == 3


@pytest.mark.parametrize("version", ["1.8", "1.9"])
def test_crosswalks_are_marked_with_two_broken_lines_along_their_edges_across_the_road(lit, version, tmp_path):
    """Each crosswalk has two white broken-line markings (13.8), each through the two outline corners of one edge
    across the road (same s, the two kerbs), the two edges 4 m apart: in the object's <markings> in 1.8, inside the
    outline in 1.9 (where 1.9 puts them); xodrcheck's marking rules and the schema accept both."""
    doc = ja.generate(
        Params.create("scenario", junction_control="traffic-lights", randomize_lanes=True, curved_roads=True),
        CASES[1][0],
    )
    path = write(doc, tmp_path / f"walks-{version}.xodr", version)
    root = etree.parse(str(path)).getroot()
    walks = 0
    for obj in root.iter("object"):
        if obj.get("type") != "crosswalk":
            continue
        walks += 1
        (outline,) = obj.iter("outline")
        corners = {int(c.get("id")): (float(c.get("s")), float(c.get("t"))) for c in outline.iterfind("cornerRoad")}
        holder = outline if version == "1.9" else obj
        assert len(obj.findall(".//markings")) == 1 and holder.find("markings") is not None
        marks = holder.findall("markings/marking")
        assert len(marks) == 2
        edge_s = []
        for m in marks:
            assert m.get("color") == "white" and float(m.get("width")) == 0.12
            assert float(m.get("lineLength")) == 0.5 and float(m.get("spaceLength")) == 0.2
            a, b = (corners[int(r.get("id"))] for r in m.iterfind("cornerReference"))
            assert a[0] == b[0] and abs(a[1] - b[1]) > 2.5  # across the road, kerb to kerb
            edge_s.append(a[0])
        assert abs(edge_s[0] - edge_s[1]) == pytest.approx(4.0)
    assert walks > 10
    report = check(path, GENERATOR)
    assert [f.code for f in report.findings if f.severity.name in ("ERROR", "WARNING")] == []


def test_the_paper_profile_writes_no_object_or_marking():
    """Markings come with the crosswalks of signalised junctions only: the default maps have neither."""
    text = ja.writer.to_bytes(ja.generate(Params.create(), 3)).decode()
    assert "<object " not in text and "<marking" not in text
