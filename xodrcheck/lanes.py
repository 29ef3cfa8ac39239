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

This module keeps each road's structure (sections, the lanes of each side, profiles, lane heights), the evaluations'
caches and the entry points; one section's evaluation at an array of ``s`` and the lane lines drawn from it (border
jets, lateral offsets across rolled and level lanes, plan-view points) are :mod:`xodrcheck.lane_lines`'s.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping

import numpy as np

from xodrcheck.budget import ByteBudget
from xodrcheck.config import Tolerances
from xodrcheck.geometry import profile
from xodrcheck.geometry.jet import Jet
from xodrcheck.geometry.planview import ReferenceLine
from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.lane_lines import (
    Evaluation,
    LanePoints,
    SideLanes,
    bend,
    border_jets,
    evaluation_size,
    place,
    projected,
    stacked_border_lines,
)
from xodrcheck.model import Cubic, Document, Lane, LaneLayer, Road, document_cache
from xodrcheck.sampling import sample_section

_WHERE = ("centre", "inner", "outer")


#: Bytes of lane evaluations the roads of one document keep cached together (:class:`~xodrcheck.budget.ByteBudget`;
#: each road also keeps at most its last few): a 10 km map's roads kept 466 MB after the curvature rules without it.
EVALUATION_BUDGET = 32 << 20


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
        self._evaluations: dict[tuple[int, bytes], Evaluation] = {}
        self._batches: dict[int, profile.Batch] = {}
        self._heights: dict[tuple[int, int], tuple[Lane, profile.Piecewise, profile.Piecewise] | None] = {}

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

    def _batch(self, section_index: int) -> profile.Batch:
        """The section's profiles evaluated together: laneOffset, elevation, then every lane's width or border law
        (left lanes inner to outer, then right lanes)."""
        batch = self._batches.get(section_index)
        if batch is None:
            laws = [law for side in self.side_lanes(section_index) for law in side.laws if law is not None]
            batch = profile.Batch((self._offset, self._elevation, *laws))
            self._batches[section_index] = batch
        return batch

    def _evaluate(self, section_index: int, s: np.ndarray) -> Evaluation:
        """Reference pose, border jets, superelevation and elevation at ``s`` (a few recent queries are cached, so
        asking for several lanes at the same ``s`` costs one evaluation)."""
        key = (section_index, s.tobytes())
        found = self._evaluations.get(key)
        if found is not None:
            if self._budget is not None:
                self._budget.touch(self._evaluations, key)
        else:
            cos: Jet | None
            sin: Jet | None
            if len(self._roll.starts):
                roll = Jet(*self._roll.jet(s))
                cos, sin = roll.cos(), roll.sin()
            else:
                cos = sin = None
            offset, elevation, *laws = self._batch(section_index).jets(s)
            jets = border_jets(self.side_lanes(section_index), offset, laws)
            found = Evaluation(self.reference_line, s.copy(), jets, cos, sin, elevation[0])
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
        return {lane_id: jet.v.copy() for lane_id, jet in self._evaluate(section_index, as_array(s)).borders.items()}

    def inner_outer(self, section_index: int, lane_id: int, s) -> tuple[np.ndarray, np.ndarray]:
        """Lateral ``t`` of a lane's inner and outer border at ``s``."""
        jets = self._evaluate(section_index, as_array(s)).borders
        if lane_id not in jets:
            raise KeyError(f"road {self.road.id}: no lane {lane_id} in lane section {section_index}")
        inner = 0
        for lane in self.side_lanes(section_index)[0 if lane_id > 0 else 1].lanes:
            if lane.id == lane_id:
                break
            inner = lane.id
        return jets[inner].v.copy(), jets[lane_id].v.copy()

    def _height_laws(
        self, section_index: int, lane_id: int
    ) -> tuple[Lane, profile.Piecewise, profile.Piecewise] | None:
        """The lane and its compiled inner and outer height profiles (``None`` for a lane without ``<height>``): each
        record is a constant, so the one profile evaluation serves (records relative to the lanes' section start)."""
        key = (section_index, lane_id)
        if key not in self._heights:
            found = None
            for side in self.side_lanes(section_index):
                lane = next((lane for lane in side.lanes if lane.id == lane_id), None)
                if lane is not None and lane.heights:
                    inner = tuple(Cubic(h.s, h.inner, 0.0, 0.0, 0.0, h.line) for h in lane.heights)
                    outer = tuple(Cubic(h.s, h.outer, 0.0, 0.0, 0.0, h.line) for h in lane.heights)
                    found = (lane, profile.Piecewise(inner, side.origin), profile.Piecewise(outer, side.origin))
                if lane is not None:
                    break
            self._heights[key] = found
        return self._heights[key]

    def has_height(self, section_index: int, lane_id: int) -> bool:
        """Whether the lane has ``<height>`` records (its own lines differ from the shared border lines)."""
        return self._height_laws(section_index, lane_id) is not None

    def lane_height(self, section_index: int, lane_id: int, s) -> tuple[np.ndarray, np.ndarray]:
        """Lane height (11.7.3) of a lane's inner and outer border at ``s``: 0 without ``<height>`` records."""
        s = as_array(s)
        laws = self._height_laws(section_index, lane_id)
        if laws is None:
            return np.zeros_like(s), np.zeros_like(s)
        return laws[1].jet(s)[0], laws[2].jet(s)[0]

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
        evaluation = self._evaluate(section_index, as_array(s))
        if lane_id not in evaluation.borders:
            raise KeyError(f"road {self.road.id}: no lane {lane_id} in lane section {section_index}")
        lateral, height = projected(self.side_lanes(section_index), evaluation, lane_id, where)
        if raised:
            lateral, height = self._raised(section_index, evaluation, lane_id, where, lateral, height)
        return place(evaluation, lateral, height)

    def _raised(
        self,
        section_index: int,
        evaluation: Evaluation,
        lane_id: int,
        where: str,
        lateral: Jet,
        height: np.ndarray | float,
    ) -> tuple[Jet, np.ndarray | float]:
        """A lane line lifted by the lane's height along the h-axis: normal to the lane's surface, which is rolled by
        the superelevation unless the lane is level."""
        laws = self._height_laws(section_index, lane_id) if lane_id != 0 else None
        if laws is None:
            return lateral, height
        lane, inner_law, outer_law = laws
        inner, outer = Jet(*inner_law.jet(evaluation.s)), Jet(*outer_law.jet(evaluation.s))
        lift = inner if where == "inner" else outer if where == "outer" else (inner + outer).scale(0.5)
        if lane.level or evaluation.cos is None or evaluation.sin is None:
            return lateral, height + lift.v
        return lateral - lift * evaluation.sin, height + lift.v * evaluation.cos.v

    def section_reference(self, section_index: int, s) -> Pose:
        """The reference-line pose at ``s``, from the same evaluation as the section's lanes at those ``s`` (asking
        for both costs one plan-view evaluation)."""
        return self._evaluate(section_index, as_array(s)).pose

    def border_curves(self, section_index: int, s) -> dict[int, LanePoints]:
        """Every lane's outer border (and lane 0's line) at ``s``: all the border polylines of the section."""
        evaluation = self._evaluate(section_index, as_array(s))
        ids, lateral, height = stacked_border_lines(self.side_lanes(section_index), evaluation)
        p = place(evaluation, lateral, height)  # every line at once, one row each
        z = p.z if p.z.ndim == 2 else np.repeat(p.z[None, :], len(ids), axis=0)  # flat road: one z for all
        return {
            lane_id: LanePoints(p.x[k], p.y[k], z[k], p.hdg[k], p.curvature[k], p.speed[k])
            for k, lane_id in enumerate(ids)
        }

    def border_bending(self, section_index: int, s) -> np.ndarray:
        """At each ``s``, the largest of ``|curvature| * speed^2`` over the section's border lines (lane 0's line
        included; see :meth:`border_curves`) and ``|curvature|`` of the reference line: what the sampler bounds.
        NaN where every one is NaN."""
        evaluation = self._evaluate(section_index, as_array(s))
        pose = evaluation.pose
        _, lateral, _ = stacked_border_lines(self.side_lanes(section_index), evaluation)
        _, speed, curvature = bend(pose, lateral)
        return np.fmax(np.abs(pose.curvature), np.fmax.reduce(np.abs(curvature) * speed**2, axis=0))

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
        ``max_samples_per_section``: past it the steps grow); see :mod:`xodrcheck.sampling`."""
        defaults = Tolerances()
        return sample_section(
            self,
            section_index,
            defaults.chord if chord is None else chord,
            defaults.max_step if max_step is None else max_step,
            defaults.max_samples_per_section if budget is None else budget,
        )


class _LazyGeometries(Mapping[str, RoadGeometry]):
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


def geometry_of(document: Document) -> Mapping[str, RoadGeometry]:
    """Road id -> :class:`RoadGeometry`, built on first access and cached for the document's lifetime."""
    cache = document_cache(document)
    found = cache.get("geometry")
    if found is None:
        found = cache["geometry"] = _LazyGeometries(document.road_by_id)
    return found


def temporary_geometry_of(document: Document) -> Mapping[str, RoadGeometry]:
    """Road id -> :class:`RoadGeometry` of the road's temporary lane layer (1.9), for the roads that have one; built
    on first access and cached like :func:`geometry_of`."""
    cache = document_cache(document)
    found = cache.get("temporary geometry")
    if found is None:
        roads = {road_id: road for road_id, road in document.road_by_id.items() if road.temporary_lanes is not None}
        found = cache["temporary geometry"] = _LazyGeometries(roads, LaneLayer.TEMPORARY)
    return found
