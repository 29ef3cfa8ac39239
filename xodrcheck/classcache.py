"""Dataclasses whose generated methods come from cached byte code.

Creating a dataclass compiles the source of each method it generates (``__init__``, ``__repr__``, ``__eq__``,
``__hash__``, the orderings, a frozen class's ``__setattr__`` and ``__delattr__``). On Python 3.11 that compilation
is about three quarters of a dataclass's creation, and with the ~120 dataclasses of the model and the rules it was
the largest part of the checker's own start-up (``benchmarks/bench_startup.py``). :func:`dataclass` is
:func:`dataclasses.dataclass` with each of those compilations looked up in a cache of code objects kept on disk, the
way Python keeps a module's byte code in ``__pycache__``. The key is the whole source text dataclasses generates, so
a class whose fields or options change misses and compiles as usual, and a class built from the cache has the very
methods dataclasses would build (equal code objects: ``tests/xodrcheck/test_classcache.py``).

The cache: one file per module and byte-code version in the user's cache folder (:mod:`xodrcheck.usercache`: where,
when it is trusted and written); a command loads the files of the modules it imports, nothing else. A module's file
is rewritten at exit when one of its compilations missed.
"""

from __future__ import annotations

import _thread
import atexit
import builtins
import dataclasses
import marshal
import sys
from pathlib import Path
from types import CodeType
from typing import TYPE_CHECKING, Any

from xodrcheck import usercache

#: Most code objects one module's file keeps (this run's first, then those of earlier runs).
LIMIT = 512
_HEADER = b"xodrcheck dataclass code 2\n"


def _magic() -> bytes:
    from importlib.util import MAGIC_NUMBER  # the byte-code version: marshalled code objects are only valid for it

    return MAGIC_NUMBER


def cache_dir() -> Path | None:
    """The folder of this Python's cache files (``None``: no cache)."""
    folder = usercache.root()
    if folder is None:
        return None
    tag = sys.implementation.cache_tag or "python"
    return folder / f"dataclass-code-{tag}-opt{sys.flags.optimize}"


def _read(path: Path) -> dict[str, CodeType]:
    """The code objects of one cache file; nothing when it is missing, foreign, damaged or of another version."""
    data = usercache.read(path)
    head = _HEADER + _magic()
    if data is None or not data.startswith(head):
        return {}
    try:
        value = marshal.loads(data[len(head) :])
    except (ValueError, EOFError, TypeError):
        return {}
    if not isinstance(value, dict):
        return {}
    return {k: v for k, v in value.items() if isinstance(k, str) and isinstance(v, CodeType)}


class _Cache:
    """Per module: source text -> code object, loaded on the module's first class, saved at exit after a miss."""

    def __init__(self) -> None:
        self.lock = _thread.RLock()
        self.folder: Path | None = None
        self.loaded: dict[str, dict[str, CodeType]] = {}
        self.used: dict[str, dict[str, CodeType]] = {}
        self.missed: set[str] = set()
        #: The module whose class is being made (set by :func:`dataclass`).
        self.module = ""

    def code(self, source: str) -> CodeType:
        """The code of ``source`` as ``exec(source)`` would compile it (file ``<string>``, no inherited flags)."""
        with self.lock:
            module = self.module
            table = self.loaded.get(module)
            if table is None:
                if not self.loaded:
                    self.folder = cache_dir()
                table = self.loaded[module] = {} if self.folder is None else _read(self.folder / f"{module}.marshal")
            code = table.get(source)
            if code is None:
                code = compile(source, "<string>", "exec", dont_inherit=True)
                if not self.missed:
                    atexit.register(self.save)
                self.missed.add(module)
            self.used.setdefault(module, {})[source] = code
            return code

    def save(self) -> None:
        """Rewrite the files of the modules that missed (not when Python writes no byte code)."""
        if self.folder is None or not usercache.writable():
            return
        with self.lock:
            for module in sorted(self.missed):
                codes = dict(self.used.get(module, {}))
                for source, code in self.loaded.get(module, {}).items():
                    if len(codes) >= LIMIT:
                        break
                    codes.setdefault(source, code)
                usercache.write(self.folder / f"{module}.marshal", _HEADER + _magic() + marshal.dumps(codes))
            self.missed.clear()


_CACHE = _Cache()


def compiled(source: str, module: str) -> CodeType:
    """``compile(source, "<string>", "exec")`` (no inherited flags), from the cache file of ``module``: for other
    generated code made at import, as :mod:`xodrcheck.reader.construct`'s constructors."""
    with _CACHE.lock:
        outer, _CACHE.module = _CACHE.module, module
        try:
            return _CACHE.code(source)
        finally:
            _CACHE.module = outer


def _exec(source: Any, globals: Any = None, locals: Any = None, /) -> None:
    """:func:`exec` for the dataclasses module: its generated sources are compiled once, then taken from the cache."""
    if isinstance(source, str):
        source = _CACHE.code(source)
    builtins.exec(source, globals, locals)


if TYPE_CHECKING:
    from dataclasses import dataclass as dataclass
else:

    def dataclass(cls=None, /, **options):
        """:func:`dataclasses.dataclass` (same options, same class), its methods' byte code from the cache."""

        def wrap(c):
            with _CACHE.lock:  # dataclasses looks exec up in its module's globals: give it the caching one meanwhile
                saved, outer = vars(dataclasses).get("exec"), _CACHE.module
                dataclasses.exec, _CACHE.module = _exec, c.__module__
                try:
                    return dataclasses.dataclass(c, **options)
                finally:
                    _CACHE.module = outer
                    if saved is None:
                        del dataclasses.exec
                    else:
                        dataclasses.exec = saved

        return wrap if cls is None else wrap(cls)
