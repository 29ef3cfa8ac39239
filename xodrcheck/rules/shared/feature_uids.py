"""The Annex F UIDs of the ``road.signal``, ``road.railroad``, ``road.crg``, ``road.cross_section_surface`` and
``ids`` families, named once (rules and :mod:`xodrcheck.standard.status` take them from here).
"""

from __future__ import annotations

_P14 = "asam.net:xodr:1.4.0:"
_P17 = "asam.net:xodr:1.7.0:"
_P18 = "asam.net:xodr:1.8.0:"
_P19 = "asam.net:xodr:1.9.0:"

# F.3 ids
ID_UNIQUE_IN_CLASS = _P14 + "ids.id_unique_in_class"
ID_UNIQUE_IN_LANE_SECTION = _P14 + "ids.id_unique_in_lane_section"
ONLY_REF_DEFINED_IDS = _P14 + "ids.only_ref_defined_ids"

# F.6.19 signal
SIGNAL_PRIORITY = _P17 + "road.signal.priority"
SIGNAL_TYPE = _P17 + "road.signal.signal_type"
SIGNAL_COUNTRY = _P17 + "road.signal.use_country_code"
MULTI_BOARD_SUB_BOARDS = _P18 + "road.signal.boards.multi_board_have_sub_boards"
MULTI_BOARD_TYPE = _P18 + "road.signal.boards.multi_board_use_correct_type"
MULTI_BOARD_DYNAMIC = _P18 + "road.signal.boards.multi_board_use_dynamic_true"
STATIC_BOARD_SINGLE = _P19 + "road.signal.boards.static_boards_no_single_signal"
STATIC_BOARD_TYPE = _P18 + "road.signal.boards.static_board_use_correct_type"
CONTROLLER_SIGNALS = _P17 + "road.signal.controller.valid_for_signals"
MULTIPLE_DEPENDENCY = _P17 + "road.signal.dependency.multiple_dependency"
GANTRY_SAME = _P19 + "road.signal.gantry.all_variable_boards_same_gantry"
GANTRY_VMS_GROUP = _P19 + "road.signal.gantry.vmsgroup_at_least_one_reference"
REFERENCE_LANE_ORDER = _P17 + "road.signal.reference.from_lower_equal_to"
REFERENCE_LHT = _P17 + "road.signal.reference.left_hand_traffic_lane_ids"
REFERENCE_RHT = _P17 + "road.signal.reference.right_hand_traffic_lane_ids"
REFERENCE_DIRECTION = _P17 + "road.signal.reference.specify_direction"
REFERENCE_SIGNALS_ONLY = _P17 + "road.signal.reference.used_for_signals_only"
SEMANTICS_CATEGORY = _P19 + "road.signal.semantics.no_semantics_without_category"
VALIDITY_LHT = _P17 + "road.signal.validity.left_hand_traffic_lane_ids"
VALIDITY_RHT = _P17 + "road.signal.validity.right_hand_traffic_lane_ids"

# F.6.17 railroad
ONE_RAIL_PER_ROAD = _P17 + "road.railroad.one_rail_per_road"
RAIL_LANE_WIDTH = _P17 + "road.railroad.rail_lane_width_validity"
RAIL_REFLINE_CENTERED = _P17 + "road.railroad.rail_refline_centered"
PLATFORMS_MIN_AMOUNT = _P17 + "road.railroad.platforms.min_amount"
PLATFORMS_MIN_SEGMENTS = _P17 + "road.railroad.platforms.min_segments"
SEGMENTS_PER_PLATFORM = _P17 + "road.railroad.segment.segments_per_platform_min_amount"
ONE_PLATFORM_PER_STATION = _P17 + "road.railroad.stations.one_platform_per_station"
SWITCH_CONNECTION = _P17 + "road.railroad.switch.check_switch_conn"
SINGLE_SWITCH_NO_PARTNER = _P17 + "road.railroad.switch.single_switch_no_partner"

# F.6.7 crg
CRG_ATTACH_FRICTION = _P17 + "road.crg.attach_vs_friction"
CRG_FRICTION_Z = _P17 + "road.crg.friction_no_z_offset_scale"
CRG_H_OFFSET = _P19 + "road.crg.h_offset_only_genuine_global"
CRG_JUNCTION = _P17 + "road.crg.junction"
CRG_NO_OPPOSITE = _P17 + "road.crg.no_opposite"
CRG_ONE_PER_S = _P17 + "road.crg.only_on_per_s"
CRG_ST_OFFSET_GLOBAL = _P17 + "road.crg.s_t_offset_no_global"
CRG_USE_LAST = _P17 + "road.crg.use_last_entry"

# F.6.8 cross_section_surface
SURFACE_HEIGHT = _P18 + "road.cross_section_surface.height"
SURFACE_LANE_DEF = _P18 + "road.cross_section_surface.lane_def_valid"
SURFACE_NO_SHAPE = _P18 + "road.cross_section_surface.no_shape_superelevation"
SURFACE_START_END = _P18 + "road.cross_section_surface.start_end_match_with_refline"
SURFACE_USE_STRIP = _P18 + "road.cross_section_surface.use_strip"
SURFACE_USE_WIDTH = _P18 + "road.cross_section_surface.use_width"
