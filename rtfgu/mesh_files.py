"""load_mesh: a triangle mesh file read by the loader its suffix names: ``.obj`` by load_obj
(rtfgu/obj.py, the 02562 worksheets' meshes), ``.ply`` by load_ply (rtfgu/ply.py, Suffern's
meshes, ch. 23)."""
from __future__ import annotations

from pathlib import Path

from .obj import load_obj
from .ply import load_ply
from .shapes.mesh import Mesh

LOADERS = {".obj": load_obj, ".ply": load_ply}


def load_mesh(path, **options) -> Mesh:
    """The Mesh of the OBJ or PLY file ``path`` (the suffix in any case); ``options`` are
    the loader's (``material``, ``default_color``, ``drop_degenerate``)."""
    suffix = Path(path).suffix.lower()
    if suffix not in LOADERS:
        raise ValueError("load_mesh: %s: unknown mesh suffix %r (it reads %s)"
                         % (path, Path(path).suffix, " and ".join(LOADERS)))
    return LOADERS[suffix](path, **options)
