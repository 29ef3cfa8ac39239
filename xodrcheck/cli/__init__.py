"""``xodrcheck`` command line: one module per subcommand.

Each subcommand module exposes ``NAME``, ``HELP``, ``add_arguments(parser)`` and ``run(args) -> int``.
Exit codes: 0 no error-level finding, 1 an error-level finding (``--strict``: a warning too), 2 usage or I/O error.
"""

from __future__ import annotations

import argparse
import importlib
import sys

import numpy as np

#: Subcommand modules, in the order ``--help`` lists them.
SUBCOMMANDS = ("info", "sample", "check", "rules", "mesh", "metrics", "snapshot", "diff")

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2


def _modules():
    for name in SUBCOMMANDS:
        try:
            yield importlib.import_module(f"xodrcheck.cli.{name}")
        except ModuleNotFoundError as exc:  # a subcommand not built yet
            if exc.name != f"xodrcheck.cli.{name}":
                raise


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):  # usage errors exit 2 with one clear line (argparse's own behaviour, kept)
        self.print_usage(sys.stderr)
        self.exit(EXIT_USAGE, f"{self.prog}: error: {message}\n")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="xodrcheck", description="Read, check and sample OpenDRIVE (.xodr) files from any tool.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for module in _modules():
        p = sub.add_parser(module.NAME, help=module.HELP, description=module.HELP)
        module.add_arguments(p)
        p.set_defaults(_run=module.run)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        # Damaged numbers (1e308 widths, say) overflow to inf/nan, which the rules report as findings; numpy's
        # floating-point warnings would only repeat that as noise on stderr. IEEE results are the same either way.
        with np.errstate(all="ignore"):
            return int(args._run(args))
    except KeyboardInterrupt:
        print("xodrcheck: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
