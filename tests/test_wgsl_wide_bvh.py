"""The experiment of benchmarks/meshes.py's "rtfgu WGSL wide" peer: the wide BVH traversed in
WGSL (benchmarks/wgsl_wide_bvh.wgsl) gives every ray the face and t of intersect_mesh.wgsl's
binary traversal, bit for bit, on the render's adapter (Mesa's llvmpipe where there is no
GPU), rays along the axes and through vertices (ties) included; of tied faces both keep the
one earlier in Scene.shapes."""
from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

import numpy as np
import pytest

from test_wide_bvh import hard_rays
from wgsl_support import wgpu_device  # noqa: F401  (fixture)

MESHES = Path(__file__).resolve().parent.parent / "benchmarks" / "meshes.py"


@pytest.fixture(scope="module")
def meshes(wgpu_device):  # noqa: F811  (the fixture)
    """benchmarks/meshes.py, loaded with the process's shader-cache setting kept (bench.py
    turns Mesa's cache off for its own runs)."""
    before = os.environ.get("MESA_SHADER_CACHE_DISABLE")
    spec = importlib.util.spec_from_file_location("meshes_benchmark", MESHES)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up there
    try:
        spec.loader.exec_module(module)
    finally:
        if before is None:
            os.environ.pop("MESA_SHADER_CACHE_DISABLE", None)
        else:
            os.environ["MESA_SHADER_CACHE_DISABLE"] = before
    return module


def traced(system, mesh, rays):
    system.build(mesh)
    t, face = system.result(system.run(system.prepare(rays)))
    return t.astype(np.float32), face


def test_wide_gives_the_binary_face_and_t(meshes):
    mesh = meshes.displaced_icosphere(4)
    v = mesh.vertices
    origins, directions = hard_rays(v, 2048, seed=7)
    # rays from a camera exactly through vertices: each hits a vertex that 5 or 6 faces share
    eye = (v.min(axis=0) + v.max(axis=0)) / 2 + np.array([0.4, 3.0, -2.5])
    through = v[np.random.default_rng(8).integers(0, len(v), 1024)] - eye
    incoherent = meshes.incoherent_rays(v, 1024)
    rays = meshes.Rays("test", np.vstack([origins, np.broadcast_to(eye, through.shape), incoherent.origins]),
                       np.vstack([directions, through, incoherent.directions]))
    binary, wide = meshes.Wgsl(0), meshes.WgslWide(0)
    # the faces in reverse order: every tie goes to the other face of the two orders
    reverse = meshes.MeshArrays("reversed", v, mesh.faces[::-1].copy(), "")
    last = len(mesh.faces) - 1
    results = {}
    for m in (mesh, reverse):
        t, face = traced(binary, m, rays)
        t_wide, face_wide = traced(wide, m, rays)
        mismatch = np.flatnonzero((t.view(np.uint32) != t_wide.view(np.uint32)) | (face != face_wide))
        assert mismatch.size == 0, "%s: %d rays differ, the first %d: binary (%r, %d), wide (%r, %d)" % (
            m.name, mismatch.size, mismatch[0], t[mismatch[0]], face[mismatch[0]], t_wide[mismatch[0]],
            face_wide[mismatch[0]])
        results[m.name] = t, face
    t, face = results[mesh.name]
    t_rev, face_rev = results["reversed"]
    assert 0.3 < np.mean(face >= 0) < 0.99, np.mean(face >= 0)
    assert np.array_equal(t.view(np.uint32), t_rev.view(np.uint32))
    as_original = np.where(face_rev >= 0, last - face_rev, -1)
    tied = np.flatnonzero(face != as_original)
    vertex_rays = slice(len(origins), len(origins) + len(through))
    assert np.sum(face[vertex_rays] != as_original[vertex_rays]) > 50, "few ties through the vertices"
    # of tied faces each order keeps its lowest index: the original's lower, the reverse's higher
    assert np.all(face[tied] < as_original[tied])


def test_wide_refuses_rows_that_are_not_faces(meshes):
    mesh = meshes.MeshArrays("with a sphere row", np.zeros((3, 3)), np.array([[0, 1, 2], [-1, 0, 0]]), "")
    with pytest.raises(ValueError, match="with a sphere row: .*faces only"):
        meshes.WgslWide.faces_only(mesh)
