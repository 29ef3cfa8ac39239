"""``xodrcheck`` command line: one module per subcommand.

Each subcommand module exposes ``NAME``, ``HELP``, ``add_arguments(parser)`` and ``run(args) -> int``.
Exit codes (the README's table): 0 ok, 1 findings (``check``: an error-level finding, ``--strict`` a warning too;
the data commands: the output was written but the reader found errors in the file; ``diff``: the map changed),
2 usage or I/O error (nothing written), 3 ``check`` incomplete (a rule did not run to its end and nothing else failed),
130 Ctrl-C, 143 SIGTERM (no partial file either way).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from types import ModuleType

#: Subcommands in the order ``--help`` lists them, with their one-line help (each module's ``HELP``; a test keeps them
#: equal). The table lets ``xodrcheck --help`` and ``xodrcheck COMMAND`` import no subcommand module but the one used.
COMMANDS = {
    "info": "Summarise OpenDRIVE files: version, roads, junctions, lanes, geometry, extent and reader findings.",
    "sample": "Sample every lane's centre line (and borders) at a fixed step, as CSV or GeoJSON.",
    "check": "Check OpenDRIVE files against the conformance rules (exit 1 when an error is found).",
    "fix": "Repair what can be repaired, safely, and check the result (-o OUT or --in-place writes it; else a diff).",
    "rules": "List the checker's rules (code, name, category, severity, basis, summary), or show one rule in full "
    "with the sentences of the standard it enforces.",
    "mesh": "Write the lane surfaces as a 3D mesh (.glb, .obj or .ply), coloured by lane type.",
    "view": "Write the map of a file as one self-contained HTML page (pan, zoom, hover a lane for its name and s).",
    "metrics": "Expressive-range metrics of every junction: FOV, maxCurvature, cornerDeviation, complexity, area, "
    "conflicts.",
    "snapshot": "Write the invariants of a map as JSON: counts of roads, junctions and lanes, legs, lane length, lane "
    "graph hash, bounding box and findings.",
    "diff": "Compare a map with its snapshot (from 'xodrcheck snapshot'): print what changed, exit 1 if anything did.",
    "graph": "Write the lane graph of a map (lanes, links, lane changes) as JSON, Graphviz DOT or GeoJSON.",
    "route": "Find the shortest route between two lanes (ROAD:LANE[:S]): its length, lanes and polyline.",
}
SUBCOMMANDS = tuple(COMMANDS)
EXIT_OK, EXIT_USAGE, EXIT_INCOMPLETE = 0, 2, 3


def command_module(name: str) -> ModuleType:
    """The module of one subcommand (``NAME``, ``HELP``, ``add_arguments``, ``run``)."""
    return importlib.import_module(f"xodrcheck.cli.{name}")


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):  # usage errors exit 2 with one clear line (argparse's own behaviour, kept)
        self.print_usage(sys.stderr)
        self.exit(EXIT_USAGE, f"{self.prog}: error: {message}\n")


def _chosen(argv: list[str] | None) -> str | None:
    """The subcommand named on the command line (its first word that is not an option), if any."""
    words = sys.argv[1:] if argv is None else argv
    first = next((w for w in words if not w.startswith("-")), None)
    return first if first in COMMANDS else None


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The command-line parser. Every subcommand is listed; with ``only``, just that one's module is imported and its
    arguments added (the others parse nothing, and are never run)."""
    parser = _Parser(prog="xodrcheck", description="Read, check and sample OpenDRIVE (.xodr) files from any tool.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for name, help_text in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        if only is None or name == only:
            module = command_module(name)
            module.add_arguments(p)
            p.set_defaults(_run=module.run)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser(only=_chosen(argv) or "")
    args = parser.parse_args(argv)
    from xodrcheck.support.atomic import EXIT_INTERRUPTED, EXIT_TERMINATED, Terminated, signals_raise

    try:
        with signals_raise():
            code = _run(args)
    except KeyboardInterrupt:
        print("xodrcheck: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Terminated:
        print("xodrcheck: terminated", file=sys.stderr)
        return EXIT_TERMINATED
    except BrokenPipeError:
        return EXIT_OK
    return code


def _run(args: argparse.Namespace) -> int:
    import numpy as np  # here: `xodrcheck --help` and usage errors load no numpy

    # Damaged numbers (1e308 widths, say) overflow to inf/nan, which the rules report as findings; numpy's
    # floating-point warnings would only repeat that as noise on stderr. IEEE results are the same either way.
    with np.errstate(all="ignore"):
        return int(args._run(args))


if __name__ == "__main__":
    sys.exit(main())
