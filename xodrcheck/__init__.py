"""xodrcheck: an independent OpenDRIVE reader and checker.

Point it at any ``.xodr``: ``read(path)`` gives the typed model and what was found while reading; ``check(path)``
runs every rule and gives a :class:`Report` (``.ok``, ``.findings``); ``is_valid(path)`` says yes or no.
"""

from xodrcheck.check import Report, check, is_valid, is_valid_reason
from xodrcheck.findings import Category, Finding, ReadError, Severity, XodrError
from xodrcheck.model import Document, LaneKey

__all__ = [
    "Category",
    "Document",
    "Finding",
    "LaneKey",
    "ReadError",
    "Report",
    "Severity",
    "XodrError",
    "check",
    "is_valid",
    "is_valid_reason",
]
