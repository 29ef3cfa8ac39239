"""``junctionart generate`` and ``junctionart render``.

Bad input (a parameter out of range, a map too large to finish in reasonable time, an unreadable control-line file,
an unwritable output) gives one line on stderr and exit code 2, never a traceback, and no output file. Output files
are written atomically (:mod:`xodrcheck.support.atomic`); Ctrl-C (exit 130) and SIGTERM (exit 143) leave no partial
file.
"""

from __future__ import annotations

import argparse
import enum
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, NamedTuple, NoReturn

from .errors import JunctionArtError, OutputError, ParamsError
from .params import size_check

__all__ = ["main"]


#: Single maps at least this large (m^2) show a progress bar over the stages.
BIG_MAP_AREA = 4_000_000.0
#: Single maps from control lines at least this long in total (m) show it too (about the lines of a 2 km x 2 km map).
BIG_MAP_LINES = 25_000.0


class Size(NamedTuple):
    """``--size WxH`` as numbers, and as the user typed it (for messages)."""

    width: float
    height: float
    text: str


def _size(text: str) -> Size:
    parts = text.lower().split("x")
    try:
        if len(parts) != 2:
            raise ValueError
        return Size(float(parts[0]), float(parts[1]), text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"--size {text!r}: expected WxH in metres, e.g. 1000x800") from None


