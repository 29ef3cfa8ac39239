"""``junctionart intersection``: one intersection from ``--leg`` options or a JSON description; a fork, merge or ramp
from a JSON description with a ``kind`` (:mod:`junctionart.splits.spec`) or a ``--preset``."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .errors import ParamsError
from .intersection import IntersectionSpec, from_dict, load, parse_leg, parse_roundabout, to_dict

if TYPE_CHECKING:
    from .splits.spec import ForkSpec, RampSpec

    SplitSpec = ForkSpec | RampSpec

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
    p.add_argument(
        "--preset",
        metavar="NAME",
        help="a named description: yosemite (the paper's one-way, two-lane road splitting: the left lane curves off "
        "left, the right lane goes straight on), y-fork, merge, exit, entry (ramps); options given as well override it",
    )
    p.add_argument(
        "--junction",
        choices=("direct", "default"),
        default=None,
        help="forks, merges and ramps: a direct junction (OpenDRIVE 1.7+, the default) or a common one with "
        "connecting roads (what CARLA and SUMO read)",
    )
    p.add_argument(
        "--roundabout",
        metavar="RADIUS[:LANES]",
        help="a roundabout instead of a junction, the legs its arms (3 to 6): the outer radius of its circulating "
        "carriageway in metres (mini 9-13, compact 13-20, large 20-35) and 1 or 2 circulating lanes, e.g. 18 or 25:2",
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


def _split(raw: dict[str, Any], args: argparse.Namespace) -> SplitSpec:
    """A fork, merge or ramp description with the options that apply to it on top (the others are refused)."""
    from .splits.spec import from_dict as split_from_dict

    values = dict(raw)
    for key in ("turn_lanes", "u_turns", "split_strategy", "median_width", "roundabout"):
        if getattr(args, key) is not None:
            raise ParamsError(f"--{key.replace('_', '-')} does not apply to a {raw['kind']}")
    for key in ("version", "junction", "traffic_rule", "lane_width", "approach_length"):
        if getattr(args, key) is not None:
            values[key] = getattr(args, key)
    return split_from_dict(values)


def _text(value: str) -> str:
    if value.startswith("@"):
        try:
            return Path(value[1:]).read_text(encoding="utf-8")
        except OSError as exc:
            raise ParamsError(f"--spec {value}: cannot read ({exc.strerror})") from None
    return value


def spec_of(args: argparse.Namespace) -> IntersectionSpec | SplitSpec:
    """The description the options give: ``--preset``, ``--spec`` or ``--leg``, with the junction-wide options on
    top."""
    import json

    from .splits.spec import PRESETS

    given = [name for name, value in (("--preset", args.preset), ("--spec", args.spec), ("--leg", args.leg)) if value]
    if len(given) > 1:
        raise ParamsError(f"give the description once: {' and '.join(given)} were both given")
    if args.preset is not None:
        if args.preset not in PRESETS:
            raise ParamsError(f"--preset {args.preset!r}: choose from {', '.join(PRESETS)}")
        return _split(PRESETS[args.preset], args)
    if args.junction is not None and args.spec is None:
        raise ParamsError("--junction applies to forks, merges and ramps (--preset or a --spec with a kind)")
    if args.spec is not None:
        text = _text(args.spec)
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise ParamsError(f"intersection description: not JSON ({exc})") from None
        if isinstance(data, dict) and "kind" in data:
            return _split(data, args)
        if args.junction is not None:
            raise ParamsError("--junction applies to forks, merges and ramps (a --spec with a kind)")
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
        raise ParamsError("no legs: give --leg HEADING:IN:OUT 3 to 7 times, --spec JSON or --preset NAME")
    for key in ("turn_lanes", "u_turns", "version", *(key for _, key, _, _ in OPTIONS)):
        if getattr(args, key) is not None:
            raw[key] = getattr(args, key)
    if args.roundabout is not None:
        radius, lanes = parse_roundabout(args.roundabout)
        raw["roundabout"] = {"radius": radius, "lanes": lanes}
    return from_dict(raw)


def run(args: argparse.Namespace) -> int:
    from . import write
    from .cli import _check_target
    from .intersection import build

    spec = spec_of(args)
    if args.seed < 0:
        raise ParamsError(f"--seed={args.seed}: must be a non-negative integer")
    _check_target(args.output)
    if not isinstance(spec, IntersectionSpec):
        from .splits.build import build as build_split
        from .splits.plan import of_spec

        path = write(build_split(spec), args.output, spec.version)
        if not args.quiet:
            print(f"{path}: one {of_spec(spec).name}, a {spec.junction} junction")
        return 0
    built = build(spec, args.seed)
    path = write(built.document, args.output, spec.version)
    ring = built.roundabout
    if not args.quiet and ring is not None:
        print(
            f"{path}: one roundabout, {built.legs} arms ({len(spec.legs)} described), outer radius {ring.radius:g} m, "
            f"{ring.lanes} circulating lane(s), {len(built.repairs)} repairs"
        )
    elif not args.quiet:
        print(f"{path}: one junction, {built.legs} legs ({len(spec.legs)} described), {len(built.repairs)} repairs")
    for repair in built.repairs:
        print(f"junctionart: repair: {repair}", file=sys.stderr)
    return 0
