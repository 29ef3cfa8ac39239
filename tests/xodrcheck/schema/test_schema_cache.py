"""The XSD 1.1 schemas of OpenDRIVE 1.8 and 1.9 cached in the user's cache folder
(:func:`xodrcheck.schema.validate.xsd11`): a schema loaded from the cache gives the same verdicts and the same errors
as one just built, and the cache is only a cache (damaged, foreign, of other files: built again)."""

from __future__ import annotations

import os
import sys
from importlib import resources
from pathlib import Path

import pytest
from lxml import etree

from xodrcheck.schema import validate as schema

ROOT = Path(__file__).resolve().parents[1]  # tests/xodrcheck


def _files(minor: int, count: int = 12) -> list[Path]:
    """The smallest test maps declaring 1.``minor``."""
    found = [p for p in ROOT.rglob("*.xodr") if f'revMinor="{minor}"' in p.read_text(errors="replace")[:2000]]
    return sorted(found, key=lambda p: (p.stat().st_size, str(p)))[:count]


def _broken(text: str) -> list[str]:
    """Invalid variants of a valid map: an unknown attribute, an unknown element, a missing required attribute."""
    return [
        text.replace("<header ", '<header bogus="1" ', 1),
        text.replace("<planView>", "<planView><bogus/>", 1),
        text.replace(' length="', ' lenght="', 1),
    ]


def _errors(xsd, text: str, version: tuple[int, int], monkeypatch: pytest.MonkeyPatch) -> list[schema.SchemaError]:
    monkeypatch.setattr(schema, "compiled", lambda v: xsd)
    tree = etree.ElementTree(etree.fromstring(text.encode()))
    return list(schema.validate(tree, version))


def _path(version: tuple[int, int]) -> Path:
    folder, main = schema.SCHEMA_FOLDERS[version]
    return Path(str(resources.files("xodrcheck.schemas") / folder / main))


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("XODRCHECK_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    return tmp_path / "cache" / "xsd11"


@pytest.mark.parametrize("minor", [8, 9])
def test_a_cached_schema_validates_like_a_built_one(cache: Path, monkeypatch, minor: int) -> None:
    version = (1, minor)
    built = schema.xsd11(version, _path(version))  # nothing cached: built, then stored
    (stored,) = cache.iterdir()
    assert stored.name.startswith(f"1.{minor}-") and stored.suffix == ".pickle"
    loaded = schema.xsd11(version, _path(version))
    assert loaded is not built and type(loaded) is type(built)
    texts = [p.read_text() for p in _files(minor)]
    assert len(texts) >= 3
    seen_errors = 0
    for text in [*texts, *(b for t in texts[:4] for b in _broken(t))]:
        expected = _errors(built, text, version, monkeypatch)
        assert _errors(loaded, text, version, monkeypatch) == expected
        seen_errors += len(expected)
    assert seen_errors >= 8  # the broken variants went through the full validator, and it found their errors


def test_a_damaged_or_untrusted_cache_file_is_built_again(cache: Path, monkeypatch) -> None:
    version = (1, 8)
    schema.xsd11(version, _path(version))
    (stored,) = cache.iterdir()
    stored.write_bytes(b"not a pickle")
    again = schema.xsd11(version, _path(version))  # damaged: built and stored again
    assert type(again).__name__ == "XMLSchema11" and stored.read_bytes() != b"not a pickle"
    os.chmod(stored, 0o666)  # others may write it: not loaded (and replaced by a private file)
    calls = []
    real = schema.pickle.loads
    monkeypatch.setattr(schema.pickle, "loads", lambda data: calls.append(1) or real(data))
    schema.xsd11(version, _path(version))
    assert calls == [] and not stored.stat().st_mode & 0o022


def test_the_cache_file_is_named_after_the_schema_files(tmp_path: Path, cache: Path) -> None:
    version = (1, 8)
    copy = tmp_path / "copy"
    copy.mkdir()
    for file in _path(version).parent.iterdir():
        (copy / file.name).write_bytes(file.read_bytes())
    same = schema.xsd11_cache_file(version, copy / _path(version).name)
    (copy / "OpenDRIVE_Core.xsd").write_bytes((copy / "OpenDRIVE_Core.xsd").read_bytes() + b"\n")
    edited = schema.xsd11_cache_file(version, copy / _path(version).name)
    assert same is not None and edited is not None and same != edited
    assert schema.xsd11_cache_file(version, _path(version)) not in (same, edited)  # another location too
