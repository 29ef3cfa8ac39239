"""Freed memory goes back to the system between the steps of a check (xodrcheck.support.memory)."""

from __future__ import annotations

import ctypes
import ctypes.util
import sys

import pytest
from lxml import etree

from xodrcheck.support import memory

GLIBC = sys.platform.startswith("linux") and ctypes.util.find_library("c") is not None


def test_resident_size_is_read_on_linux():
    size = memory.resident_mb()
    assert size is not None and 5 < size < 64_000


@pytest.mark.skipif(not GLIBC, reason="malloc_trim is glibc's")
def test_a_parse_tree_freed_and_released_leaves_the_process():
    """An lxml tree of 200,000 elements is about 150 MB of small blocks; freed, glibc keeps them unless trimmed."""
    data = b"<r>" + b'<e a="1.0" b="2.0" c="3.0"/>' * 200_000 + b"</r>"
    tree = etree.fromstring(data)
    pin = ctypes.create_string_buffer(1 << 16)  # after the tree: freeing it cannot shrink the heap's top
    assert len(tree) == 200_000
    del tree
    before = memory.resident_mb()
    assert memory.release() is True
    after = memory.resident_mb()
    assert before is not None and after is not None
    assert before - after > 50, f"{before:.0f} MB before release, {after:.0f} MB after"
    assert len(pin.raw) == 1 << 16


def test_release_is_harmless_to_call_often():
    assert all(memory.release() == GLIBC for _ in range(3))
