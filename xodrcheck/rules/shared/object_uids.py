"""The Annex F UIDs of road objects (F.6.5 ``road.corner_local``, F.6.6 ``road.corner_road``, F.6.16
``road.object``), named once for the object rules (``B0xx``)."""

from __future__ import annotations

_P17 = "asam.net:xodr:1.7.0:"
_P18 = "asam.net:xodr:1.8.0:"
_P182 = "asam.net:xodr:1.8.2:"
_P19 = "asam.net:xodr:1.9.0:"
_P1X = "asam.net:xodr:1.x.0:"

# F.6.5 corner_local, F.6.6 corner_road (13.2.1, 13.2.2)
LOCAL_MIN_AMOUNT = _P17 + "road.corner_local.element_min_amount"
LOCAL_FIRST_ID_ZERO = _P19 + "road.corner_local.first_id_zero"
LOCAL_ID_WITH_MARKINGS = _P19 + "road.corner_local.mandatory_id_with_markings"
LOCAL_NO_MIXING = _P1X + "road.corner_local.no_mixing_road_local"
LOCAL_SEQUENTIAL_IDS = _P19 + "road.corner_local.sequential_id_values"
ROAD_LOCAL_EXCLUSIVITY = _P19 + "road.corner_road.corner_road_local_exclusivity"
ROAD_MIN_AMOUNT = _P17 + "road.corner_road.element_min_amount"
ROAD_FIRST_ID_ZERO = _P19 + "road.corner_road.first_id_zero"
ROAD_ID_WITH_MARKINGS = _P19 + "road.corner_road.mandatory_id_with_markings"
ROAD_SEQUENTIAL_IDS = _P19 + "road.corner_road.sequential_id_values"

# F.6.16.1-4 object (13.1)
CIRCULAR_VS_ANGULAR = _P17 + "road.object.circular_vs_angular"
ORIENTATION = _P17 + "road.object.orientation"
S_T_COORDS = _P17 + "road.object.s_t_coords"
TYPE_ATTR = _P17 + "road.object.type_attr"

# F.6.16.5 borders (13.9), F.6.16.6 bridges (13.12), F.6.16.15 tunnels (13.11)
BORDERS_DIFFERENT_OUTLINE_IDS = _P19 + "road.object.borders.different_outlineids"
BORDERS_COMPLETE_OUTLINE = _P17 + "road.object.borders.useCompleteOutline_true"
BRIDGES_DEFINE_TYPE = _P17 + "road.object.bridges.define_type"
BRIDGES_FROM_TO = _P17 + "road.object.bridges.from_lower_equal_to"
BRIDGES_TYPE = _P17 + "road.object.bridges.type_definition"
TUNNELS_FROM_TO = _P17 + "road.object.tunnels.from_lower_equal_to"
TUNNELS_TYPE = _P17 + "road.object.tunnels.type_definition"

# F.6.16.7 marking, F.6.16.9 object_marking (13.8)
MARKING_COLOUR = _P17 + "road.object.marking.colour"
MARKING_ON_OUTLINE = _P19 + "road.object.marking.complete_or_partial_on_outline"
MARKINGS_WITH_OUTLINE = _P19 + "road.object.marking.markings_with_outline"
MARKINGS_WITHOUT_OUTLINE = _P19 + "road.object.marking.markings_without_outline"
NO_REFERENCE_WITHOUT_OUTLINE = _P17 + "road.object.marking.no_cornerreference_if_no_outline"
SIDE_WITHOUT_OUTLINE = _P17 + "road.object.marking.no_outline_side_attr"
MARKING_REFERENCE_COUNT = _P17 + "road.object.marking.outline_corner_reference_count"
OBJECT_MARKING_COLOUR = _P182 + "road.object.object_marking.colour"
ENCLOSED_OUTLINE_MARKING = _P182 + "road.object.object_marking.enclosed_outline_marking"
INCLUDE_POINTS_BETWEEN = _P182 + "road.object.object_marking.include_points_between_cornerReferences"
KEEP_ID_ORDERED = _P182 + "road.object.object_marking.keep_id_ordered"
OBJECT_MARKING_REFERENCE_COUNT = _P182 + "road.object.object_marking.outline_corner_reference_count"

# F.6.16.8 material (13.5)
MATERIALS_MAY_DIFFER = _P17 + "road.object.material.materials_may_differ"

