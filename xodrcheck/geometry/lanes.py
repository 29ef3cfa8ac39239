"""Lane borders and lane centres of a road, evaluated exactly and vectorised over ``s``.

Conventions and decisions (ASAM OpenDRIVE 1.8 section numbers)
--------------------------------------------------------------
* ``t`` is the lateral coordinate of the road reference line's s/t system, positive to the left (8.3). Lane 0 (the
  centre lane) lies at ``t = laneOffset(s)`` (11.4).
* Width records accumulate outward from lane 0: the outer border of lane ``+k`` is
  ``laneOffset + w(1) + ... + w(k)`` and of lane ``-k`` is ``laneOffset - w(-1) - ... - w(-k)`` (11.6.1), over the lanes
  the section actually has, ordered by ``|id|``. Records are ``sOffset`` from the section start.
* A ``<border>`` record gives the outer border's ``t`` itself, "independent of the parameters of their inner borders"
  (11.6.2); ``t`` being measured from the road reference line (8.3), a border is *not* shifted by the laneOffset.
  When a lane has both ``<width>`` and ``<border>``, the widths are used, as 11.6.1 requires. A lane with neither is
  zero wide.
* The centre of a lane is midway (in ``t``) between its inner and outer border.
* Superelevation rolls the t-axis about the reference line (8.3: "t ... angled relative to the x/y plane according
  to the road superelevation. Values of t are measured in the superelevated lane. The value of the @width attribute
  of the lane does not change if superelevation is applied"). A point at lateral ``t`` therefore lies ``t cos(phi)``
  from the reference line in plan view and ``t sin(phi)`` above it (positive ``phi`` lifts the left side). A lane with
  ``level="true"`` is not rolled (11.2: "keep lane on level, that is, do not apply superelevation"): it continues
  horizontally from its inner border, so it keeps its full width in plan view and its inner border's height; lanes
  outside it are rolled again from its outer border. The road's pitch does not enter: the reference line lies in
  the x/y plane (8.3) and the t-axis is rotated about it by superelevation only. (The two oracle readers disagree here:
  esmini, judging from its positions, turns the lateral axis by heading, pitch and roll, which adds an along-road
  shift of about ``t sin(phi) sin(pitch)``; CARLA's lane points carry heading and pitch but no roll.)
* Lane height (11.7.3, ``<height inner outer>``) raises a lane's inner and outer border "along the h-coordinate",
  normal to the (superelevated) road surface: by ``h cos(phi)`` in z and ``-h sin(phi)`` across the road in plan view
  (straight up for a level lane or a road without superelevation). A record holds from its ``sOffset`` until the next
  one (no interpolation along ``s``; 0 before the first), and the lane's centre is raised by the mean of ``inner`` and
  ``outer``. The border lines shared by neighbouring lanes (:meth:`RoadGeometry.border_curves`) are the road surface
  without lane height; :meth:`RoadGeometry.lane_points` with ``raised=True`` gives a lane's own raised lines.
* ``z`` is the elevation profile (10.5) plus the superelevation height above. The header ``<offset>`` is not applied:
  it maps the file's local coordinates to world coordinates for georeferencing (8.5) and every lane position here is
  in the file's own inertial frame, as the geometry is written.
* ``singleSide="true"`` sections (11.3, Figure 62) describe one side only; the other side continues with the lanes
  (and records, relative to their own section start) of the last earlier section that had lanes there.
* The lane section containing ``s`` is the last one starting at or before ``s``: a section boundary belongs to the
  section that starts there (and ``s`` before the first section to the first). A 1.9 section with ``length`` ends at
  ``s + length`` (11.4); past that end, until the next section, there is none.
* OpenDRIVE 1.9 lane layers (11.2): :func:`geometry_of` evaluates the permanent layer (the road surface: the temporary
  layer "does not modify the surface", 11.2), :func:`temporary_geometry_of` the temporary layer with its own lane
  offset and sections, through the same evaluator; it has no section before its first one.

Lane heading and curvature are those of the offset curve ``P = R(s) + q(s) N(s)`` in plan view (``q`` the projected
lateral offset), with ``q'`` and ``q''`` carried exactly (:mod:`xodrcheck.geometry.jet`): heading
``theta + atan2(q', 1 - q k)`` and curvature ``(A^2 k + A q'' + 2 q'^2 k + q q' k') / (A^2 + q'^2)^(3/2)``,
``A = 1 - q k``; widening lanes therefore contribute their width change.

This module keeps each road's structure (sections, the lanes of each side laid out as rows, profiles, lane heights,
knots), the evaluations' caches and the per-road entry points; every evaluation is one block of the batched kernel
(:mod:`xodrcheck.geometry.batch`), which evaluates many sections at once with the same numbers.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.geometry import profile
from xodrcheck.geometry.batch import Evaluation
from xodrcheck.geometry.lines import LanePoints
from xodrcheck.geometry.planview import ReferenceLine
from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.geometry.rows import SectionRows, lay_out
from xodrcheck.geometry.sampling import sample_sections
from xodrcheck.model import Document, Lane, LaneLayer, Road, document_cache
from xodrcheck.support.budget import ByteBudget, array_bytes

_WHERE = ("centre", "inner", "outer")


#: Bytes of lane evaluations the roads of one document keep cached together
#: (:class:`~xodrcheck.support.budget.ByteBudget`; each road also keeps at most its last few): unbounded, a big map's
#: cached evaluations grow with the map.
EVALUATION_BUDGET = 32 << 20


@dataclass(frozen=True, slots=True)
class SideLanes:
    """The lanes of one side in effect in a section, inner to outer, with the ``s`` their records are relative to.

    ``laws[i]`` is lane ``i``'s compiled width profile (``is_width[i]``) or border profile, ``None`` for neither."""

    lanes: tuple[Lane, ...]
    origin: float
    laws: tuple[profile.Piecewise | None, ...]
    is_width: tuple[bool, ...]


