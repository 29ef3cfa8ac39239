"""Reader rules: what :func:`xodrcheck.reader.read` reports while turning bytes into the model.

``X1xx`` concern the XML itself (category ``xml``); ``X2xx`` concern the OpenDRIVE structure the reader needs to build
the model: elements and attributes that are missing, invalid, unknown or out of order (category ``schema``; the full
XSD validation is a separate, optional step). Every finding names the element, its line and, inside a road or a
junction, that road's or junction's id, and says what the reader did about it (skipped the element, read a value as
absent, used the standard's default).
"""

from __future__ import annotations

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.rules.registry import declare
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared import road_uids as RU

NOT_WELL_FORMED = declare(
    "X101",
    "xml-not-well-formed",
    Category.XML,
    Severity.ERROR,
    """
    The file is not well-formed XML.

    Truncated files, binary data, an empty file, a tag closed twice, an attribute given twice, bytes that do not
    match the declared encoding, nesting deeper than the parser allows: no conforming XML reader accepts them. The
    finding gives the parser's message and line; xodrcheck then builds what a recovering parser can still make of the
    file, so later parts of the map may be missing.

    Passes::

        <OpenDRIVE><header revMajor="1" revMinor="8"/></OpenDRIVE>

    Fails (the file ends inside ``<road>``)::

        <OpenDRIVE><header revMajor="1" revMinor="8"/><road id="1" length="10" junction="-1">
    """,
    basis=Basis.READING,
)

DOCTYPE = declare(
    "X102",
    "xml-doctype",
    Category.XML,
    Severity.ERROR,
    """
    The file has a DOCTYPE; xodrcheck neither loads DTDs nor expands entities.

    OpenDRIVE never needs a DOCTYPE. Entity declarations in one are how "billion laughs" expansion bombs and external
    entities that read local files work, so the reader drops the DOCTYPE before parsing: references to its entities
    are left out (this finding counts them and names the line of the first; they are not reported again as
    ``xml-not-well-formed``) and no file or URL named in it is ever opened. An error when the DOCTYPE declares
    entities, a warning for a bare one. A file with left-out references is not read whole: the commands that turn a
    map into data refuse it.

    Passes::

        <?xml version="1.0"?>
        <OpenDRIVE>...</OpenDRIVE>

    Fails::

        <?xml version="1.0"?>
        <!DOCTYPE OpenDRIVE [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
        <OpenDRIVE><header name="&secret;" revMajor="1" revMinor="6"/></OpenDRIVE>
    """,
    basis=Basis.READING,
)

CONTENT_BEFORE_DECLARATION = declare(
    "X103",
    "xml-content-before-declaration",
    Category.XML,
    Severity.WARNING,
    """
    Something (a comment, blank lines, text) comes before the XML declaration.

    XML allows the declaration only as the very first thing in a file. CARLA and libOpenDRIVE read such files anyway,
    SUMO's netconvert, pyxodr and strict XML parsers reject them. xodrcheck reports it and reads the rest of the file.

    Passes::

        <?xml version="1.0" encoding="UTF-8"?>
        <!-- written by my tool -->
        <OpenDRIVE>...</OpenDRIVE>

    Fails::

        <!-- written by my tool -->
        <?xml version="1.0" encoding="UTF-8"?>
        <OpenDRIVE>...</OpenDRIVE>
    """,
    basis=Basis.READING,
)

ENCODING = declare(
    "X104",
    "xml-encoding-not-utf8",
    Category.XML,
    Severity.WARNING,
    """
    The file is not UTF-8: it is UTF-16/UTF-32, or declares another encoding and uses characters outside ASCII.

    Such a file is valid XML and xodrcheck reads it, but OpenDRIVE files are normally UTF-8 and tools that assume
    UTF-8 will misread or reject it. A file that declares ``ISO-8859-1`` but contains only ASCII is byte for byte UTF-8
    and passes.

    Plausibility: neither XML nor OpenDRIVE requires UTF-8 (the standard names no encoding), so a warning whatever
    the profile.

    Passes::

        <?xml version="1.0" encoding="UTF-8"?>
        <OpenDRIVE><header name="Straße" revMajor="1" revMinor="6"/>...</OpenDRIVE>

    Fails (saved as UTF-16)::

        <?xml version="1.0" encoding="UTF-16"?>
        <OpenDRIVE>...</OpenDRIVE>
    """,
    basis=Basis.PLAUSIBILITY,
)