# F.6.16.10 outline (13.2)
EXACTLY_ONE_OUTER = _P19 + "road.object.outline.exactly_one_outer"
INNER_TOUCHES_OUTER = _P19 + "road.object.outline.inner_outline_touches_outer"
OUTLINE_FOLLOWED_BY_CORNER = _P17 + "road.object.outline.outline_followed_by_corner"
OUTLINE_INSIDE_BOX = _P17 + "road.object.outline.points_inside_box"

# F.6.16.11 reference (13.10)
REFERENCE_FROM_TO = _P17 + "road.object.reference.from_lower_equal_to"

# F.6.16.12 repeating (13.4)
REPEAT_SIZE_WITH_SHAPE = _P19 + "road.object.repeating.attributes_with_outline_skeleton"
REPEAT_WIDTH_WITH_RADIUS = _P19 + "road.object.repeating.no_widthstart_end_with_radius"
REPEAT_OUTLINE_LOCAL = _P19 + "road.object.repeating.outline_use_cornerlocal"
REPEAT_VALID_S_LENGTH = _P19 + "road.object.repeating.valid_s_length"

# F.6.16.13 skeleton (13.3)
SKELETON_BOUNDARY_INSIDE_BOX = _P19 + "road.object.skeleton.points_boundary_inside_box"
SKELETON_INSIDE_BOX = _P18 + "road.object.skeleton.points_inside_box"
SKELETON_POINTS_REQUIREMENTS = _P18 + "road.object.skeleton.points_requirements"
SKELETON_FOLLOWED_BY_VERTEX = _P18 + "road.object.skeleton.polyline_followed_by_vertex"
SKELETON_RADIUS_OR_WIDTH_LENGTH = _P18 + "road.object.skeleton.use_radius_or_width_length"
VERTEX_LOCAL_MIN_AMOUNT = _P18 + "road.object.skeleton.vertex_local.element_min_amount"
VERTEX_LOCAL_INTERPOLATION = _P18 + "road.object.skeleton.vertex_local.linear_interpolation"
VERTEX_LOCAL_NO_MIXING = _P19 + "road.object.skeleton.vertex_local.no_mixing_road_local"
VERTEX_LOCAL_SIZE = _P18 + "road.object.skeleton.vertex_local.vertex_local_elements"
VERTEX_ROAD_MIN_AMOUNT = _P18 + "road.object.skeleton.vertex_road.element_min_amount"
VERTEX_ROAD_INTERPOLATION = _P19 + "road.object.skeleton.vertex_road.linear_interpolation"
VERTEX_ROAD_SIZE = _P18 + "road.object.skeleton.vertex_road.no_radius_with_width_length"
VERTEX_ROAD_NO_MIXING = _P18 + "road.object.skeleton.vertex_road.polyline_elements"

# F.6.16.14 surface (13.13)
SURFACE_SKEWED_CRG = _P19 + "road.object.surface.avoid_skewed_crg_surfacees"
SURFACE_ROAD_HEIGHT = _P17 + "road.object.surface.calculate_road_height"
SURFACE_HIDE_ROAD_CRG = _P17 + "road.object.surface.crg_hidden_on_object_overlap"
SURFACE_LOCAL_COORDINATES = _P17 + "road.object.surface.identical_local_coordinates"
SURFACE_NO_BOX_OVERLAP = _P17 + "road.object.surface.no_bounding_box_overlap"
SURFACE_REFERENCE_ON_OVERLAP = _P17 + "road.object.surface.object_reference_on_overlap"
SURFACE_ANGULAR_ONLY = _P17 + "road.object.surface.only_for_angular_boxes"
SURFACE_ONE_CRG = _P17 + "road.object.surface.only_one_crg_file"
SURFACE_DISCRETE_REPEAT = _P17 + "road.object.surface.repeat_discretely_not_continously"

# F.6.16.16 validty (13.6)
VALIDITY_PARENT_ORIENTATION = _P17 + "road.object.validty.check_parent_orientation"
VALIDITY_FROM_TO = _P17 + "road.object.validty.from_lower_equal_to"
VALIDITY_LHT = _P17 + "road.object.validty.left_hand_traffic_lane_ids"
VALIDITY_RHT = _P17 + "road.object.validty.right_hand_traffic_lane_ids"
