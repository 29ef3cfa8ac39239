"""Tolerances, bounds and profiles: the one place they live.

Defaults are here; a project overrides them in ``[tool.xodrcheck]`` of its ``pyproject.toml`` or in an
``xodrcheck.toml`` (same keys at top level), and command-line flags override both. A profile (:data:`PROFILES`) is a
named way of judging: ``default`` gives the standard's verdicts, ``strict`` and ``generator`` every rule's own.
"""

from __future__ import annotations

import dataclasses
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from xodrcheck.findings import XodrError

__all__ = ["PROFILES", "SEVERITY_NAMES", "Config", "ConfigError", "Profile", "Tolerances", "load_config"]


def _toml(text: str) -> dict[str, Any]:
    """A TOML document's table (the parser is imported here: a check without a configuration file needs none)."""
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - Python 3.10
        import tomli as tomllib
    return tomllib.loads(text)


def _tolerance(default: float, unit: str, doc: str, rules: str = ""):
    """A tolerance field with its unit, documentation and the codes of the rules it bounds (space-separated);
    ``xodrcheck rules --tolerances`` lists them, ``xodrcheck rules CODE`` names a rule's tolerances."""
    return field(default=default, metadata={"unit": unit, "doc": doc, "rules": tuple(rules.split())})


@dataclass(frozen=True)
class Tolerances:
    """Every tolerance and bound of the checker, with its unit and meaning (``metadata["unit"]``/``["doc"]``).

    Positions and headings are graded in two steps (:meth:`grade`): a deviation up to the strict value (``position``,
    ``heading``) is no finding, one above the error threshold (``gap``, ``kink``) an error, one between a warning.
    """

    position: float = _tolerance(
        1e-3,
        "m",
        "Positions that should coincide (plan-view joints, linked road ends and lane borders, in plan view and in "
        "height) may be this far apart without a finding; further apart up to `gap` is a warning.",
        rules="G001 G014 G016 K101 K103 K104 L101 L031 L032",
    )
    gap: float = _tolerance(
        0.01,
        "m",
        "A gap or step over this between positions that should coincide is an error: ASAM's checker uses 1 cm "
        "(lane.smoothness.contact_point_no_horizontal_gaps).",
        rules="G001 G014 K101 K103 K104 L101 J031 J032",
    )
    heading: float = _tolerance(
        1e-3,
        "rad",
        "Headings at joints that should be smooth (plan-view joints, road links) may differ this much without a "
        "finding; more, up to `kink`, is a warning (1 mrad: 1 mm off course per metre, as `position`).",
        rules="G002 G014 K102",
    )
    kink: float = _tolerance(
        0.01,
        "rad",
        "A heading change over this at a joint is an error: 0.01 rad (0.57 deg) takes the path off the other road's "
        "course by the 1 cm `gap` within one metre.",
        rules="G002 G014 K102",
    )
    grade_kink: float = _tolerance(
        0.01,
        "rad",
        "Where a road enters a junction's elevation grid without a transition zone, the surface's pitch (atan of its "
        "grade along the road) may change this much between the road and the grid; more is not a smooth entry "
        "(junctions.elevation_grid.entry_exit_smoothness): 0.01 rad (about 1 % of grade), as `kink` in plan view, "
        "takes the surface 1 cm off within one metre.",
        rules="J032",
    )
    length_rel: float = _tolerance(
        1e-3,
        "1",
        "Relative error allowed between a declared length and the computed one (paramPoly3 arc length, road length).",
        rules="G004",
    )
    length_abs: float = _tolerance(
        1e-3,
        "m",
        "Absolute length slack added to `length_rel`; also the s-jump bound.",
        rules="G003 G004 G005 G006 L028",
    )
    min_radius: float = _tolerance(
        5.0, "m", "Smallest curvature radius of lane-0 lines and drivable lane centres.", rules="C001 C002"
    )
    min_section_length: float = _tolerance(
        0.01,
        "m",
        "Lane sections shorter than this are reported (G012); a lane's zero-width stretch shorter than this is "
        "ignored (G015).",
        rules="G012 G015",
    )
    long_zero_width: float = _tolerance(
        1.0,
        "m",
        "A lane of zero width over its whole lane section longer than this is a lane of zero width over a long "
        "distance (G015, road.lane_section.lane_long_zero_width, 1.9).",
        rules="G015",
    )
    object_volume: float = _tolerance(
        0.01,
        "m",
        "Points of an object's outline or skeleton may lie this far outside the object's bounding volume (and a "
        "skeleton point's cross-section this far from it) without a finding: corners written with a few decimals.",
        rules="B018 B034",
    )
    junction_start: float = _tolerance(
        1.0,
        "m",
        "Connection lanes leaving the same incoming lane carry one queue of vehicles until their centre lines are "
        "this far apart: where they meet before (a turn weaving a few cm or dm around the straight-on path as they "
        "part, as in CARLA's Town06) is no crossing, a meeting after they parted is. 1 m: two cars (1.7-2 m wide) on "
        "paths closer than that cannot be side by side. The strict profile uses 5 cm.",
        rules="J101 V001",
    )
    gantry_reach: float = _tolerance(
        1.0,
        "m",
        "A variable message board (its signal's s/t) this far outside a gantry object's bounding box (length x width "
        "around the object's s/t) still counts as mounted on that gantry.",
        rules="T008",
    )
    signal_reach: float = _tolerance(
        50.0,
        "m",
        "A signal on an incoming road this close to the road's end at a junction regulates the junction (a junction "
        "with such signals should state no priorities, junctions.priority.no_signals).",
        rules="J015",
    )
    chord: float = _tolerance(
        0.01,
        "m",
        "Chord error of polylines and meshes (sampling, overlaps, exports).",
        rules="C001 C002 C003 G013 J101 O001 O002 O003 O004",
    )
    max_step: float = _tolerance(
        5.0,
        "m",
        "Longest step between sampled points along a lane, whatever the chord tolerance allows.",
        rules="C001 C002 C003 G013 J101",
    )
    zero_width: float = _tolerance(
        1e-3,
        "m",
        "Lanes narrower than this count as zero-wide (a lane that opens or closes).",
        rules="G010 G011 G015 J005 L010 L013 L031",
    )
    overlap_area: float = _tolerance(
        0.5, "m2", "Plan-view overlap area between roads above which it is reported.", rules="O001 O002 O003 O004"
    )
    clearance: float = _tolerance(
        4.5,
        "m",
        "Surfaces further apart than this in height do not overlap (bridges, tunnels).",
        rules="O001 O003 O004",
    )
    max_turns: float = _tolerance(
        10.0,
        "turns",
        "A lane whose surface covers itself in plan view and whose border turns through more than this many full "
        "circles winds round itself (a damaged curvature or length, not a road): O002 says so, and its self-overlap "
        "and its overlaps with other roads are not computed, whose cost grows with every turn. A spiral ramp of more "
        "storeys needs a larger value.",
        rules="O001 O002 O003 O004 O005",
    )
    centre_distance: float = _tolerance(
        10_000.0,
        "m",
        "Distance from (0, 0) beyond which a map whose extent does not reach the origin counts as not centred "
        "(header.offset.centered_coords): 32-bit floats resolve 1 mm up to about 8 km, 2 mm up to 16 km.",
        rules="H001",
    )
    rail_vehicle_min_width: float = _tolerance(
        2.2,
        "m",
        "Narrowest rail-bound vehicle a rail or tram lane must hold (road.railroad.rail_lane_width_validity): the file "
        "names no vehicle, so this is assumed. 2.2 m is the width of the Tatra KT4 tram (standard and metre gauge), "
        "among the narrowest rail-bound vehicles in service (2,200 mm, built for 1,435 and 1,000 mm gauge); most trams "
        "are 2.3-2.65 m wide, main-line coaches about 2.8-3.2 m. Raise it to the vehicles your map is for.",
        rules="W005",
    )
    time_budget: float = _tolerance(
        0.0,
        "s",
        "Wall-clock bound on checking one file; 0 (the default): none, every rule runs to its end, so the verdict "
        "never depends on the machine's speed. With a bound, rules past it stop and report X901 (an error: the check "
        "is incomplete, exit code 3).",
        rules="X901",
    )
    max_samples_per_section: int = _tolerance(
        200_000,
        "1",
        "Most s samples one lane section gets per sampling stage; a longer section is sampled with longer steps "
        "(G013 says so), so time and memory stay bounded.",
        rules="G013",
    )
    max_file_bytes: int = _tolerance(512 * 1024 * 1024, "B", "Files larger than this are refused with a clear error.")

    max_output_points: int = _tolerance(
        10_000_000,
        "1",
        "Most points `xodrcheck sample` writes and most vertices `xodrcheck mesh` builds (10 million: about 0.7 GB of "
        "CSV); a step or chord needing more is refused (exit 2) before anything is written.",
    )

    def grade(self, deviation: float, kind: str = "position"):
        """The severity of a deviation from a joint that should be exact: ``None`` up to the strict value
        (``position`` or ``heading``, by ``kind``), an error above the error threshold (``gap`` or ``kink``), a
        warning between. ``None`` for NaN."""
        from xodrcheck.findings import Severity

        strict, error = (self.position, self.gap) if kind == "position" else (self.heading, self.kink)
        if not deviation > strict:
            return None
        return Severity.ERROR if deviation > error else Severity.WARNING


