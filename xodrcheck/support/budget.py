"""A byte budget shared by many small caches: the least recently used entries go first when the total is over it.

The geometric rules cache evaluations per road (a road's last lane evaluations, a lane section's sampled lines), so
that the rules asking for the same numbers share one computation. Kept for the whole check, those caches grew with
the map; counted against one :class:`ByteBudget` per document,
they keep what fits, and a dropped entry is computed again when asked for, with the same numbers. A small map's
caches fit whole: it is checked as fast as without a bound.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Hashable, MutableMapping
from typing import Any

#: Python's own bytes around one numpy array (object, header, allocation), about: added per array to estimates.
ARRAY_OVERHEAD = 160


def array_bytes(count: int, size: int) -> int:
    """Estimated bytes of ``count`` float64 arrays of ``size`` values each."""
    return count * (8 * size + ARRAY_OVERHEAD)


class ByteBudget:
    """Entries of many caches (each a mutable mapping) counted together by their estimated size in bytes.

    A cache registers what it stores with :meth:`add` and what it uses with :meth:`touch`; when the total passes
    ``limit``, the least recently used entries are removed from their caches (the newest entry always stays).
    """

    __slots__ = ("_entries", "limit", "total")

    def __init__(self, limit: int) -> None:
        self.limit = limit
        self.total = 0
        self._entries: OrderedDict[tuple[int, Hashable], tuple[MutableMapping[Any, Any], int]] = OrderedDict()

    def __len__(self) -> int:
        return len(self._entries)

    def touch(self, cache: MutableMapping[Any, Any], key: Hashable) -> None:
        """Mark ``cache[key]`` as just used."""
        entry = (id(cache), key)
        if entry in self._entries:
            self._entries.move_to_end(entry)

    def add(self, cache: MutableMapping[Any, Any], key: Hashable, size: int) -> None:
        """Count ``cache[key]`` (just stored, ``size`` bytes), then remove the least recently used entries while the
        total is over the limit."""
        entry = (id(cache), key)
        old = self._entries.pop(entry, None)
        if old is not None:
            self.total -= old[1]
        self._entries[entry] = (cache, size)
        self.total += size
        while self.total > self.limit and len(self._entries) > 1:
            (_, old_key), (owner, old_size) = self._entries.popitem(last=False)
            owner.pop(old_key, None)
            self.total -= old_size

    def discard(self, cache: MutableMapping[Any, Any], key: Hashable) -> None:
        """Forget ``cache[key]``, which its cache removed itself."""
        found = self._entries.pop((id(cache), key), None)
        if found is not None:
            self.total -= found[1]
