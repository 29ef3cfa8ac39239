"""``junctionart generate`` and ``junctionart render``.

Bad input (a parameter out of range, an unreadable control-line file, an unwritable output) gives one line on stderr
and exit code 2, never a traceback, and no output file.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Sequence
from pathlib import Path

from .errors import InputError, JunctionArtError, ParamsError

#: Single maps at least this large (m^2) show a progress bar over the stages.
BIG_MAP_AREA = 4_000_000.0


def _size(text: str) -> tuple[float, float]:
    parts = text.lower().split("x")
    try:
        if len(parts) != 2:
            raise ValueError
        return float(parts[0]), float(parts[1])
    except ValueError:
        raise argparse.ArgumentTypeError(f"--size {text!r}: expected WxH in metres, e.g. 1000x800") from None


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
]


def _add_generate(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "generate",
        help="generate a road network (.xodr)",
        description="Generate an OpenDRIVE road network from automatic or given control lines.",
    )
    p.add_argument(
        "-o",
        "--output",
        default="map.xodr",
        help="output file; with --count, '{seed}' in the name is replaced by each seed",
    )
    p.add_argument("--seed", type=int, default=0, help="random seed (same seed and parameters: identical file)")
    p.add_argument("--count", type=int, default=1, help="generate this many maps, seeds SEED, SEED+1, ...")
    p.add_argument("--size", type=_size, help="map size WxH in metres for automatic control lines")
    p.add_argument("--control-lines", type=Path, help="JSON or GeoJSON control-line file")
    p.add_argument("--version", choices=("1.8", "1.7"), default=None, help="OpenDRIVE version written (default 1.8)")
    p.add_argument("--transitions", help="JSON object (or @file) of MDP transition probabilities")
    p.add_argument("-q", "--quiet", action="store_true", help="no summary line, no progress bar")
    for opt, field, typ, help_ in OPTIONS:
        p.add_argument(opt, dest=field, type=typ, default=None, help=help_, metavar=opt[2:].upper().replace("-", "_"))


def _params(args: argparse.Namespace):
    from .params import Params

    values = {field: getattr(args, field) for _, field, _, _ in OPTIONS if getattr(args, field) is not None}
    if args.size is not None:
        values["width"], values["height"] = args.size
    if args.version is not None:
        values["version"] = args.version
    if args.transitions is not None:
        text = args.transitions
        try:
            if text.startswith("@"):
                text = Path(text[1:]).read_text(encoding="utf-8")
            values["transitions"] = json.loads(text)
        except (OSError, json.JSONDecodeError) as exc:
            raise ParamsError(f"--transitions: cannot read JSON ({exc})") from None
    return Params.create(**values)


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
    folder = Path(out).parent
    if not folder.is_dir():
        raise InputError(f"-o {out}: folder {folder} does not exist")
    seeds = range(args.seed, args.seed + args.count)
    bar = stage_bar = None
    big = lines is None and params.width * params.height >= BIG_MAP_AREA
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
            lay = result.layout
            print(
                f"{path}: {len(lay.roads)} roads, {len(lay.junctions)} junctions, "
                f"{sum(len(j.connections) for j in lay.junctions)} connection lanes, "
                f"{len(lay.repairs)} repairs, {time.perf_counter() - t0:.2f} s"
            )
    if bar is not None:
        bar.close()
    return 0


def _add_render(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("render", help="draw a .xodr file as a plan-view PNG")
    p.add_argument("file", type=Path, help="OpenDRIVE file")
    p.add_argument("-o", "--output", type=Path, required=True, help="PNG to write")
    p.add_argument("--dpi", type=int, default=150)
    p.add_argument("--title", default=None)


def _render(args: argparse.Namespace) -> int:
    from .render import render

    if not args.output.parent.is_dir() and str(args.output.parent):
        raise InputError(f"-o {args.output}: folder {args.output.parent} does not exist")
    if not 10 <= args.dpi <= 1200:
        raise ParamsError(f"--dpi={args.dpi}: must be in [10, 1200]")
    render(args.file, args.output, dpi=args.dpi, title=args.title)
    return 0


def _add_era(sub: argparse._SubParsersAction) -> None:
    from .era import add_arguments

    p = sub.add_parser(
        "era",
        help="expressive range analysis: generate maps, measure intersections, draw figures",
        description="Generate maps until N intersections are collected per run, measure them with "
        "xodrcheck and write legs.csv, maps.csv, PNG figures and report.md (resumable).",
    )
    add_arguments(p)


class _Parser(argparse.ArgumentParser):
    """Usage errors as one line and exit code 2 (``junctionart generate -h`` still shows the full help)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        self.exit(2, f"{self.prog}: error: {message}\n")


def main(argv: Sequence[str] | None = None) -> int:
    parser = _Parser(prog="junctionart", description="Procedural OpenDRIVE road networks.")
    sub = parser.add_subparsers(dest="command", required=True)
    _add_generate(sub)
    _add_render(sub)
    _add_era(sub)
    args = parser.parse_args(argv)
    try:
        if args.command == "generate":
            return _generate(args)
        if args.command == "era":
            from .era import run as _era

            return _era(args)
        return _render(args)
    except JunctionArtError as exc:
        print(f"junctionart: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        print(f"junctionart: error: {exc.filename or ''}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("junctionart: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
