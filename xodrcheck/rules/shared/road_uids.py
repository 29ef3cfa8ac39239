"""The Annex F UIDs of the road-level families (``road.geometry``, ``road.elevation``, ``road.superelevation``,
``road.shape``, ``road.type``, ``road.linkage``, road overlaps, ``road.use_cases``, ``road.curve_local``) and of
``header``, ``defaultRegulations`` and ``performance``, named once.

Reader rules (:mod:`xodrcheck.rules.xml`) and check rules alike take them from here, so a UID is spelled in one place.
"""

from __future__ import annotations

_P14 = "asam.net:xodr:1.4.0:"
_P17 = "asam.net:xodr:1.7.0:"
_P18 = "asam.net:xodr:1.8.0:"
_P181 = "asam.net:xodr:1.8.1:"
_P19 = "asam.net:xodr:1.9.0:"

# F.1 defaultRegulations, F.2 header, F.5 performance
DEFAULT_REGULATIONS_ONLY_SPEED_PRIORITY = _P18 + "defaultRegulations.only_speed_priority"
HEADER_CENTERED_COORDS = _P17 + "header.offset.centered_coords"
HEADER_MAX_ONE_PROJ = _P19 + "header.proj.max_one_proj"
AVOID_REDUNDANT_INFO = _P181 + "performance.avoid_redundant_info"

# F.6.1-F.6.4 road length and overlaps
LENGTH_SUM_GEOMETRIES = _P19 + "road.length_sum_geometries"
NO_OVERLAP_OUTSIDE_JUNCTION = _P14 + "road.no_overlap_outside_junction"
NO_OVERLAP_SELF = _P14 + "road.no_overlap_self"
OVERLAP_INSIDE_JUNCTION = _P14 + "road.overlap_inside_junction"

# F.6.9 curve_local (outlines of objects, 1.9)
CURVE_LOCAL_CONTINUOUS = _P19 + "road.curve_local.continuous_curve_local"
CURVE_LOCAL_MIN_AMOUNT = _P19 + "road.curve_local.element_min_amount"
CURVE_LOCAL_LENGTH_MATCH = _P19 + "road.curve_local.length_match"
CURVE_LOCAL_ARC_LENGTH_RANGE = _P19 + "road.curve_local.paramPoly3.arcLength_range"
CURVE_LOCAL_NORMALIZED_RANGE = _P19 + "road.curve_local.paramPoly3.normalized_range"

# F.6.10 elevation
ELEVATION_ORDER = _P14 + "road.elevation.elem_asc_order"
ELEVATION_ALONG_REF_LINE = _P14 + "road.elevation.elev_along_ref_line"

# F.6.11 geometry
GEOMETRY_CONTACT_POINT = _P17 + "road.geometry.contact_point"
GEOMETRY_ORDER = _P14 + "road.geometry.elem_asc_order"
GEOMETRY_ONE_ELEMENT = _P14 + "road.geometry.one_geom_elem_per_spec"
GEOMETRY_ONLY_ONE_REFLINE = _P14 + "road.geometry.only_one_refline"
GEOMETRY_REFLINE_EXISTS = _P14 + "road.geometry.refline_exists"
GEOMETRY_NO_GAPS = _P14 + "road.geometry.refline_no_gaps"
GEOMETRY_NO_KINKS = _P14 + "road.geometry.refline_no_kinks"
GEOMETRY_S_VALUE_SUM = _P19 + "road.geometry.s-value_sum"
ARC_NO_ZERO_CURVATURE = _P19 + "road.geometry.arc.no_zero_curvature"
PARAMPOLY3_ARC_LENGTH_RANGE = _P17 + "road.geometry.paramPoly3.arcLength_range"
PARAMPOLY3_LENGTH_MATCH = _P17 + "road.geometry.paramPoly3.length_match"
PARAMPOLY3_NORMALIZED_RANGE = _P17 + "road.geometry.paramPoly3.normalized_range"
PARAMPOLY3_VALID_PARAMETERS = _P17 + "road.geometry.paramPoly3.valid_parameters"
SPIRAL_CURVATURE_CHANGE = _P19 + "road.geometry.spiral.curvature_change"

# F.6.15 linkage
LINKAGE_BOTH_SIDES = _P19 + "road.linkage.both_sides_consistency"
LINKAGE_JUNCTION_NEEDED = _P14 + "road.linkage.is_junction_needed"
LINKAGE_JUNCTION_ATTRIBUTES = _P17 + "road.linkage.junc_link_attribute_usage"
LINKAGE_ROAD_ATTRIBUTES = _P14 + "road.linkage.road_link_attribute_usage"
LINKAGE_VIRTUAL_ATTRIBUTES = _P17 + "road.linkage.virtjunc_link_attribute_usage"

# F.6.18 shape, F.6.20 superelevation, F.6.21 type, F.6.22 use cases
SHAPE_ORDER = _P14 + "road.shape.elem_asc_order"
SHAPE_T_COVERAGE = _P14 + "road.shape.t_definition_coverage"
SUPERELEVATION_ORDER = _P14 + "road.superelevation.elem_asc_order"
TYPE_NEW_IN_PARENT = _P14 + "road.type.create_new_type_in_parent"
TYPE_ORDER = _P14 + "road.type.elem_asc_order"
TYPE_LANE_MAY_DIFFER = _P14 + "road.type.lane_type_may_differ_from_parent"
TYPE_ALPHA_2 = _P17 + "road.type.only_alpha_2_country_codes"
SHAPES_START_RIGHT = _P19 + "road.use_cases.shape_elements_start_right"
