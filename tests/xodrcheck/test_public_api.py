"""The package's public names: each one in ``__all__`` resolves (lazily) to the object its module defines, and the
README's three-line use works on a real file."""

from __future__ import annotations

import importlib

import pytest

import xodrcheck

#: Every public name of the package and the module that defines it (the documented home users may import it from).
HOMES = {
    "Category": "xodrcheck.findings",
    "Config": "xodrcheck.config",
    "ConfigError": "xodrcheck.config",
    "Document": "xodrcheck.model",
    "Finding": "xodrcheck.findings",
    "FixResult": "xodrcheck.fix.result",
    "LaneKey": "xodrcheck.model",
    "OutputError": "xodrcheck.support.atomic",
    "ReadError": "xodrcheck.findings",
    "ReadResult": "xodrcheck.reader",
    "Report": "xodrcheck.check",
    "Severity": "xodrcheck.findings",
    "Tolerances": "xodrcheck.config",
    "XodrError": "xodrcheck.findings",
    "check": "xodrcheck.check",
    "fix": "xodrcheck.fix.result",
    "is_valid": "xodrcheck.check",
    "is_valid_reason": "xodrcheck.check",
    "read": "xodrcheck.reader",
}


@pytest.mark.parametrize("name", xodrcheck.__all__)
def test_every_public_name_resolves_to_its_module_object(name):
    value = getattr(xodrcheck, name)
    module = HOMES[name]
    importlib.import_module("xodrcheck.check")  # binds the package attribute 'check' to the submodule, then...
    importlib.import_module("xodrcheck.fix.driver")  # (and 'fix' to the sub-package)
    assert getattr(importlib.import_module(module), name) is value
    assert callable(xodrcheck.check) and callable(xodrcheck.fix)  # ...the functions are still what it names


def test_all_lists_the_lazy_names():
    assert sorted(xodrcheck.__all__) == sorted(HOMES)
    offered = {n for n in dir(xodrcheck) if not n.startswith("_")}
    own = {n for n in offered if getattr(getattr(xodrcheck, n), "__module__", "").startswith("xodrcheck")}
    assert own == set(HOMES)  # every name the package offers from its own modules is listed, and only those


def test_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'chek'"):
        xodrcheck.chek  # noqa: B018


def test_read_check_and_is_valid_on_a_file(tmp_path):
    path = tmp_path / "bad.xodr"
    path.write_text('<?xml version="1.0"?>\n<OpenDRIVE><header revMajor="1" revMinor="6"/></OpenDRIVE>\n')
    result = xodrcheck.read(str(path))
    assert result.document is not None and len(result.document.roads) == 0
    report = xodrcheck.check(str(path))
    assert report.ok is xodrcheck.is_valid(str(path))
    assert isinstance(xodrcheck.is_valid_reason(str(path)), str)
    with pytest.raises(xodrcheck.XodrError):
        xodrcheck.read(str(tmp_path / "missing.xodr"))
