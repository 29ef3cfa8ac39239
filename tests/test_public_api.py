"""Each public module of both packages declares ``__all__``: every listed name exists, ``from M import *`` gives
exactly those names, and every class or function the module defines without a leading underscore is listed."""

from __future__ import annotations

import importlib
import inspect

import pytest

#: The modules users import (the packages' own names, the checker's library modules, the generator's entry points and
#: its public Hypothesis strategies).
MODULES = [
    "xodrcheck",
    "xodrcheck.support.atomic",
    "xodrcheck.check",
    "xodrcheck.config",
    "xodrcheck.findings",
    "xodrcheck.fix",
    "xodrcheck.mesh.surfaces",
    "xodrcheck.analysis.metrics",
    "xodrcheck.model",
    "xodrcheck.pytest_plugin",
    "xodrcheck.reader",
    "xodrcheck.report",
    "xodrcheck.analysis.sample",
    "xodrcheck.analysis.snapshot",
    "xodrcheck.structures",
    "junctionart",
    "junctionart.cli",
    "junctionart.errors",
    "junctionart.fuzz",
    "junctionart.fuzz.documents",
    "junctionart.fuzz.generator",
    "junctionart.fuzz.mutations",
    "junctionart.fuzz.profiles",
    "junctionart.fuzz.properties",
]

#: Defined without an underscore yet not part of the module's API: the command line's argument types and pytest's
#: hook (pytest finds it by name).
NOT_EXPORTED = {"junctionart.cli": {"Size"}, "xodrcheck.pytest_plugin": {"pytest_addoption"}}


@pytest.mark.parametrize("name", MODULES)
def test_all_names_exist_and_star_import_gives_exactly_them(name: str) -> None:
    module = importlib.import_module(name)
    assert "__all__" in vars(module), f"{name} declares no __all__"
    listed = list(module.__all__)
    assert len(listed) == len(set(listed)), f"{name}.__all__ lists a name twice"
    missing = [n for n in listed if not hasattr(module, n)]
    assert not missing, f"{name}.__all__ lists names it does not have: {missing}"
    namespace: dict[str, object] = {}
    exec(f"from {name} import *", namespace)
    assert set(namespace) - {"__builtins__"} == set(listed)


@pytest.mark.parametrize("name", MODULES)
def test_every_public_class_and_function_is_listed(name: str) -> None:
    module = importlib.import_module(name)
    defined = {
        n
        for n, value in vars(module).items()
        if not n.startswith("_") and (inspect.isclass(value) or inspect.isfunction(value)) and value.__module__ == name
    }
    unlisted = defined - set(module.__all__) - NOT_EXPORTED.get(name, set())
    assert not unlisted, f"{name} defines public names its __all__ does not list: {sorted(unlisted)}"
