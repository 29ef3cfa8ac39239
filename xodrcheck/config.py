"""Tolerances and bounds: the one place they live.

Defaults are here; a project overrides them in ``[tool.xodrcheck]`` of its ``pyproject.toml`` or in an
``xodrcheck.toml`` (same keys at top level), and command-line flags override both.
"""

from __future__ import annotations

import dataclasses
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib  # type: ignore[no-redef]


@dataclass(frozen=True)
class Tolerances:
    #: Largest gap (m) between positions that should coincide (planView joints, road links, lane borders at links).
    position: float = 1e-3
    #: Largest heading difference (rad) at joints that should be smooth.
    heading: float = 1e-3
    #: Relative error allowed between a declared length and the computed one (paramPoly3 arc length, road length).
    length_rel: float = 1e-3
    #: Absolute length slack (m) added to ``length_rel``.
    length_abs: float = 1e-3
    #: Smallest curvature radius (m) of reference lines and driving-lane centres.
    min_radius: float = 5.0
    #: Lane sections shorter than this (m) are reported as degenerate.
    min_section_length: float = 0.01
    #: Connection lanes of one incoming road may run together this far (m) from where they start before they part.
    junction_start: float = 0.05
    #: Chord error (m) for polylines and meshes.
    chord: float = 0.01
    #: Longest step (m) between sampled points along a lane, whatever the chord tolerance allows.
    max_step: float = 5.0
    #: Smallest lane width (m) treated as non-zero (a lane narrower than this "starts or ends at zero width").
    zero_width: float = 1e-3
    #: Plan-view overlap area (m^2) between roads above which an overlap is reported.
    overlap_area: float = 0.5
    #: Vertical clearance (m): surfaces further apart than this in z do not overlap (bridges).
    clearance: float = 4.5
    #: Distance (m) from (0, 0) beyond which a map whose extent does not reach the origin counts as not centred
    #: (``header.offset.centered_coords``): 32-bit floats resolve 1 mm up to about 8 km, 2 mm up to 16 km.
    centre_distance: float = 10_000.0
    #: Wall-clock bound (s) on checking one file; 0 (the default): none, every rule runs to its end, so the verdict
    #: never depends on the machine's speed. With a bound, rules past it stop and report X901 (an error: the check is
    #: incomplete, exit code 3).
    time_budget: float = 0.0
    #: Most ``s`` samples one lane section gets per sampling stage (checker grid, mesh, info). A longer section (a road
    #: of 1e9 m) is sampled with proportionally longer steps, so time and memory stay bounded; rule G013 reports it.
    max_samples_per_section: int = 200_000
    #: Files larger than this many bytes are refused with a clear error.
    max_file_bytes: int = 512 * 1024 * 1024
    #: Most points ``xodrcheck sample`` writes and most vertices ``xodrcheck mesh`` builds (10 million: about 0.7 GB
    #: of CSV); a step or chord needing more is refused (exit 2) before anything is written.
    max_output_points: int = 10_000_000


@dataclass(frozen=True)
class Config:
    tolerances: Tolerances = field(default_factory=Tolerances)
    select: tuple[str, ...] = ()  # rule codes or categories; empty: all
    ignore: tuple[str, ...] = ()
    strict: bool = False  # warnings fail too


class ConfigError(ValueError):
    """A configuration value is unknown or out of range."""


def _tolerances_from(mapping: dict, base: Tolerances) -> Tolerances:
    known = {f.name: f for f in dataclasses.fields(Tolerances)}
    values = {}
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


def load_config(start: Path | None = None, overrides: dict | None = None) -> Config:
    """Read ``xodrcheck.toml`` or ``[tool.xodrcheck]`` of the nearest ``pyproject.toml`` from ``start`` upwards,
    then apply ``overrides`` (tolerance name -> value, e.g. from flags)."""
    table: dict = {}
    here = (start or Path.cwd()).resolve()
    for folder in (here, *here.parents):
        own = folder / "xodrcheck.toml"
        if own.is_file():
            table = tomllib.loads(own.read_text(encoding="utf-8"))
            break
        pyproject = folder / "pyproject.toml"
        if pyproject.is_file():
            data = tomllib.loads(pyproject.read_text(encoding="utf-8"))
            if "xodrcheck" in data.get("tool", {}):
                table = data["tool"]["xodrcheck"]
                break
    tolerances = _tolerances_from(table.get("tolerances", {}), Tolerances())
    if overrides:
        tolerances = _tolerances_from(overrides, tolerances)
    return Config(
        tolerances=tolerances,
        select=tuple(table.get("select", ())),
        ignore=tuple(table.get("ignore", ())),
        strict=bool(table.get("strict", False)),
    )
