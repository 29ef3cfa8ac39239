"""Writing lane meshes for viewers: glTF binary (``.glb``), Wavefront OBJ (``.obj``) and PLY (``.ply``) through
trimesh's exporters, coloured by lane type.

* ``.glb``: a scene with one named mesh per lane type (``driving``, ``sidewalk``...), each with its vertex colours,
  so a viewer's outliner lists the lane types and each can be hidden or re-materialised on its own.
* ``.obj`` and ``.ply``: one mesh with vertex colours (every lane has vertices of its own, so colours do not bleed).

OpenDRIVE is z-up; glTF is y-up by definition and Blender's OBJ importer assumes y-up too, so ``.glb`` and ``.obj``
are written with ``(x, y, z) -> (x, z, -y)`` and open the right way up; ``.ply`` keeps the file's own axes. The file
is written to a temporary file beside the target and moved into place, so a failed run leaves nothing behind.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from xodrcheck.findings import XodrError
from xodrcheck.mesh.surfaces import LaneSurfaces
from xodrcheck.support.atomic import write_bytes

#: Output formats by file extension.
FORMATS = {".glb": "glb", ".obj": "obj", ".ply": "ply"}

#: RGBA colours of lane types; other types use :data:`OTHER_COLOUR`.
COLOURS = {
    "driving": (90, 90, 96, 255),
    "bidirectional": (90, 90, 96, 255),
    "entry": (110, 110, 120, 255),
    "exit": (110, 110, 120, 255),
    "onRamp": (110, 110, 120, 255),
    "offRamp": (110, 110, 120, 255),
    "connectingRamp": (110, 110, 120, 255),
    "slipLane": (110, 110, 120, 255),
    "mwyEntry": (110, 110, 120, 255),
    "mwyExit": (110, 110, 120, 255),
    "bus": (150, 60, 60, 255),
    "taxi": (170, 150, 40, 255),
    "HOV": (120, 70, 150, 255),
    "biking": (170, 80, 70, 255),
    "sidewalk": (190, 185, 175, 255),
    "walking": (190, 185, 175, 255),
    "curb": (160, 160, 160, 255),
    "shoulder": (140, 125, 100, 255),
    "border": (120, 140, 110, 255),
    "parking": (70, 100, 140, 255),
    "median": (90, 140, 80, 255),
    "restricted": (180, 120, 60, 255),
    "stop": (180, 60, 60, 255),
    "tram": (110, 90, 80, 255),
    "rail": (110, 90, 80, 255),
    "roadWorks": (220, 140, 30, 255),
    "none": (200, 200, 200, 255),
}
OTHER_COLOUR = (230, 0, 230, 255)

#: OpenDRIVE's z-up axes to y-up: ``(x, y, z) -> (x, z, -y)``, a rotation by -90 degrees about x (right-handed stays
#: right-handed, so faces wound counter-clockwise seen from above still face up). Applied as ``vertices @ _Y_UP.T``.
_Y_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])


class ExportError(XodrError, ValueError):
    """The output cannot be written in the requested form (unknown extension, nothing to write)."""


def format_of(path: str | Path) -> str:
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        known = ", ".join(sorted(FORMATS))
        raise ExportError(f"unknown mesh format {suffix or '(no extension)'!r} of {path}; use one of {known}")
    return FORMATS[suffix]


def vertex_colours(surfaces: LaneSurfaces) -> np.ndarray:
    """``(V, 4)`` uint8 colour of every vertex, by the lane type of the lane owning it."""
    palette = np.array([COLOURS.get(t, OTHER_COLOUR) for t in surfaces.lane_types], dtype=np.uint8).reshape(-1, 4)
    owner = np.repeat(np.arange(len(surfaces.lanes)), np.diff(surfaces.lane_vertices))
    return palette[owner]


def _trimesh(surfaces: LaneSurfaces, y_up: bool):
    import trimesh

    vertices = surfaces.vertices @ _Y_UP.T if y_up else surfaces.vertices
    return trimesh.Trimesh(
        vertices=vertices,
        faces=surfaces.faces,
        vertex_colors=vertex_colours(surfaces),
        process=False,
        validate=False,
    )


def scene(surfaces: LaneSurfaces, y_up: bool = True):
    """A :class:`trimesh.Scene` with one mesh per lane type, named after it."""
    import trimesh

    out = trimesh.Scene()
    types = np.array(surfaces.lane_types, dtype=object)
    for lane_type in sorted(set(surfaces.lane_types)):
        part = surfaces.select(types == lane_type)
        out.add_geometry(_trimesh(part, y_up), geom_name=lane_type, node_name=lane_type)
    return out


def encode(surfaces: LaneSurfaces, fmt: str) -> bytes:
    """The mesh file's bytes in ``fmt`` (``glb``, ``obj`` or ``ply``)."""
    if len(surfaces.faces) == 0:
        raise ExportError("no lane surface to write (no road with a plan view and lanes of the selected types)")
    if fmt == "glb":
        data = scene(surfaces).export(file_type="glb")
    elif fmt == "obj":
        data = _trimesh(surfaces, y_up=True).export(file_type="obj")
    elif fmt == "ply":
        data = _trimesh(surfaces, y_up=False).export(file_type="ply")
    else:
        raise ExportError(f"unknown mesh format {fmt!r}")
    return data.encode("utf-8") if isinstance(data, str) else bytes(data)


def write(surfaces: LaneSurfaces, path: str | Path) -> int:
    """Write the mesh to ``path`` (format from its extension) atomically; return the number of bytes written. A
    target that cannot be written raises :class:`~xodrcheck.support.atomic.OutputError` naming ``path``."""
    data = encode(surfaces, format_of(path))
    write_bytes(path, data)
    return len(data)
