"""The Annex F UIDs of the junction families (``junctions.*``, F.4; chapter 12 of ASAM OpenDRIVE 1.9.0), named once.

Rules take them from here, so a UID is spelled in one place.
"""

from __future__ import annotations

_P14 = "asam.net:xodr:1.4.0:junctions."
_P15 = "asam.net:xodr:1.5.0:junctions."
_P17 = "asam.net:xodr:1.7.0:junctions."
_P18 = "asam.net:xodr:1.8.0:junctions."
_P19 = "asam.net:xodr:1.9.0:junctions."

# F.4.1-F.4.3 junctions (12.1)
NO_OVERLAP = _P14 + "no_overlap"
DEFAULT_NO_LINKED_ROAD = _P17 + "type_default_no_linked_road"
DIRECT_NO_CONN_ROAD = _P17 + "type_direct_no_conn_road"

# F.4.4 boundary (12.10)
BOUNDARY_CLOSE_GAP_WITH_NEW_ROADS = _P18 + "boundary.close_gap_with_new_roads"
BOUNDARY_ONLY_COMMON = _P18 + "boundary.only_for_common_junctions"
BOUNDARY_CLOSED = _P18 + "boundary.segments_close_boundry"
BOUNDARY_COUNTER_CLOCKWISE = _P18 + "boundary.segments_counter_clockwise_order"
BOUNDARY_EACH_ROAD = _P18 + "boundary.segments_for_each_conn_road"

# F.4.5 common (12.2)
COMMON_DIRECT_ATTRIBUTES = _P18 + "common.direct_junction_attributes"
COMMON_NO_PRED_SUCC = _P14 + "common.junctions_no_pred_succ"
COMMON_NOT_ONLY_TWO = _P19 + "common.not_only_two"
COMMON_VIRTUAL_ATTRIBUTES = _P15 + "common.virtual_junction_attributes"
COMMON_WHEN_TO_USE = _P14 + "common.when_to_use"

# F.4.6 connection (12.3, 12.4)
CONNECTION_NOT_INCOMING = _P14 + "connection.connect_road_no_incoming_road"
CONNECTION_END_OPPOSITE = _P17 + "connection.end_opposite_linkage"
CONNECTION_ONE_CON_ROAD = _P17 + "connection.lane_change_one_con_road"
CONNECTION_NO_CONNECTING_ROAD_DIRECT = _P19 + "connection.no_connecting_road_direct"
CONNECTION_MULT_CON_ROADS = _P17 + "connection.no_lane_change_for_mult_con_roads"
CONNECTION_ONE_LINK = _P18 + "connection.one_link_to_incoming"
CONNECTION_SMOOTH_FIT = _P19 + "connection.smooth_fit"
CONNECTION_START_ALONG = _P17 + "connection.start_along_linkage"

# F.4.7 crossing (12.8)
CROSSING_ONE_HIGH = _P18 + "crossing.only_one_high_prio"
CROSSING_ONLY_ROAD_SECTIONS = _P18 + "crossing.only_road_sections"
CROSSING_COVERAGE = _P18 + "crossing.s_start_end_coverage"

# F.4.8 cross_path (12.5)
CROSS_PATH_JUNCTION_ID = _P18 + "cross_path.correct_junction_id"
CROSS_PATH_ELEVATION = _P18 + "cross_path.disregard_cross_road_evelation"
CROSS_PATH_LANE_LINKAGE = _P18 + "cross_path.lane_linkage"
CROSS_PATH_LANE_TYPES = _P18 + "cross_path.only_connect_correct_type"
CROSS_PATH_CONTAINED = _P18 + "cross_path.start_end_contained"
CROSS_PATH_WITHIN_JUNCTION = _P18 + "cross_path.within_junction_area"

# F.4.9 direct (12.6)
DIRECT_CONNECTING_ROAD = _P17 + "direct.connecting_road_attribute_usage"
DIRECT_LINKED_ROAD = _P17 + "direct.correct_type_linked_road_usage"
DIRECT_FLAT = _P18 + "direct.flat_exits_entries"
DIRECT_SMOOTH = _P17 + "direct.linked_lane_smoothness"
DIRECT_OVERLAP_COVERAGE = _P18 + "direct.overlap_zone_coverage"
DIRECT_OVERLAP_EXCLUSIVE = _P18 + "direct.overlap_zone_exclusivity"
DIRECT_CONNECTIVITY = _P18 + "direct.road_connectivity"
DIRECT_HEADING = _P17 + "direct.road_ramp_heading"
DIRECT_SPLIT_OR_MERGE = _P18 + "direct.split_or_merge"

# F.4.10 elevation_grid (12.11)
GRID_SMOOTH = _P18 + "elevation_grid.entry_exit_smoothness"
GRID_ONLY_ONE = _P18 + "elevation_grid.only_one_elev_grid"
GRID_PERPENDICULAR = _P18 + "elevation_grid.perpendicular_vectors"
GRID_COEFFICIENTS = _P18 + "elevation_grid.polynome_coefficient_values"
GRID_COVERS_BOUNDARY = _P18 + "elevation_grid.valid_for_entire_boundry"

# F.4.11 geometry (12.9)
REFLINE_MEETS_BOUNDARY = _P18 + "geometry.correct_junction_boundry"
REFLINE_ONE_LINE = _P18 + "geometry.only_one_line_element"
REFLINE_REACHES_ALL = _P18 + "geometry.ref_line_definition"

# F.4.12 priority (12.4.1)
PRIORITY_HIGH_AND_LOW = _P18 + "priority.high_and_low_attr"
PRIORITY_NO_SIGNALS = _P17 + "priority.no_signals"

# F.4.13 virtual (12.7)
VIRTUAL_START_END = _P19 + "virtual.connecting_roads_start_end"
VIRTUAL_HEADING = _P19 + "virtual.heading_equal_mainroad"
VIRTUAL_SMOOTH = _P19 + "virtual.linked_lanes_smooth_fit"
VIRTUAL_MAIN_ROAD_ONLY = _P19 + "virtual.main_road_only"
VIRTUAL_NO_CONTROLLERS = _P19 + "virtual.no_controllers"
VIRTUAL_ONE_START_END = _P19 + "virtual.only_one_start_end"
VIRTUAL_CONNECTIONS = _P19 + "virtual.connections.only_virtual_junctions"
VIRTUAL_CROSS_PATH_S_T = "asam.net:xodr:1.8.0:junctions.virtual.crossPath.cross_road_check_s_t"
