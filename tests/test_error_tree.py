"""One error tree per package: every exception class xodrcheck defines derives from ``XodrError``, every one
junctionart defines from ``JunctionArtError`` (so ``except XodrError`` catches whatever the checker raises on purpose,
as ``except shapely.errors.ShapelyError`` does for shapely). Signals are not errors:
``xodrcheck.support.atomic.Terminated`` is a ``BaseException`` like ``KeyboardInterrupt``."""

from __future__ import annotations

import importlib
import inspect
import pkgutil

import pytest

import junctionart
import xodrcheck
from junctionart.errors import JunctionArtError
from xodrcheck.findings import XodrError


def _error_classes(package) -> list[type]:
    found = []
    for info in pkgutil.walk_packages(package.__path__, package.__name__ + "."):
        if info.name.rsplit(".", 1)[-1] == "__main__":
            continue
        module = importlib.import_module(info.name)
        for _, obj in inspect.getmembers(module, inspect.isclass):
            if obj.__module__ == module.__name__ and issubclass(obj, Exception):
                found.append(obj)
    return found


@pytest.mark.parametrize(("package", "base"), [(xodrcheck, XodrError), (junctionart, JunctionArtError)])
def test_every_error_a_package_defines_derives_from_its_base(package, base):
    classes = _error_classes(package)
    assert base in classes  # the walk reached the module that defines the base
    strays = sorted(f"{c.__module__}.{c.__qualname__}" for c in classes if not issubclass(c, base))
    assert strays == []
