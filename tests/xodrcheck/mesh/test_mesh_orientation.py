"""Mesh files open the right way up: a road climbing from 0 to 6 m, written as ``.glb``, ``.obj`` and ``.ply`` and read
back with trimesh, has its height on the format's up axis (glTF and OBJ: +y; PLY: +z, the file's own axes) and face
normals pointing up.

The y-up formats map OpenDRIVE's ``(x, y, z)`` to ``(x, z, -y)`` (a rotation: right-handed stays right-handed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from xodrcheck.cli import main

LENGTH, RISE = 120.0, 6.0

#: A crest: an arc turning left while the elevation climbs smoothly from 0 to 6 m (zero slope at both ends).
SLOPED = f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="7" name="crest" version="1" date="2024-01-01"/>
  <road id="1" length="{LENGTH}" junction="-1" rule="RHT">
    <planView>
      <geometry s="0" x="0" y="0" hdg="0.3" length="{LENGTH}"><arc curvature="0.004"/></geometry>
    </planView>
    <elevationProfile>
      <elevation s="0" a="0" b="0" c="{3 * RISE / LENGTH**2!r}" d="{-2 * RISE / LENGTH**3!r}"/>
    </elevationProfile>
    <lanes>
      <laneSection s="0">
        <left><lane id="1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
        <center><lane id="0" type="none" level="false"/></center>
        <right><lane id="-1" type="sidewalk" level="false"><width sOffset="0" a="3.0" b="0" c="0" d="0"/></lane></right>
      </laneSection>
    </lanes>
  </road>
</OpenDRIVE>
"""

#: Format -> (axis that is up, map from OpenDRIVE (x, y, z) to the file's axes).
AXES = {
    ".glb": (1, lambda p: np.column_stack([p[:, 0], p[:, 2], -p[:, 1]])),
    ".obj": (1, lambda p: np.column_stack([p[:, 0], p[:, 2], -p[:, 1]])),
    ".ply": (2, lambda p: p),
}


def _load(path: Path) -> trimesh.Trimesh:
    loaded = trimesh.load(path, process=False)
    if isinstance(loaded, trimesh.Scene):
        return trimesh.util.concatenate([loaded.geometry[name] for name in sorted(loaded.geometry)])
    return loaded


@pytest.fixture(scope="module")
def sloped(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("sloped") / "crest.xodr"
    path.write_text(SLOPED, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def reference(sloped) -> np.ndarray:
    """The mesh's vertices in OpenDRIVE's own axes (x, y, z), as xodrcheck builds them."""
    from xodrcheck.mesh.surfaces import build_surfaces
    from xodrcheck.reader import read

    return build_surfaces(read(sloped).document, chord=0.05).vertices


@pytest.mark.parametrize("suffix", sorted(AXES))
def test_sloped_road_is_right_way_up(tmp_path, sloped, reference, suffix):
    out = tmp_path / f"crest{suffix}"
    assert main(["mesh", str(sloped), "-o", str(out), "--chord", "0.05"]) == 0
    mesh = _load(out)
    up, to_file = AXES[suffix]
    heights = mesh.vertices[:, up]
    assert heights.min() == pytest.approx(0.0, abs=1e-4)
    assert heights.max() == pytest.approx(RISE, abs=1e-4)
    # every face points up (the road is nowhere steeper than 4.3 degrees), on average almost straight up
    assert (mesh.face_normals[:, up] > 0.99).all()
    assert mesh.face_normals[:, up].mean() > 0.998
    # the plan view is mapped as documented, so the file is not mirrored: same bounding box as the mapped vertices
    want = to_file(reference)
    np.testing.assert_allclose(mesh.bounds, [want.min(axis=0), want.max(axis=0)], atol=1e-3)