@dataclass(frozen=True)
class Profile:
    """A named way of judging a file: tolerance values, and whether the standard's words bound the severities.

    With ``capped`` (the ``default`` profile) a finding is at most what the standard's words make it: one enforcing an
    Annex F rule worded "should" is at most a warning, "may" at most an info, and a ``plausibility`` finding (the
    checker's own judgement) at most a warning; "shall" rules, the schema and what cannot be read keep the rule's
    severity. Without it every rule gives the severity it declares.
    """

    name: str
    #: What the profile is for, in a sentence or two (``--help``, ``xodrcheck rules --tolerances``).
    doc: str
    #: Tolerance name -> value, over the defaults (the configured tolerances and ``--tolerance`` come on top).
    tolerances: tuple[tuple[str, float], ...] = ()
    #: Bound severities by the standard's words (see above).
    capped: bool = True

    def tolerance_values(self, base: Tolerances | None = None) -> Tolerances:
        """``base`` (the defaults) with this profile's values."""
        return _tolerances_from(dict(self.tolerances), base or Tolerances())


#: The named profiles (``--profile``, key ``profile``, ``Config(profile=...)``).
PROFILES: dict[str, Profile] = {
    p.name: p
    for p in (
        Profile(
            "default",
            "the standard: errors only where an Annex F rule worded 'shall', the schema of the file's version or "
            "the reading of the file is violated; 'should' rules and the checker's own plausibility checks (minimum "
            "radius, the JunctionArt paper's junction rules, ...) give warnings, 'may' rules infos",
        ),
        Profile(
            "strict",
            "every rule at the severity it declares, plausibility checks as errors too, and deviations over the "
            "strict values (1 mm, 1 mrad; 5 cm where connection lanes part) errors",
            (("gap", Tolerances.position), ("kink", Tolerances.heading), ("junction_start", 0.05)),
            capped=False,
        ),
        Profile(
            "generator",
            "the invariants junctionart guarantees for the maps it writes: every rule at the severity it declares "
            "(no crossing or merging connection lanes of one road, the minimum radius, ... are errors) with the "
            "default tolerances; junctionart's own checks and tests use it",
            capped=False,
        ),
    )
}

