"""FileBytes: ``needle in`` a file on disk answers as ``needle in`` its bytes, also across the chunks it reads."""

from __future__ import annotations

from pathlib import Path

import pytest

from xodrcheck.support import filebytes
from xodrcheck.support.filebytes import FileBytes


@pytest.mark.parametrize("chunk", [1, 3, 4, 7, 1 << 22])
def test_contains_like_bytes(tmp_path: Path, chunk: int, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(filebytes, "CHUNK", chunk)
    data = b'<road id="1"><signal name="staticBoard"/></road>\n'
    path = tmp_path / "f.xodr"
    path.write_bytes(data)
    found = FileBytes(str(path))
    needles = [b"staticBoard", b"Board", b"signal", b"road", b"</road>\n", b"gantry", b"x", b"", data, data + b"!"]
    for needle in needles:
        assert (needle in found) is (needle in data), needle
    assert bytes(found) == data
    assert found.decode("utf-8") == data.decode()


def test_unreadable_file_may_hold_anything(tmp_path: Path) -> None:
    found = FileBytes(str(tmp_path / "gone.xodr"))
    assert b"signal" in found  # the rules then walk the tree instead of skipping it


def test_needle_is_bytes(tmp_path: Path) -> None:
    path = tmp_path / "f.xodr"
    path.write_bytes(b"abc")
    with pytest.raises(TypeError):
        assert "a" in FileBytes(str(path))