def evaluation_size(evaluation: Evaluation) -> int:
    """Bytes an evaluation of one block holds once its lines and pose are computed, about: per row the border and
    lateral jets, the pairs' samples and where each depth's rows and their inner neighbours lie, and per sample ``s``,
    the pose with its heading, the elevation and the roll."""
    return array_bytes(9 * len(evaluation.sections[0].ids) + 17, evaluation.s.size)


class RoadGeometry:
    """Evaluates one road: reference line, lane offset, lane borders and lane points; of the road's temporary lane
    layer (1.9) with ``layer=LaneLayer.TEMPORARY`` (then ``road`` is the road seen through that layer,
    :meth:`~xodrcheck.model.Road.temporary_layer`, and no section covers ``s`` before its first one)."""

    _CACHED_EVALUATIONS = 4

    def __init__(self, road: Road, layer: LaneLayer = LaneLayer.PERMANENT, budget: ByteBudget | None = None) -> None:
        self.layer = layer
        #: The cache bound shared with the document's other roads (``None``: this road's last few evaluations).
        self._budget = budget
        if layer is LaneLayer.TEMPORARY:
            view = road.temporary_layer()
            if view is None:
                raise ValueError(f"road {road.id} has no temporary lane layer")
            road = view
        self.road = road
        self.reference_line = ReferenceLine(road.plan_view)
        self._starts = np.array([sec.s for sec in road.lane_sections], dtype=float)
        # ends of sections with a 1.9 length (others end where the next starts): None when no section has one
        self._ends = (
            np.array([road.section_end(i) for i in range(len(road.lane_sections))], dtype=float)
            if any(sec.length is not None for sec in road.lane_sections)
            else None
        )
        self._sides: dict[int, tuple[SideLanes, SideLanes]] = {}
        self._offset = profile.Piecewise(road.lane_offset)
        self._elevation = profile.Piecewise(road.elevation)
        self._roll = profile.Piecewise(road.superelevation)
        self._laws = (
            profile.Table((self._elevation,)),
            profile.Table((self._roll,)) if len(self._roll.starts) else None,
        )
        self._rows: dict[int, SectionRows] = {}
        self._knots: dict[int, np.ndarray] = {}
        self._evaluations: dict[tuple[int, bytes], Evaluation] = {}

    # ---------------------------------------------------------------------------------------------------------------
    # Road level
    # ---------------------------------------------------------------------------------------------------------------
    def reference(self, s) -> Pose:
        return self.reference_line.evaluate(s)

    def lane_offset(self, s) -> np.ndarray:
        return self._offset.jet(s)[0]

    def elevation(self, s) -> np.ndarray:
        return self._elevation.jet(s)[0]

    def superelevation(self, s) -> np.ndarray:
        return self._roll.jet(s)[0]

    def section_index(self, s) -> np.ndarray:
        """Index of the lane section containing each ``s`` (see the module docstring for boundaries); -1 where there
        is none (no sections, or past the end of a section with a 1.9 ``length``)."""
        s = as_array(s)
        if len(self._starts) == 0:
            return np.full(len(s), -1)
        index = np.searchsorted(self._starts, s, side="right") - 1
        if self.layer is LaneLayer.PERMANENT:
            index = np.maximum(index, 0)
        if self._ends is not None:
            index = np.where((index >= 0) & (s > self._ends[index]), -1, index)
        return index

    def section_range(self, section_index: int) -> tuple[float, float]:
        return self.road.lane_sections[section_index].s, self.road.section_end(section_index)

    # ---------------------------------------------------------------------------------------------------------------
    # Lateral structure
    # ---------------------------------------------------------------------------------------------------------------
    def side_lanes(self, section_index: int) -> tuple[SideLanes, SideLanes]:
        """(left, right) lanes in effect in the section, each inner to outer (``singleSide`` resolved)."""
        cached = self._sides.get(section_index)
        if cached is None:
            cached = (self._side(section_index, +1), self._side(section_index, -1))
            self._sides[section_index] = cached
        return cached

    def cached_evaluations(self) -> int:
        """How many evaluations (of a lane section at a set of ``s``) the road keeps for reuse."""
        return len(self._evaluations)

    def placed_lane_ids(self, section_index: int) -> frozenset[int]:
        """Ids of the lanes placed in the section: positive ids in ``<left>``, negative in ``<right>`` (a lane filed
        on the wrong side has no border to evaluate), ``singleSide`` sections resolved."""
        return frozenset(lane.id for side in self.side_lanes(section_index) for lane in side.lanes)

    def _side(self, section_index: int, sign: int) -> SideLanes:
        sections = self.road.lane_sections
        i = section_index
        while True:
            section = sections[i]
            group = section.left if sign > 0 else section.right
            lanes = tuple(sorted((lane for lane in group if lane.id * sign > 0), key=lambda lane: abs(lane.id)))
            if lanes or not section.single_side or i == 0:
                break
            i -= 1
        laws = tuple(
            profile.Piecewise(lane.widths or lane.borders, section.s) if lane.widths or lane.borders else None
            for lane in lanes
        )
        return SideLanes(lanes, section.s, laws, tuple(bool(lane.widths) for lane in lanes))

    def rows(self, section_index: int) -> SectionRows:
        """The section laid out for the batched evaluation (:class:`~xodrcheck.geometry.rows.SectionRows`)."""
        found = self._rows.get(section_index)
        if found is None:
            found = self._rows[section_index] = lay_out(
                self.reference_line, self.side_lanes(section_index), self._offset, *self._laws
            )
        return found

    def knots(self, section_index: int) -> np.ndarray:
        """Sorted unique ``s`` where the section's curves may change their law: the section ends, plan-view element
        joints, laneOffset, elevation and superelevation record starts, and the width/border record starts of the
        lanes in effect (a new array: callers own it)."""
        found = self._knots.get(section_index)
        if found is None:
            s0, s1 = self.section_range(section_index)
            candidates = [
                np.array([s0, s1]),
                self.reference_line.breakpoints,
                self._offset.starts,
                self._elevation.starts,
                self._roll.starts,
            ]
            for side in self.side_lanes(section_index):
                candidates.extend(law.starts for law in side.laws if law is not None)
            points = np.concatenate(candidates)
            found = self._knots[section_index] = np.unique(points[(points >= s0) & (points <= s1)])
        return found.copy()

    def _evaluate(self, section_index: int, s) -> Evaluation:
        """The section evaluated at ``s``, a batch of one block (a few recent queries are cached, so asking for
        several lanes at the same ``s`` costs one evaluation)."""
        s = as_array(s)
        key = (section_index, s.tobytes())
        found = self._evaluations.get(key)
        if found is not None:
            if self._budget is not None:
                self._budget.touch(self._evaluations, key)
            return found
        found = Evaluation([self.rows(section_index)], [s])
        if len(self._evaluations) >= self._CACHED_EVALUATIONS:
            oldest = next(iter(self._evaluations))
            del self._evaluations[oldest]
            if self._budget is not None:
                self._budget.discard(self._evaluations, oldest)
        self._evaluations[key] = found
        if self._budget is not None:
            self._budget.add(self._evaluations, key, evaluation_size(found))
        return found

    def borders(self, section_index: int, s) -> dict[int, np.ndarray]:
        """Lateral ``t`` of each lane's outer border at ``s`` (lane 0: the laneOffset line)."""
        return self._evaluate(section_index, s).borders(0)

    def _row(self, section_index: int, lane_id: int) -> int:
        row = self.rows(section_index).first.get(lane_id)
        if row is None:
            raise KeyError(f"road {self.road.id}: no lane {lane_id} in lane section {section_index}")
        return row

    def inner_outer(self, section_index: int, lane_id: int, s) -> tuple[np.ndarray, np.ndarray]:
        """Lateral ``t`` of a lane's inner and outer border at ``s``."""
        outer = self._row(section_index, lane_id)
        inner = 0
        for lane in self.side_lanes(section_index)[0 if lane_id > 0 else 1].lanes:
            if lane.id == lane_id:
                break
            inner = lane.id
        evaluation = self._evaluate(section_index, s)
        t = evaluation.t[0]
        first = self.rows(section_index).first
        return t[evaluation.row_pairs(0, first[inner])].copy(), t[evaluation.row_pairs(0, outer)].copy()

    def has_height(self, section_index: int, lane_id: int) -> bool:
        """Whether the lane has ``<height>`` records (its own lines differ from the shared border lines)."""
        rows = self.rows(section_index)
        return rows.first.get(lane_id, -1) in rows.heights

    def lane_height(self, section_index: int, lane_id: int, s) -> tuple[np.ndarray, np.ndarray]:
        """Lane height (11.7.3) of a lane's inner and outer border at ``s``: 0 without ``<height>`` records."""
        s = as_array(s)
        rows = self.rows(section_index)
        laws = rows.heights.get(rows.first.get(lane_id, -1))
        if laws is None:
            return np.zeros_like(s), np.zeros_like(s)
        return laws[0].jet(s)[0], laws[1].jet(s)[0]

    # ---------------------------------------------------------------------------------------------------------------
    # Points
    # ---------------------------------------------------------------------------------------------------------------
    def lane_points(
        self, section_index: int, lane_id: int, s, where: str = "centre", raised: bool = False
    ) -> LanePoints:
        """Points of a lane's centre, inner or outer border at ``s`` (lane 0: its line, whatever ``where``); with
        ``raised``, lifted by the lane's height along the h-axis (see the module docstring)."""
        if where not in _WHERE:
            raise ValueError(f"where must be one of {_WHERE}, got {where!r}")
        self._row(section_index, lane_id)
        return self._evaluate(section_index, s).lines([(0, lane_id, where, raised)]).points()

    def section_reference(self, section_index: int, s) -> Pose:
        """The reference-line pose at ``s``, from the same evaluation as the section's lanes at those ``s`` (asking
        for both costs one plan-view evaluation)."""
        return self._evaluate(section_index, s).pose

    def border_curves(self, section_index: int, s) -> dict[int, LanePoints]:
        """Every lane's outer border (and lane 0's line) at ``s``: all the border polylines of the section."""
        return self._evaluate(section_index, s).border_points()[0]

    def border_bending(self, section_index: int, s) -> np.ndarray:
        """At each ``s``, the largest of ``|curvature| * speed^2`` over the section's border lines (lane 0's line
        included; see :meth:`border_curves`) and ``|curvature|`` of the reference line: what the sampler bounds.
        NaN where every one is NaN."""
        return self._evaluate(section_index, s).bending()

    # ---------------------------------------------------------------------------------------------------------------
    # Sampling
    # ---------------------------------------------------------------------------------------------------------------
    def sample_s(
        self,
        section_index: int,
        chord: float | None = None,
        max_step: float | None = None,
        budget: int | None = None,
    ) -> np.ndarray:
        """Sorted ``s`` covering the section with every knot, lane-border chord error under ``chord`` (default:
        the configured tolerance) and steps of at most ``max_step``, within a sample ``budget`` (default
        ``max_samples_per_section``: past it the steps grow); see :mod:`xodrcheck.geometry.sampling`."""
        defaults = Tolerances()
        return sample_sections(
            [(self.rows(section_index), self.knots(section_index))],
            defaults.chord if chord is None else chord,
            defaults.max_step if max_step is None else max_step,
            defaults.max_samples_per_section if budget is None else budget,
        )[0]