#: ``Config.tolerances`` when none are given: the profile's values are used.
_PROFILE_TOLERANCES = Tolerances()


@dataclass(frozen=True)
class Config:
    """The checker's configuration: profile, tolerances, rule selection, strictness and what a report shows.

    ``profile`` names one of :data:`PROFILES` (``default``: the standard's verdicts); ``tolerances`` default to that
    profile's values, so ``check(path, Config(profile="strict"))`` is ``--profile strict``.
    """

    tolerances: Tolerances = _PROFILE_TOLERANCES
    select: tuple[str, ...] = ()  # rule codes or categories; empty: all
    ignore: tuple[str, ...] = ()
    strict: bool = False  # warnings fail too
    #: Least severity a report shows (``info``, ``warning``, ``error``); ``None``: the format's default (text and
    #: github: warning; json, sarif, junit, xqar: info). Findings not shown still count for the exit code.
    min_severity: str | None = None
    profile: str = "default"

    def __post_init__(self) -> None:
        if self.profile not in PROFILES:
            raise ConfigError(f"unknown profile {self.profile!r}; known: {', '.join(PROFILES)}")
        if self.tolerances is _PROFILE_TOLERANCES and PROFILES[self.profile].tolerances:
            object.__setattr__(self, "tolerances", PROFILES[self.profile].tolerance_values())

    @property
    def profile_spec(self) -> Profile:
        """The :class:`Profile` named by :attr:`profile`."""
        return PROFILES[self.profile]


