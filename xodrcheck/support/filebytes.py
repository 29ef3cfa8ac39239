"""A file's bytes searched on disk instead of held in memory.

The XML rules skip their walk when a keyword is not in the file (``b"signal" in ctx.data``). Holding the file's bytes
for that costs their size for the whole check (51 MB on a 10 km generated map, beside a 720 MB parse tree):
:class:`FileBytes` answers the same ``in`` by reading the file in chunks, from the page cache, each answer once.
"""

from __future__ import annotations

#: Bytes read at a time by a search.
CHUNK = 1 << 20


class FileBytes:
    """The bytes of the file at ``path`` (as the reader read them: not compressed) for ``needle in data``; ``bytes()``
    and :meth:`decode` read them whole. The file is expected not to change during the check."""

    __slots__ = ("_found", "path")

    def __init__(self, path: str) -> None:
        self.path = path
        self._found: dict[bytes, bool] = {}

    def __contains__(self, needle: object) -> bool:
        if not isinstance(needle, (bytes, bytearray)):
            raise TypeError(f"a bytes needle is searched, not {type(needle).__name__}")
        key = bytes(needle)
        if key not in self._found:
            self._found[key] = self._search(key)
        return self._found[key]

    def _search(self, needle: bytes) -> bool:
        if not needle:
            return True
        keep = len(needle) - 1  # a match not yet seen starts in the last len(needle) - 1 bytes read
        tail = b""
        try:
            with open(self.path, "rb") as stream:
                while chunk := stream.read(CHUNK):
                    seen = tail + chunk
                    if needle in seen:
                        return True
                    tail = seen[-keep:] if keep else b""
        except OSError:
            return True  # unreadable now: "may hold it", so the rule walks the tree rather than skip it
        return False

    def __bytes__(self) -> bytes:
        with open(self.path, "rb") as stream:
            return stream.read()

    def decode(self, encoding: str = "utf-8", errors: str = "strict") -> str:
        return bytes(self).decode(encoding, errors)
