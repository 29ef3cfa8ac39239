"""The package's data folder: a plain path on disk, with what importlib.resources lists."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from xodrcheck.support import packagedata


def test_data_folders_on_disk_are_paths_with_the_same_files():
    for package in ("xodrcheck.schemas", "xodrcheck.standard"):
        folder = packagedata.folder(package)
        assert isinstance(folder, Path) and folder.is_dir()
        assert sorted(p.name for p in folder.iterdir()) == sorted(e.name for e in resources.files(package).iterdir())
    assert (packagedata.folder("xodrcheck.schemas") / "1.8.1-corrected" / "fast-plan.json").is_file()