WRONG_ROOT = declare(
    "X201",
    "not-opendrive",
    Category.SCHEMA,
    Severity.ERROR,
    """
    The root element is not ``<OpenDRIVE>``: this is not an OpenDRIVE file, and nothing else is read.

    Passes::

        <OpenDRIVE><header revMajor="1" revMinor="7"/>...</OpenDRIVE>

    Fails::

        <OpenSCENARIO><FileHeader revMajor="1" revMinor="1"/></OpenSCENARIO>
    """,
    basis=Basis.READING,
)

UNKNOWN_VERSION = declare(
    "X202",
    "unknown-version",
    Category.SCHEMA,
    Severity.WARNING,
    """
    The header's ``revMajor.revMinor`` is not an OpenDRIVE version xodrcheck knows (1.1 to 1.9).

    The file is read as an OpenDRIVE 1.9 file, so whatever the declared version changed may be misunderstood. (A
    version that is missing or not an integer is reported by ``missing-attribute`` or ``invalid-attribute``.)

    Passes::

        <header revMajor="1" revMinor="6"/>

    Fails::

        <header revMajor="2" revMinor="0"/>
    """,
    basis=Basis.READING,
)

MISSING_ELEMENT = declare(
    "X203",
    "missing-element",
    Category.SCHEMA,
    Severity.ERROR,
    """
    An element the model needs is missing. It is one of: ``<header>``, a road's ``<planView>`` or ``<lanes>``, a
    ``<laneSection>`` in ``<lanes>``, a geometry in ``<planView>``, or the centre lane 0 of a lane section.

    The parent is kept (a road without ``<planView>`` has no reference line, a lane section without lane 0 keeps its
    other lanes) so that the rest of the map can still be checked.

    Annex F: a road without ``<lanes>`` breaks ``road.lane_section.lane_sect_req`` (every road has a lane section),
    ``<lanes>`` without ``<laneSection>`` ``road.lane.lane_sect_min_amount``, a lane section without ``<center>``
    ``road.lane.center_elem_definition``, a road without ``<planView>`` or a ``<planView>`` without ``<geometry>``
    ``road.geometry.refline_exists`` (each road has a reference line); a ``<center>`` without lane 0
    ``road.lane.center_lane_singular`` (1.9), a lane section of a 1.9 permanent lane layer without centre lane
    ``road.lane.layer.center_lane_permanent``, a 1.9 road without a permanent lane layer
    ``road.lane.layer.layer_limits``.

    Passes::

        <laneSection s="0"><center><lane id="0" type="none"/></center>...</laneSection>

    Fails::

        <laneSection s="0"><right><lane id="-1" type="driving">...</lane></right></laneSection>
    """,
    uids=(
        U.LANE_SECT_MIN_AMOUNT,
        U.SECTION_REQ,
        U.CENTER_ELEM_DEFINITION,
        U.CENTER_LANE_SINGULAR,
        U.LAYER_CENTER_PERMANENT,
        U.LAYER_LIMITS,
        RU.GEOMETRY_REFLINE_EXISTS,
    ),
    every_version=True,
    basis=Basis.SCHEMA,
)

REPEATED_ELEMENT = declare(
    "X204",
    "repeated-element",
    Category.SCHEMA,
    Severity.ERROR,
    """
    An element that may appear only once appears several times (a second ``<header>``, ``<planView>``, ``<lanes>``,
    road ``<predecessor>``, ``<center>``...). The first one is read, the others are ignored. A second ``<center>``
    in a lane section breaks Annex F ``road.lane.center_elem_definition`` (one centre for each s), a second
    ``<planView>`` in a road ``road.geometry.only_one_refline`` (one reference line per road), a second ``<lanes>`` of
    one lane layer (1.9) ``road.lane.layer.layer_limits``.

    Passes::

        <road id="1" length="10" junction="-1"><planView>...</planView>...</road>

    Fails::

        <road id="1" length="10" junction="-1"><planView>...</planView><planView>...</planView>...</road>
    """,
    uids=(U.CENTER_ELEM_DEFINITION, U.LAYER_LIMITS, RU.GEOMETRY_ONLY_ONE_REFLINE),
    every_version=True,
    basis=Basis.SCHEMA,
)

MISSING_ATTRIBUTE = declare(
    "X205",
    "missing-attribute",
    Category.SCHEMA,
    Severity.ERROR,
    """
    A required attribute is absent. The reader never invents a value for it: the finding says what was done instead
    (the element skipped, the value read as absent, or the standard's documented default used). A ``<laneSection>``
    without ``s`` breaks Annex F ``road.lane.s_attr_value``.

    Passes::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>

    Fails (no ``x``: the geometry is skipped)::

        <geometry s="0" y="0" hdg="0" length="10"><line/></geometry>
    """,
    uids=(U.S_ATTR_VALUE,),
    every_version=True,
    basis=Basis.SCHEMA,
)