class ConfigError(XodrError, ValueError):
    """A configuration value is unknown or out of range."""


def _tolerances_from(mapping: dict, base: Tolerances) -> Tolerances:
    known = {f.name: f for f in dataclasses.fields(Tolerances)}
    values: dict[str, Any] = {}
    for key, value in mapping.items():
        name = key.replace("-", "_")
        if name not in known:
            raise ConfigError(f"unknown tolerance {key!r}; known: {', '.join(sorted(known))}")
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise ConfigError(f"tolerance {key!r} must be a number, got {value!r}") from None
        if not math.isfinite(number) or number < 0:
            raise ConfigError(f"tolerance {key!r} must be a finite number >= 0, got {value!r}")
        values[name] = int(number) if known[name].type in (int, "int") else number
    return dataclasses.replace(base, **values)


def load_config(start: Path | None = None, overrides: dict | None = None, profile: str | None = None) -> Config:
    """Read ``xodrcheck.toml`` or ``[tool.xodrcheck]`` of the nearest ``pyproject.toml`` from ``start`` upwards,
    then apply ``overrides`` (tolerance name -> value, e.g. from flags). The ``profile`` is the argument, else the
    file's ``profile`` key, else ``default`` (see :data:`PROFILES`); tolerances come from the defaults, then the
    profile's values, then the file's ``tolerances`` table, then ``overrides``."""
    table: dict = {}
    here = (start or Path.cwd()).resolve()
    for folder in (here, *here.parents):
        own = folder / "xodrcheck.toml"
        if own.is_file():
            table = _toml(own.read_text(encoding="utf-8"))
            break
        pyproject = folder / "pyproject.toml"
        if pyproject.is_file():
            data = _toml(pyproject.read_text(encoding="utf-8"))
            if "xodrcheck" in data.get("tool", {}):
                table = data["tool"]["xodrcheck"]
                break
    name = profile if profile is not None else table.get("profile", "default")
    if not isinstance(name, str) or name not in PROFILES:
        raise ConfigError(f"unknown profile {name!r}; known: {', '.join(PROFILES)}")
    tolerances = _tolerances_from(table.get("tolerances", {}), PROFILES[name].tolerance_values())
    if overrides:
        tolerances = _tolerances_from(overrides, tolerances)
    return Config(
        tolerances=tolerances,
        select=tuple(table.get("select", ())),
        ignore=tuple(table.get("ignore", ())),
        strict=bool(table.get("strict", False)),
        min_severity=_severity_name(table.get("min_severity")),
        profile=name,
    )


SEVERITY_NAMES = ("info", "warning", "error")


def _severity_name(value) -> str | None:
    if value is None:
        return None
    if not isinstance(value, str) or value.strip().lower() not in SEVERITY_NAMES:
        raise ConfigError(f"min_severity must be one of {', '.join(SEVERITY_NAMES)}, got {value!r}")
    return value.strip().lower()