class RoadGeometries(Mapping[str, RoadGeometry]):
    """Road id -> :class:`RoadGeometry` of one lane layer, each built when first asked for; their evaluations share
    one memory budget."""

    def __init__(self, roads: Mapping[str, Road], layer: LaneLayer = LaneLayer.PERMANENT):
        self._roads = roads
        self._layer = layer
        self._built: dict[str, RoadGeometry] = {}
        self.budget = ByteBudget(EVALUATION_BUDGET)

    def __getitem__(self, road_id: str) -> RoadGeometry:
        geometry = self._built.get(road_id)
        if geometry is None:
            geometry = RoadGeometry(self._roads[road_id], self._layer, self.budget)
            self._built[road_id] = geometry
        return geometry

    def __iter__(self) -> Iterator[str]:
        return iter(self._roads)

    def __len__(self) -> int:
        return len(self._roads)

    def built(self) -> list[str]:
        """Ids of the roads whose geometry was asked for so far (the others are not evaluated)."""
        return list(self._built)


def road_geometry(geometries: Mapping[str, RoadGeometry], road: Road) -> RoadGeometry:
    """``road``'s geometry from ``geometries`` (:func:`geometry_of`), or one of its own for a road whose id an earlier
    road of the document has (the mapping holds the first road of an id)."""
    found = geometries[road.id]
    return found if found.road is road else RoadGeometry(road)


def geometry_of(document: Document) -> RoadGeometries:
    """Road id -> :class:`RoadGeometry`, built on first access and cached for the document's lifetime."""
    cache = document_cache(document)
    found = cache.get("geometry")
    if found is None:
        found = cache["geometry"] = RoadGeometries(document.road_by_id)
    return found


def temporary_geometry_of(document: Document) -> RoadGeometries:
    """Road id -> :class:`RoadGeometry` of the road's temporary lane layer (1.9), for the roads that have one; built
    on first access and cached like :func:`geometry_of`."""
    cache = document_cache(document)
    found = cache.get("temporary geometry")
    if found is None:
        roads = {road_id: road for road_id, road in document.road_by_id.items() if road.temporary_lanes is not None}
        found = cache["temporary geometry"] = RoadGeometries(roads, LaneLayer.TEMPORARY)
    return found
