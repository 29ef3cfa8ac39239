"""xodrcheck: an independent OpenDRIVE reader and checker.

Point it at any ``.xodr``: ``read(path)`` gives the typed model and what was found while reading.
"""

from xodrcheck.findings import Category, Finding, ReadError, Severity, XodrError
from xodrcheck.model import Document, LaneKey

__all__ = ["Category", "Document", "Finding", "LaneKey", "ReadError", "Severity", "XodrError"]