INVALID_ATTRIBUTE = declare(
    "X206",
    "invalid-attribute",
    Category.SCHEMA,
    Severity.ERROR,
    """
    An attribute's value is not valid. It is not a number (``"seven"``, ``"1,5"``), not finite (``NaN``, ``INF``),
    negative where the standard requires a value >= 0 (a length, an ``s``), not an integer where one is required (a
    lane id, ``revMinor``), or not one of the values the standard allows (``contactPoint="middle"``).

    Passes::

        <road id="1" length="25.5" junction="-1">

    Fails::

        <road id="1" length="-25.5" junction="-1">
    """,
    basis=Basis.READING,
)

UNKNOWN_GEOMETRY = declare(
    "X207",
    "unknown-geometry",
    Category.SCHEMA,
    Severity.ERROR,
    """
    A ``<geometry>`` has no known shape: none of ``<line>``, ``<arc>``, ``<spiral>``, ``<poly3>``, ``<paramPoly3>``,
    an unknown one (``<clothoid>``, ``<bezier>``), or several. The geometry is skipped, leaving a gap in the
    reference line. Annex F ``road.geometry.one_geom_elem_per_spec``: a geometry holds exactly one element that
    specifies its shape.

    Passes::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><arc curvature="0.01"/></geometry>

    Fails::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><clothoid k0="0" k1="0.01"/></geometry>
    """,
    uids=(RU.GEOMETRY_ONE_ELEMENT,),
    every_version=True,
    basis=Basis.SCHEMA,
)

UNKNOWN_LANE_TYPE = declare(
    "X208",
    "unknown-lane-type",
    Category.SCHEMA,
    Severity.WARNING,
    """
    A lane's ``type`` is not a lane type of any OpenDRIVE version (spelling is compared without regard to case, so
    ``"Driving"`` is read as ``driving``). The lane is kept with type ``unknown``: it is not treated as drivable.

    Passes::

        <lane id="-1" type="driving">

    Fails::

        <lane id="-1" type="carriageway">
    """,
    basis=Basis.SCHEMA,
)

OUT_OF_ORDER = declare(
    "X209",
    "records-out-of-order",
    Category.SCHEMA,
    Severity.ERROR,
    """
    Records that the standard orders by ``s`` come in descending order. These are geometries, elevation,
    superelevation, laneOffset and lane-section starts along the road, or width, border, height, roadMark and speed
    ``sOffset`` values inside a lane. Readers disagree about which record applies where. The records are kept in file
    order. Annex F ``elem_asc_order`` of ``road.geometry``, ``road.elevation``, ``road.superelevation``,
    ``road.lane.width``, ``.border``, ``.height``, ``.road_mark``, ``.speed``, ``road.lanes.lane_offset`` and
    ``road.lane_section`` (``<access>``, ``<material>`` and ``<rule>``: ``lane-records-out-of-order``; road
    ``<type>``: ``road-type-out-of-order``; ``<shape>``: ``shape-out-of-order``).

    Passes::

        <elevation s="0" a="0" b="0" c="0" d="0"/><elevation s="50" a="0" b="0.01" c="0" d="0"/>

    Fails::

        <elevation s="50" a="0" b="0.01" c="0" d="0"/><elevation s="0" a="0" b="0" c="0" d="0"/>
    """,
    uids=(
        U.WIDTH_ORDER,
        U.BORDER_ORDER,
        U.ROAD_MARK_ORDER,
        U.SPEED_ORDER,
        U.HEIGHT_ORDER,
        U.LANE_OFFSET_ORDER,
        U.SECTION_ORDER,
        RU.GEOMETRY_ORDER,
        RU.ELEVATION_ORDER,
        RU.SUPERELEVATION_ORDER,
    ),
    every_version=True,
    basis=Basis.SCHEMA,
)

#: Every reader rule, in code order.
READER_RULES = (
    NOT_WELL_FORMED,
    DOCTYPE,
    CONTENT_BEFORE_DECLARATION,
    ENCODING,
    WRONG_ROOT,
    UNKNOWN_VERSION,
    MISSING_ELEMENT,
    REPEATED_ELEMENT,
    MISSING_ATTRIBUTE,
    INVALID_ATTRIBUTE,
    UNKNOWN_GEOMETRY,
    UNKNOWN_LANE_TYPE,
    OUT_OF_ORDER,
)
