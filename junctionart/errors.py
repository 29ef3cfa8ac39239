"""The generator's error types: bad parameters, bad input files, unwritable output files."""

from __future__ import annotations

__all__ = ["GenerationError", "InputError", "JunctionArtError", "MissingDependency", "OutputError", "ParamsError"]


class JunctionArtError(Exception):
    """Base of every error junctionart raises on purpose (the CLI turns these into one line and exit code 2)."""


class ParamsError(JunctionArtError, ValueError):
    """A parameter is outside its valid range; the message names the value and the range."""


class InputError(JunctionArtError, ValueError):
    """A control-line file (JSON / GeoJSON) cannot be used; the message names the file and the problem."""


class GenerationError(JunctionArtError):
    """The generator could not finish a map (a bug guard: repairs always converge)."""


class OutputError(JunctionArtError, OSError):
    """An output file cannot be written; the message names the path as given and the cause (never a temporary
    file)."""


class MissingDependency(JunctionArtError, ImportError):
    """An optional dependency a command needs is not installed; the message names the extra that brings it
    (``pip install 'junctionart[figures]'``)."""
