"""Corrections xodrcheck applies to the official OpenDRIVE 1.8.1 and 1.9.0 XSDs, so that valid files validate.

The official files (``schemas/1.8.1``, ``schemas/1.9.0``) are shipped unchanged. Both releases share defects that make
*every* file using some element invalid, or a constraint that can never fire. S001 validates against corrected copies
(``schemas/1.8.1-corrected``, ``schemas/1.9.0-corrected``), which are the official files with exactly the edits of
:data:`ERRATA` (a comment before ``<xs:schema>`` marks each edited file). ``scripts/schema_errata.py`` writes them;
``tests/xodrcheck/schema/test_schema_errata.py`` checks that the shipped copies are exactly that, and that each
correction lets a valid document through while the defect it guards against is still an error.

Each correction does what the schema's own text evidently meant (the spec section named in :attr:`Erratum.why`),
nothing more. The same defects are also reported by rules with their Annex F UIDs (road.signal: multiBoard, vmsGroup;
road.object: outline ids, borders), whose messages say more than a schema error can.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from importlib import resources

from xodrcheck.findings import XodrError


@dataclass(frozen=True, slots=True)
class Erratum:
    """One correction: in ``file``, ``pattern`` (a regular expression) occurs exactly ``count`` times and is replaced
    by ``replacement``."""

    key: str
    file: str
    pattern: str
    replacement: str
    count: int
    why: str


_ABSTRACT_CHILD = (
    r'[ \t]*<xs:element maxOccurs="1" minOccurs="1" name="_OpenDriveElement" type="_OpenDriveElement"/>\r?\n'
)

ERRATA: tuple[Erratum, ...] = (
    Erratum(
        "multiboard-dynamic",
        "OpenDRIVE_Signal.xsd",
        re.escape("@dynamic = true()"),
        "@dynamic = 'yes'",
        1,
        "The multiBoard assertion of t_road_signals_signal compares @dynamic (t_yesNo, a string: 'yes'/'no') with the "
        "boolean true(): an XPath type error (XPTY0004) on every signal of type multiBoard, valid or not. Corrected to "
        "@dynamic = 'yes' (14.7.3: multi boards shall be dynamic and have static and variable message boards).",
    ),
    Erratum(
        "vmsgroup-abstract-child",
        "OpenDRIVE_Signal.xsd",
        _ABSTRACT_CHILD,
        "",
        1,
        "t_signalGroup_vmsGroup requires a child element literally named <_OpenDriveElement> of the abstract base "
        "type, which no valid file has: every <vmsGroup> fails. The line is removed (14.7.4: a vmsGroup holds "
        "vmsBoardReference elements; _OpenDriveElement is the base every type already extends).",
    ),
    Erratum(
        "regulations-abstract-child",
        "OpenDRIVE_Core.xsd",
        _ABSTRACT_CHILD,
        "",
        3,
        "The same required <_OpenDriveElement> child in t_header_defaultRegulations, t_header_roadRegulation and "
        "t_header_signalRegulation: every <defaultRegulations> fails. The three lines are removed (6.4).",
    ),
    Erratum(
        "outline-id-key",
        "OpenDRIVE_Object.xsd",
        r'<xs:key name="k_road_objects_object_outlines_outlineId">(\s*)'
        r'<xs:selector xpath="road/objects/object/outlines/outline \| road/objects/object/outline"/>(\s*)'
        r'<xs:field xpath="@id"/>(\s*)</xs:key>',
        r'<xs:unique name="k_road_objects_object_outlines_outlineId">\1'
        r'<xs:selector xpath="outlines/outline | outline"/>\2<xs:field xpath="@id"/>\3</xs:unique>',
        1,
        "The key on <object> meant to keep outline ids unique selects road/objects/object/outlines/outline relative "
        "to the <object> itself, which matches nothing: duplicate outline ids pass. Corrected to select the object's "
        "own outlines; xs:unique instead of xs:key because an outline's id is optional (13.2: the id must be unique "
        "within one object).",
    ),
    Erratum(
        "border-outline-keyref",
        "OpenDRIVE_Object.xsd",
        re.escape('<xs:selector xpath="road/objects/object/borders/border"/>'),
        '<xs:selector xpath="borders/border"/>',
        1,
        "The keyref from a border's @outlineId to the object's outlines has the same selector relative to the "
        "<object>: it matches nothing. Corrected to the object's own borders (13.9: outlineId names the outline "
        "the border runs along).",
    ),
    Erratum(
        "border-complete-outline",
        "OpenDRIVE_Object.xsd",
        re.escape("if (@useCompleteOutline) then not(cornerReference)"),
        "if (not(@useCompleteOutline) or @useCompleteOutline = 'true') then not(cornerReference)",
        1,
        "The border assertion tests whether @useCompleteOutline is present, not whether it is 'true' (t_bool is a "
        "string): a border without the attribute (which defaults to true) is required to have corner references, "
        "and one with useCompleteOutline='false' is forbidden to have them; both valid. Corrected to test the value "
        "(13.9: true, the default, forbids cornerReference; false requires at least two).",
    ),
)

#: Official release folder -> folder of its corrected copy (both under the package data ``xodrcheck.schemas``).
CORRECTED: dict[str, str] = {"1.8.1": "1.8.1-corrected", "1.9.0": "1.9.0-corrected"}

MARK = (
    "<!--xodrcheck: corrected copy of the official file: the edits listed in xodrcheck/schema/errata.py "
    "(see NOTICE.md)-->"
)


class ErratumMismatch(XodrError, ValueError):
    """A correction did not find its text as often as expected: the official file is not the one it was made for."""


def correct(name: str, text: str) -> str:
    """``text`` (the official file ``name``) with every erratum for that file applied."""
    edited = False
    for erratum in ERRATA:
        if erratum.file != name:
            continue
        text, n = re.subn(erratum.pattern, erratum.replacement, text)
        if n != erratum.count:
            raise ErratumMismatch(f"{name}: erratum {erratum.key} matched {n} times, expected {erratum.count}")
        edited = True
    if edited:
        at = text.index("<xs:schema")
        text = text[:at] + MARK + text[at:]
    return text


def corrected_files(release: str) -> dict[str, bytes]:
    """File name -> content of the corrected copy of the official ``release`` folder (every ``.xsd`` of it)."""
    folder = resources.files("xodrcheck.schemas").joinpath(release)
    out = {}
    for entry in sorted(folder.iterdir(), key=lambda e: e.name):
        if entry.name.endswith(".xsd"):
            text = entry.read_bytes().decode("utf-8")
            out[entry.name] = correct(entry.name, text).encode("utf-8")
    return out