def _default_text(value: Any) -> str:
    """A parameter's default as a user would type it on the command line."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, enum.Enum):
        return str(value.value)
    if isinstance(value, tuple):
        return ",".join(":".join(map(_default_text, v)) if isinstance(v, tuple) else _default_text(v) for v in value)
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


def _floats(n: int):
    def parse(text: str) -> tuple[float, ...]:
        try:
            vals = tuple(float(x) for x in text.split(","))
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r}: expected {n} comma-separated numbers") from None
        if len(vals) != n:
            raise argparse.ArgumentTypeError(f"{text!r}: expected {n} comma-separated numbers, got {len(vals)}")
        return vals

    return parse


def _lane_pairs(text: str) -> tuple[tuple[int, int], ...]:
    try:
        return tuple((int(a), int(b)) for a, b in (item.split(":") for item in text.split(",")))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: expected F:B pairs separated by commas, e.g. 2:2,1:1") from None


def _bool(text: str) -> bool:
    if text.lower() in ("1", "true", "yes", "on"):
        return True
    if text.lower() in ("0", "false", "no", "off"):
        return False
    raise argparse.ArgumentTypeError(f"{text!r}: expected true or false")


#: (option, Params field, type, help)
OPTIONS = [
    ("--lines", "n_lines", int, "number of automatic control lines (default: as many as fit in the height)"),
    ("--line-spacing", "line_spacing", _floats(2), "LOW,HIGH gap between automatic control lines (m)"),
    ("--snap-distance", "snap_distance", float, "merge control points on a line closer than this (m)"),
    ("--min-distance", "min_distance", float, "smallest gap between control points on a line (m)"),
    ("--max-distance", "max_distance", float, "largest gap between control points on a line (m)"),
    ("--gap-scale", "gap_scale", _floats(2), "LOW,HIGH random factor applied to the control-point gap"),
    ("--randomize-lanes", "randomize_lanes", _bool, "true: 0-3 lanes per side drawn; false: one lane each way"),
    ("--lane-distribution", "lane_distribution_side", _floats(4), "P(0),P(1),P(2),P(3) lanes on a side"),
    (
        "--control-line-lane-distribution",
        "lane_distribution_control_lines",
        _floats(4),
        "the same for roads along control lines",
    ),
    (
        "--control-line-lanes",
        "control_line_lanes",
        _lane_pairs,
        "F:B,F:B,... exact forward:backward lanes along automatic control lines 0, 1, ...",
    ),
    ("--lane-width", "lane_width", float, "lane width (m)"),
    ("--median-probability", "median_probability", float, "chance of a median on a two-way road"),
    ("--median-width", "median_width", float, "median width (m)"),
    ("--split-strategy", "split_strategy", str, "split-first, split-last or random"),
    ("--traffic-rule", "traffic_rule", str, "RHT or LHT"),
    ("--curved-roads", "curved_roads", _bool, "bend long connections (true/false)"),
    ("--curve-probability", "curve_probability", float, "chance an eligible connection is bent"),
    ("--turn-lane-probability", "turn_lane_probability", float, "chance of a turn lane before a junction"),
    (
        "--u-turn-probability",
        "u_turn_probability",
        float,
        "chance of a U-turn lane on a leg wide enough for one within the radius bound",
    ),
    ("--min-turn-radius", "min_turn_radius", float, "smallest radius of any lane centre line (m)"),
    (
        "--min-leg-angle",
        "min_leg_angle",
        float,
        "legs of a junction closer than this (degrees) lose a road where the map stays connected (0: keep all)",
    ),
    ("--taper-length", "taper_length", float, "length of lane splits and merges (m)"),
    (
        "--roadside",
        "roadside",
        str,
        "beside the outer driving lanes: urban (kerb 0.2 m + sidewalk 2 m, raised 0.15 m), rural (shoulder 1.5 m +"
        " border 0.5 m) or none; continued round junction corners",
    ),
    (
        "--signals",
        "junction_control",
        str,
        "junction control: auto (drawn by leg count and road class), traffic-lights, stop, yield or none",
    ),
    ("--country", "country", str, "country whose sign catalogue the signs come from"),
    ("--terrain", "terrain", str, "flat, rolling (grades up to 5 %%) or hilly (up to 8 %%); junctions stay planar"),
    (
        "--overpass-probability",
        "overpass_probability",
        float,
        "chance that a crossing of control lines becomes an overpass (5.5 m over the other road, ramps within the "
        "terrain's grade limits) instead of a junction, where both roads are long enough",
    ),
    (
        "--fork-probability",
        "fork_probability",
        float,
        "chance that a road with a long enough straight stretch forks: its outermost lane (or one it gains) splits off "
        "and joins it again further on",
    ),
    (
        "--ramp-probability",
        "ramp_probability",
        float,
        "chance that such a road gains a ramp pair instead: exit lane and off-ramp, link road, on-ramp and entry lane",
    ),
    (
        "--direct-junctions",
        "direct_junctions",
        _bool,
        "forks and ramps meet their road at direct junctions (OpenDRIVE 1.7+); false: default junctions with "
        "connecting roads (CARLA and SUMO read no direct junction)",
    ),
    (
        "--roundabout-probability",
        "roundabout_probability",
        float,
        "chance that a junction of 3 to 6 legs becomes a roundabout (a one-way ring of 1 or 2 lanes, a junction per "
        "arm, splitter islands on two-way arms)",
    ),
]


def _add_generate(p: argparse.ArgumentParser) -> None:
    from .params import MAX_AREA, MAX_SIDE, MIN_SIDE, Params

    defaults = Params()
    p.add_argument(
        "-o",
        "--output",
        default="map.xodr",
        help="output file (default: map.xodr); with --count, '{seed}' in the name is replaced by each seed",
    )
    p.add_argument("--seed", type=int, default=0, help="random seed (default: 0; same seed and parameters: same file)")
    p.add_argument("--count", type=int, default=1, help="generate this many maps, seeds SEED, SEED+1, ... (default: 1)")
    p.add_argument(
        "--size",
        type=_size,
        help=f"map size WxH in metres for automatic control lines (default: "
        f"{defaults.width:g}x{defaults.height:g}; each side {MIN_SIDE:g} to {MAX_SIDE:g}, W*H at most "
        f"{MAX_AREA:.0e} m^2: a 10 km x 10 km map takes 1-2 minutes)",
    )
    p.add_argument("--control-lines", type=Path, help="JSON or GeoJSON control-line file (default: automatic lines)")
    p.add_argument(
        "--version", choices=("1.8", "1.9", "1.7"), default=None, help="OpenDRIVE version written (default: 1.8)"
    )
    p.add_argument(
        "--transitions", help="JSON object (or @file) of MDP transition probabilities (default: the paper's)"
    )
    p.add_argument(
        "--profile",
        choices=("paper", "scenario"),
        default=None,
        help="paper (default): the JunctionArt paper's maps, byte for byte as before; scenario: a test map with "
        "what scenarios need (urban roadside, junction control auto, overpass probability 0.5, fork probability 0.15 "
        "and ramp probability 0.1 on default junctions, roundabout probability 0.25); options given as well override "
        "the profile",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no summary line, no progress bar")
    p.add_argument("-v", "--verbose", action="store_true", help="list each repair the generator made, on stderr")
    for opt, field, typ, help_ in OPTIONS:
        default = getattr(defaults, field)
        if default is not None:
            help_ = f"{help_} (default: {_default_text(default) or 'none'})"
        p.add_argument(opt, dest=field, type=typ, default=None, help=help_, metavar=opt[2:].upper().replace("-", "_"))


def _params(args: argparse.Namespace):
    from .params import Params

    values = {field: getattr(args, field) for _, field, _, _ in OPTIONS if getattr(args, field) is not None}
    if args.size is not None:
        values["width"], values["height"] = args.size.width, args.size.height
        size_check(args.size.width, args.size.height, f"--size {args.size.text}")
    if args.version is not None:
        values["version"] = args.version
    if args.transitions is not None:
        import json  # here: only --transitions reads JSON

        text = args.transitions
        try:
            if text.startswith("@"):
                text = Path(text[1:]).read_text(encoding="utf-8")
            values["transitions"] = json.loads(text)
        except (OSError, json.JSONDecodeError) as exc:
            raise ParamsError(f"--transitions: cannot read JSON ({exc})") from None
    return Params.create(args.profile, **values)


def _generate(args: argparse.Namespace) -> int:
    from . import STAGES, controllines, generate_layout, write

    params = _params(args)
    if args.count < 1:
        raise ParamsError(f"--count={args.count}: must be at least 1")
    if args.seed < 0:
        raise ParamsError(f"--seed={args.seed}: must be a non-negative integer")
    lines = controllines.load(args.control_lines) if args.control_lines is not None else None
    out = str(args.output)
    if args.count > 1 and "{seed}" not in out:
        raise ParamsError(f"-o {out}: with --count > 1 the name must contain '{{seed}}'")
    _check_target(out.replace("{seed}", str(args.seed)))
    seeds = range(args.seed, args.seed + args.count)
    bar = stage_bar = None
    if lines is None:
        big = params.width * params.height >= BIG_MAP_AREA
    else:
        big = sum(line.length for line in lines.lines) >= BIG_MAP_LINES
    if not args.quiet and args.count > 1:
        from tqdm import tqdm

        bar = tqdm(total=args.count, unit="map", file=sys.stderr)
    t0 = time.perf_counter()
    for seed in seeds:
        on_stage = None
        if not args.quiet and args.count == 1 and big:
            from tqdm import tqdm

            stage_bar = tqdm(total=len(STAGES), unit="stage", file=sys.stderr, leave=False)

            def on_stage(name: str, bar_=stage_bar) -> None:
                bar_.set_description(name)
                bar_.update(1)

        result = generate_layout(params, seed, lines, on_stage)
        if stage_bar is not None:
            stage_bar.close()
        path = write(result.document, out.replace("{seed}", str(seed)), params.version)
        if bar is not None:
            bar.update(1)
        elif not args.quiet:
            lay, doc = result.layout, result.document
            print(
                f"{path}: {sum(r.junction == '-1' for r in doc.roads)} roads, {len(doc.junctions)} junctions, "
                f"{sum(len(j.connections) for j in lay.junctions)} connection lanes, "
                f"{len(lay.repairs)} repairs (changes made so every junction fits"
                f"{'' if args.verbose else '; --verbose lists them'}), {time.perf_counter() - t0:.2f} s"
            )
        if args.verbose:
            for repair in result.layout.repairs:
                print(f"junctionart: seed {seed}: repair: {repair}", file=sys.stderr)
        for note in result.notes:  # what the control-line file asked for and did not get: always said
            print(f"junctionart: seed {seed}: {note}", file=sys.stderr)
    if bar is not None:
        bar.close()
    return 0


def _add_render(p: argparse.ArgumentParser) -> None:
    from .render import FORMATS

    p.add_argument("file", type=Path, help="OpenDRIVE file")
    p.add_argument(
        "-o",
        "--output",
        type=Path,
        required=True,
        help=f"image to write; its suffix sets the format ({', '.join(FORMATS)})",
    )
    p.add_argument("--dpi", type=int, default=150, help="resolution of raster formats (default: 150)")
    p.add_argument("--title", default=None, help="title above the map (default: file name, roads and junctions)")


def _render(args: argparse.Namespace) -> int:
    from .render import image_format, render

    image_format(args.output)
    _check_target(args.output)
    if not 10 <= args.dpi <= 1200:
        raise ParamsError(f"--dpi={args.dpi}: must be in [10, 1200]")
    done = render(args.file, args.output, dpi=args.dpi, title=args.title)
    print(
        f"{done.path}: {done.format.upper()} plan view of {args.file}, {done.roads} roads, {done.junctions} junctions"
    )
    return 0


def _check_target(path: str | Path) -> None:
    """Fail before any work when ``path`` cannot be an output file (:func:`xodrcheck.support.atomic.check_target`)."""
    from xodrcheck.support.atomic import OutputError as TargetError
    from xodrcheck.support.atomic import check_target

    try:
        check_target(path)
    except TargetError as exc:
        raise OutputError(str(exc)) from None


def _add_era(p: argparse.ArgumentParser) -> None:
    from .era_cli import add_arguments

    add_arguments(p)


def _add_intersection(p: argparse.ArgumentParser) -> None:
    from .intersection_cli import add_arguments

    add_arguments(p)


def _add_search(p: argparse.ArgumentParser) -> None:
    from .search.cli import add_arguments

    add_arguments(p)


#: Subcommands in the order ``--help`` lists them: (help, description, what adds the arguments). Only the chosen
#: subcommand's arguments are added, so ``junctionart generate`` imports no module of render, era or search.
COMMANDS: dict[str, tuple[str, str | None, Callable[[argparse.ArgumentParser], None]]] = {
    "generate": (
        "generate a road network (.xodr)",
        "Generate an OpenDRIVE road network from automatic or given control lines. No map is thrown away: where a "
        "junction does not fit, the generator repairs the network (merges or enlarges junctions, removes or "
        "straightens roads); the summary line counts these repairs and --verbose lists them.",
        _add_generate,
    ),
    "render": ("draw a .xodr file as a plan view (PNG, JPEG, SVG, PDF or WebP)", None, _add_render),
    "era": (
        "expressive range analysis: generate maps, measure intersections, draw figures",
        "Generate maps until N intersections are collected per run, measure them with xodrcheck and write legs.csv, "
        "maps.csv, PNG figures and report.md (resumable).",
        _add_era,
    ),
    "intersection": (
        "one intersection from explicit legs (headings, lanes in and out, medians, bends), a roundabout of them, or a "
        "fork, merge or ramp",
        "Write a small map with one intersection described leg by leg (--leg) or as JSON (--spec), built by the "
        "generator's intersection stage: the junction and an approach road per leg; with --roundabout RADIUS[:LANES] a "
        "roundabout whose arms the legs are. A fork, merge or ramp instead: --preset (yosemite: the paper's one-way, "
        "two-lane road splitting in two) or --spec with a kind.",
        _add_intersection,
    ),
    "search": (
        "quality-diversity search (MAP-Elites, pyribs) for intersections, forks, ramps or roundabouts across chosen "
        "metrics",
        "Fill an archive of intersections spanning two or three metrics with MAP-Elites (needs the [search] extra); "
        "stop at a budget or when -n elites meet --where. Writes archive.csv, heatmaps, report.md and the elites' "
        ".xodr (resumable).",
        _add_search,
    ),
}


def _chosen(argv: Sequence[str] | None) -> str | None:
    """The subcommand named on the command line (its first word that is not an option), if any."""
    words = sys.argv[1:] if argv is None else argv
    first = next((w for w in words if not w.startswith("-")), None)
    return first if first in COMMANDS else None


class _Parser(argparse.ArgumentParser):
    """Usage errors as one line and exit code 2 (``junctionart generate -h`` still shows the full help)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message}\n")


def main(argv: Sequence[str] | None = None) -> int:
    parser = _Parser(prog="junctionart", description="Procedural OpenDRIVE road networks.")
    sub = parser.add_subparsers(dest="command", required=True)
    chosen = _chosen(argv)
    for name, (help_text, description, add_arguments) in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=description)
        if name == chosen:  # the others parse nothing and are never run
            add_arguments(p)
    args = parser.parse_args(argv)
    from xodrcheck.support.atomic import EXIT_INTERRUPTED, EXIT_TERMINATED, Terminated, signals_raise

    try:
        with signals_raise():
            return _command(args)
    except JunctionArtError as exc:
        print(f"junctionart: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"junctionart: error: {where}{exc.strerror or exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("junctionart: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Terminated:
        print("junctionart: terminated", file=sys.stderr)
        return EXIT_TERMINATED


def _command(args: argparse.Namespace) -> int:
    if args.command == "generate":
        return _generate(args)
    if args.command == "era":
        from .era_cli import run as _era

        return _era(args)
    if args.command == "intersection":
        from .intersection_cli import run as _intersection

        return _intersection(args)
    if args.command == "search":
        from .search.cli import run as _search

        return _search(args)
    return _render(args)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
