"""Lane surfaces as triangle meshes and their plan-view footprints.

:mod:`.surfaces` builds the meshes, :mod:`.footprint` and :mod:`.strip_shapes` the shapely polygons the overlap rules
and metrics ask about, :mod:`.export` writes meshes for viewers (glTF, OBJ, PLY).
"""
