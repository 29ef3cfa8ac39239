"""The checker's rules, one module per family.

Every rule is registered in :mod:`xodrcheck.rules.registry` when its module is imported; :func:`load_rules` imports
them all. A family module that does not exist (yet) is skipped, so a partial tree still imports.

Codes are stable: a letter for the family, then three digits.

========  ==========  =========================================================================================
prefix    category    codes
========  ==========  =========================================================================================
``X``     xml         ``X0xx``-``X8xx`` reader rules (:mod:`.xml`); ``X9xx`` the engine's own (:mod:`.internal`)
``S``     schema      ``S0xx`` XSD validation (:mod:`.schema`)
``R``     reference   ``R0xx`` ids and references (:mod:`.reference`; ``R02x`` other classes: :mod:`.ids`)
``K``     link        ``K0xx`` road-link topology (:mod:`.link_topology`, :mod:`.link_usage`); ``K1xx`` positions at
                      contacts (:mod:`.link`)
``L``     lane        ``L0xx`` lane topology (:mod:`.lane`, :mod:`.lane_attributes`), road marks
                      (:mod:`.lane_marks`); ``L04x`` where traffic can go (:mod:`.reach`); ``L1xx`` lane geometry
``G``     geometry    ``G0xx``-``G8xx`` plan view and profiles (:mod:`.geometry`, :mod:`.elements`), lane shapes
                      (:mod:`.lane_shape`),
                      road types, shapes and country codes (:mod:`.road_attributes`), object outlines of curves
                      (:mod:`.outline_curves`);
                      ``G9xx`` redundant records (:mod:`.records`)
``C``     curvature   ``C0xx`` (:mod:`.curvature`)
``J``     junction    ``J0xx`` junction topology (:mod:`.junction`, :mod:`.junction_connections`), attribute and element
                      usage by junction type (:mod:`.junction_usage`), priorities, virtual junctions and when a junction
                      is needed (:mod:`.junction_roles`), direct junctions, cross paths and boundary roads
                      (:mod:`.junction_members`), boundary, reference line, grid, crossing sections and overlap zones in
                      plan view (:mod:`.junction_area`), entries and exits of an elevation grid
                      (:mod:`.junction_entries`), virtual junctions' joints (:mod:`.junction_virtual`), cross paths'
                      placement (:mod:`.junction_paths`), crossing traffic in direct junctions
                      (:mod:`.junction_direct`); ``J040`` approaches with no way through (:mod:`.reach`); ``J1xx``
                      junction geometry (:mod:`.junction_geometry`)
``O``     overlap     ``O0xx`` (:mod:`.overlap`)
``H``     header      ``H0xx`` header, default regulations, whole-file recommendations (:mod:`.header`)
``B``     object      ``B0xx`` road objects: attributes and lane validity (:mod:`.object_attributes`), outlines and
                      borders (:mod:`.object_outlines`), markings (:mod:`.object_markings`), skeletons
                      (:mod:`.object_skeletons`), repeats (:mod:`.object_repeats`), where outlines and skeletons
                      lie (:mod:`.object_geometry`), surfaces (:mod:`.object_surfaces`)
``T``     signal      ``T0xx`` signals, signal references, boards, controllers (:mod:`.signal`,
                      :mod:`.signal_validity`, :mod:`.signal_gantry`)
``V``     signal-     ``V0xx`` what signal controllers let go together (:mod:`.signal_control`)
          control
``W``     railroad    ``W0xx`` railroads (tracks, switches, stations; :mod:`.railroad`)
``U``     surface     ``U0xx`` road surfaces (CRG, cross-section surfaces; :mod:`.surface`)
========  ==========  =========================================================================================
"""

from __future__ import annotations

import importlib

from xodrcheck.rules.registry import RULES, Rule

#: Rule modules in the order their rules run (cheap, structural families first).
FAMILIES = (
    "internal",
    "xml",
    "schema",
    "reference",
    "ids",
    "link_topology",
    "link_usage",
    "link",
    "lane",
    "lane_attributes",
    "lane_records",
    "lane_links",
    "lane_sections",
    "lane_layers",
    "lane_marks",
    "geometry",
    "elements",
    "road_attributes",
    "outline_curves",
    "object_attributes",
    "object_outlines",
    "object_markings",
    "object_skeletons",
    "object_repeats",
    "object_geometry",
    "object_surfaces",
    "lane_shape",
    "lane_zero_width",
    "lane_layer_width",
    "records",
    "curvature",
    "junction",
    "junction_connections",
    "junction_usage",
    "junction_roles",
    "junction_members",
    "junction_area",
    "junction_entries",
    "junction_virtual",
    "junction_paths",
    "junction_direct",
    "reach",
    "junction_geometry",
    "overlap",
    "header",
    "signal",
    "signal_validity",
    "signal_gantry",
    "signal_control",
    "surface",
    "railroad",
)

_loaded = False


def load_rules() -> dict[str, Rule]:
    """Import every family module and return the registry (code -> rule)."""
    global _loaded
    if not _loaded:
        for family in FAMILIES:
            importlib.import_module(f"{__name__}.{family}")  # a misspelled family raises
        _loaded = True
    return RULES


__all__ = ["FAMILIES", "RULES", "Rule", "load_rules"]
