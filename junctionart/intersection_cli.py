"""``junctionart intersection``: one intersection from ``--leg`` options or a JSON description."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from .errors import ParamsError
from .intersection import IntersectionSpec, from_dict, load, parse_leg, to_dict

#: (option, key of the JSON description, type, help) of the junction-wide options; each overrides the description's.
OPTIONS: list[tuple[str, str, Any, str]] = [
    ("--traffic-rule", "traffic_rule", str, "RHT or LHT (default: RHT)"),
    ("--split-strategy", "split_strategy", str, "split-first, split-last or random (default: split-first)"),
    ("--lane-width", "lane_width", float, "lane width in metres (default: 3.5)"),
    ("--median-width", "median_width", float, "median width in metres (default: 2)"),
    ("--approach-length", "approach_length", float, "metres from the junction's centre to each road's end (150)"),
]


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--leg",
        action="append",
        default=[],
        metavar="HEADING:IN:OUT[:median][:bend=DEG]",
        help="one leg: heading in degrees (counter-clockwise from east, outwards), lanes in and out (1-3 each), "
        "optionally a median and a bend of the approach road halfway out; give it 3 to 7 times",
    )
    p.add_argument(
        "--spec",
        metavar="JSON|@FILE",
        help='the whole description as JSON (or @file), e.g. {"legs": [{"heading": 0, "in": 2, "out": 2}, ...]}',
    )
    p.add_argument("-o", "--output", type=Path, default=Path("intersection.xodr"), help="output file")
    p.add_argument("--seed", type=int, default=0, help="random seed (split strategy 'random' draws per leg)")
    p.add_argument(
        "--turn-lanes",
        action="store_true",
        default=None,
        help="a turn lane before the junction where the exits allow one",
    )
    p.add_argument("--u-turns", action="store_true", default=None, help="U-turn lanes where one fits the radius bound")
    for opt, key, typ, help_ in OPTIONS:
        p.add_argument(opt, dest=key, type=typ, default=None, help=help_)
    p.add_argument("--version", choices=("1.8", "1.9", "1.7"), default=None, help="OpenDRIVE version (default: 1.8)")
    p.add_argument("-q", "--quiet", action="store_true", help="no summary line")


def spec_of(args: argparse.Namespace) -> IntersectionSpec:
    """The description the options give: ``--spec`` or ``--leg``, with the junction-wide options on top."""
    if args.spec is not None and args.leg:
        raise ParamsError("give the legs either with --leg or in --spec, not both")
    if args.spec is not None:
        text = args.spec
        if text.startswith("@"):
            text = Path(text[1:]).read_text(encoding="utf-8")
        raw = to_dict(load(text))
    elif args.leg:
        legs = [parse_leg(text) for text in args.leg]
        raw = {
            "legs": [
                {"heading": g.heading, "in": g.lanes_in, "out": g.lanes_out, "median": g.median, "bend": g.bend}
                for g in legs
            ]
        }
    else:
        raise ParamsError("no legs: give --leg HEADING:IN:OUT 3 to 7 times, or --spec JSON")
    for key in ("turn_lanes", "u_turns", "version", *(key for _, key, _, _ in OPTIONS)):
        if getattr(args, key) is not None:
            raw[key] = getattr(args, key)
    return from_dict(raw)


def run(args: argparse.Namespace) -> int:
    from . import write
    from .cli import _check_target
    from .intersection import build

    spec = spec_of(args)
    if args.seed < 0:
        raise ParamsError(f"--seed={args.seed}: must be a non-negative integer")
    _check_target(args.output)
    built = build(spec, args.seed)
    path = write(built.document, args.output, spec.version)
    if not args.quiet:
        print(f"{path}: one junction, {built.legs} legs ({len(spec.legs)} described), {len(built.repairs)} repairs")
    for repair in built.repairs:
        print(f"junctionart: repair: {repair}", file=sys.stderr)
    return 0
