"""The folder of a package's data files (the schemas, the Annex F table), without importlib.resources' readers when
the package is a folder on disk, as an installed or editable package is: ``importlib.resources.files`` imports
``zipfile`` and its readers, a few milliseconds of every start-up. A package elsewhere (inside a zip archive) still
goes through importlib.resources."""

from __future__ import annotations

import importlib
import os
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from importlib.abc import Traversable


def folder(package: str) -> Path | Traversable:
    """The data folder of ``package`` (a :class:`~pathlib.Path` when it is on disk)."""
    module = importlib.import_module(package)
    for location in getattr(module, "__path__", ()):
        if os.path.isdir(location):
            return Path(location)
    from importlib import resources

    return resources.files(package)
