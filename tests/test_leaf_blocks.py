"""The experiment of benchmarks/leaf_blocks.py (docs/bvh.md, "Leaf blocks"): the wide tree's
bottom nodes as blocks of eight faces tested by one 8-wide watertight test give every ray
mesh_closest's face and t, bit for bit (ties, rays along the axes and through vertices
included), and no ray from inside a closed mesh leaks between the blocks' faces."""
from __future__ import annotations

import numpy as np
import pytest

from benchmark_scripts import benchmark_script
from test_wide_bvh import hard_rays, rays_from_inside, traced, traversal_mesh, tree_of


def blocks_traced(vertices, rows, wide, origins, directions, all_leaves):
    leaf_blocks = benchmark_script("leaf_blocks")
    v32 = vertices.astype(np.float32)
    nodes, blocks, reached = leaf_blocks.make_blocks(wide.nodes, v32, rows, all_leaves)
    t = np.empty(len(origins), dtype=np.float32)
    face = np.empty(len(origins), dtype=np.int64)
    leaf_blocks.closest_hits_blocks(v32, rows, nodes, nodes.view(np.int32), blocks, blocks.view(np.int32), len(nodes),
                                    origins.astype(np.float32), directions.astype(np.float32), t, face)
    return t, face, blocks, reached


@pytest.mark.parametrize("all_leaves", [False, True], ids=["pure nodes", "all leaves"])
@pytest.mark.parametrize("mesh", ["soup", "icosphere", "coincident"])
def test_the_blocks_find_mesh_closests_face_and_t(mesh, all_leaves):
    vertices, faces = traversal_mesh(mesh)
    _, wide, rows = tree_of(vertices, faces)
    origins, directions = hard_rays(vertices, 20000, seed=9)
    truth, _ = traced(vertices, rows, wide.nodes, origins, directions, np.float32)
    t, face, blocks, reached = blocks_traced(vertices, rows, wide, origins, directions, all_leaves)
    assert len(blocks) > 0 and not reached.all()          # blocks were made and are used
    assert (face >= 0).mean() > 0.3
    assert np.array_equal(face, truth[:, 1].astype(np.int64))
    assert t.tobytes() == truth[:, 0].astype(np.float32).tobytes()


@pytest.mark.parametrize("all_leaves", [False, True], ids=["pure nodes", "all leaves"])
def test_no_ray_from_inside_a_closed_mesh_leaks_between_the_blocks_faces(all_leaves):
    vertices, rows, wide, rays = rays_from_inside()
    for origins, directions in rays:
        _, face, _, _ = blocks_traced(vertices, rows, wide, origins, directions, all_leaves)
        assert (face >= 0).all(), "%d of %d rays leak" % ((face < 0).sum(), len(origins))
