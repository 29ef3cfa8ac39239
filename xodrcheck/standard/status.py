"""Which rules of the standard xodrcheck enforces, computed from the rule registry.

A UID is *enforced* when a registered rule declares it in full, *partial* when rules declare it only in part (each
says what it leaves out), and *not enforced* otherwise; :data:`NOT_ENFORCED` gives the reason for each of those
(a UID there that a rule enforces is a contradiction the tests catch).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from xodrcheck.findings import Severity
from xodrcheck.rules.registry import Rule
from xodrcheck.standard import annex_rules

#: Why a rule of the standard is not enforced, by UID.
NOT_ENFORCED: dict[str, str] = {
    # road.lane.road_mark (11.9)
    "asam.net:xodr:1.9.0:road.lane.road_mark.position_outer_half": (
        "says where an application draws a marking: centred on the lane's outer border, half on the next lane. A "
        "<roadMark> has no position of its own (the tOffset of its <line> elements and its <sway> are deliberate "
        "displacements from that border), so nothing in the file can place it otherwise"
    ),
    # road.object (13): permissions and statements of what a reader does
    "asam.net:xodr:1.7.0:road.object.bridges.define_type": (
        "a permission: a bridge may be restricted to certain lanes with <validity> (or not), so no file can break it; "
        "the lanes' order is validity-lanes-reversed's (B005)"
    ),
    "asam.net:xodr:1.7.0:road.object.material.materials_may_differ": (
        "a permission: an object's <material> may differ from the road's around it, so no file can break it"
    ),
    "asam.net:xodr:1.8.2:road.object.object_marking.include_points_between_cornerReferences": (
        "says how a marking is drawn when its corner references skip outline points: through every point between "
        "them; any ordered list of references has that meaning, so no file can break it (the order itself is "
        "keep_id_ordered's, B023)"
    ),
    "asam.net:xodr:1.8.0:road.object.skeleton.vertex_local.linear_interpolation": (
        "says how a reader sizes a skeleton between two <vertexLocal> points (radius or width and length "
        "interpolated linearly); no file can say otherwise"
    ),
    "asam.net:xodr:1.9.0:road.object.skeleton.vertex_road.linear_interpolation": (
        "says how a reader sizes a skeleton between two <vertexRoad> points (radius or width and length "
        "interpolated linearly); no file can say otherwise"
    ),
    "asam.net:xodr:1.7.0:road.object.surface.calculate_road_height": (
        "says how a reader computes the road height where the object's CRG (crgEvaluv2z) returns NaN: needs the "
        "content of the CRG file, which is outside the .xodr, and describes evaluation, not the file"
    ),
    "asam.net:xodr:1.7.0:road.object.surface.identical_local_coordinates": (
        "says that a reader places the object's CRG in the object's local frame and ignores the CRG file's own "
        "reference line, position, curvature and heading: those are in the CRG file, outside the .xodr"
    ),
    # junctions (12.4, 12.11)
    "asam.net:xodr:1.7.0:junctions.connection.lane_change_one_con_road": (
        "describes one of two ways to connect an incoming road's lanes (one connecting road with several <laneLink> "
        "elements, which allows lane changes in the junction); a permission, which no file can break"
    ),
    "asam.net:xodr:1.7.0:junctions.connection.no_lane_change_for_mult_con_roads": (
        "describes the other way (one connecting road per pair of lanes, each with one <laneLink>) and what it means: "
        "no lane changes in the junction; a permission and its consequence for traffic, which no file can break"
    ),
    "asam.net:xodr:1.8.0:junctions.direct.flat_exits_entries": (
        "states a limit of the model ('currently only flat entries and exits can be modeled by overlapping direct "
        "junctions', 12.6), not a property with a measure: 12.6 gives no slope or height limit for 'flat'. Where the "
        "overlapping lanes' surfaces do not meet, link-step (K104) and lane-border-gap (K103) report it at the "
        "junction's joints (junctions.direct.linked_lane_smoothness)"
    ),
    "asam.net:xodr:1.8.0:junctions.elevation_grid.polynome_coefficient_values": (
        "says how an application interpolates an elevation grid (12.11.1: c and d of the edge polynomials are 0 "
        "where too few grid points support them); the file holds only the grid's z-values, no coefficients, so no "
        "file can break it"
    ),
    # road.type (10.4)
    "asam.net:xodr:1.4.0:road.type.create_new_type_in_parent": (
        "says how a change of road type is written (a new <type> in the <road>); a file has no other way to write "
        "one, and the schema (S001) allows <type> only inside <road>, so no file can break it; a <type> that "
        "changes nothing is redundant-record's (G901)"
    ),
    "asam.net:xodr:1.4.0:road.type.lane_type_may_differ_from_parent": (
        "a permission: any lane type may sit under any road type, so no file can break it"
    ),
}

NOT_ENFORCED.update(
    {
        # road.signal (14)
        "asam.net:xodr:1.7.0:road.signal.priority": (
            "says how applications use signals (before other traffic rules); a file has no way to rank them "
            "otherwise, so no file can break it"
        ),
        "asam.net:xodr:1.7.0:road.signal.dependency.multiple_dependency": (
            "a permission: a signal may have any number of <dependency> elements, so no file can break it"
        ),
        # road.crg (10.6), road.cross_section_surface (10.5.4)
        "asam.net:xodr:1.7.0:road.crg.use_last_entry": (
            "says which of overlapping CRG entries applications use (the last one); a file cannot break that, and "
            "overlapping entries are reported under road.crg.only_on_per_s (U003)"
        ),
        "asam.net:xodr:1.8.0:road.cross_section_surface.height": (
            "says how a lane's @height combines with a cross section surface (it is added in z); a permission about "
            "evaluation that no file can break"
        ),
        "asam.net:xodr:1.8.0:road.cross_section_surface.lane_def_valid": (
            "says where a cross section surface applies (within the road's lanes: its outer strips reach the outer "
            "lane edges); the surface's extent is defined by the lanes, so no file can make it reach elsewhere"
        ),
    }
)

#: Under the default profile a finding is at most as severe as the standard's wording makes it (shall -> error,
#: should -> warning, may -> info: :mod:`xodrcheck.verdict`). These UIDs' findings are less severe still: UID ->
#: (severity, why). (The strict and generator profiles give every rule its own severity: G002's and G004's errors.)
SEVERITY_DEVIATIONS: dict[str, tuple[Severity, str]] = {
    "asam.net:xodr:1.8.1:performance.avoid_redundant_info": (
        Severity.INFO,
        "a redundant record changes nothing any reader computes (the map means the same with it or without it); the "
        "shared corpus has over 9,000 of them, and as warnings they would bury the defects that matter; select G901 "
        "or the UID to list them",
    ),
}


def expected_severity(uid: str) -> Severity:
    """The severity of a finding that enforces ``uid`` under the default profile."""
    if uid in SEVERITY_DEVIATIONS:
        return SEVERITY_DEVIATIONS[uid][0]
    return annex_rules()[uid].severity


ENFORCED, PARTIAL, MISSING = "enforced", "partial", "not enforced"


@dataclass(frozen=True, slots=True)
class UidStatus:
    """How far xodrcheck enforces one rule (UID) of the standard, and by which of its rules."""

    uid: str
    section: str
    level: str
    status: str
    #: Codes of the rules that enforce the UID (in full or in part).
    codes: tuple[str, ...]
    #: What is not checked (partial) or why nothing is (not enforced); empty when enforced in full.
    note: str

    def as_dict(self) -> dict:
        return {
            "uid": self.uid,
            "section": self.section,
            "level": self.level,
            "status": self.status,
            "codes": list(self.codes),
            "note": self.note,
        }


def statuses(rules: Mapping[str, Rule]) -> list[UidStatus]:
    """The status of every Annex F rule, in the annex's order."""
    full: dict[str, list[str]] = {}
    part: dict[str, list[tuple[str, str]]] = {}
    for rule in rules.values():
        for uid in rule.uids:
            if uid in rule.partial:
                part.setdefault(uid, []).append((rule.code, rule.partial[uid]))
            else:
                full.setdefault(uid, []).append(rule.code)
    out = []
    for uid, annex in annex_rules().items():
        codes = tuple(sorted({*full.get(uid, ()), *(code for code, _ in part.get(uid, ()))}))
        if uid in full:
            status, note = ENFORCED, ""
        elif uid in part:
            status, note = PARTIAL, "; ".join(f"{code}: {why}" for code, why in part[uid])
        else:
            status, note = MISSING, NOT_ENFORCED.get(uid, "not implemented yet")
        out.append(UidStatus(uid, annex.section, annex.level, status, codes, note))
    return out


def summary_line(table: list[UidStatus]) -> str:
    counts = {s: sum(1 for row in table if row.status == s) for s in (ENFORCED, PARTIAL, MISSING)}
    return (
        f"{len(table)} checker rules of ASAM OpenDRIVE 1.9.0 (Annex F): {counts[ENFORCED]} enforced in full, "
        f"{counts[PARTIAL]} in part, {counts[MISSING]} not enforced"
    )
