"""The experiment of benchmarks/leaf_blocks.py (docs/bvh.md, "Leaf blocks"): the wide tree's
bottom nodes as blocks of up to eight faces, their corners stored row by row without padding
and tested by one 8-wide watertight test, give every ray mesh_closest's face and t, bit for
bit (ties, rays along the axes and through vertices included), and no ray from inside a
closed mesh leaks between the blocks' faces."""
from __future__ import annotations

import numpy as np
import pytest

from benchmark_scripts import benchmark_script
from test_wide_bvh import hard_rays, rays_from_inside, traced, traversal_mesh, tree_of


def blocks_traced(vertices, rows, wide, origins, directions, all_leaves):
    leaf_blocks = benchmark_script("leaf_blocks")
    v32 = vertices.astype(np.float32)
    nodes, corners, table, reached, _ = leaf_blocks.make_blocks(wide.nodes, v32, rows, all_leaves)
    t = np.empty(len(origins), dtype=np.float32)
    face = np.empty(len(origins), dtype=np.int64)
    leaf_blocks.closest_hits_blocks(v32, rows, nodes, nodes.view(np.int32), corners, table, len(nodes),
                                    origins.astype(np.float32), directions.astype(np.float32), t, face)
    return t, face, table, reached


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


def test_a_block_reads_only_its_own_lanes():
    """A block of fewer than eight faces is followed by the next block's corners (no
    padding): its masked rows must not take them as faces. Each block's faces hit at t = 1
    and the corners after it hold a face at t = 0.5 that the ray would hit, in every lane."""
    leaf_blocks = benchmark_script("leaf_blocks")
    from rtfgu.kernels import wide_bvh
    from rtfgu.kernels.mesh import ray_frame
    from numba import njit

    near = [(-1.0, -1.0, 0.5), (3.0, -1.0, 0.5), (-1.0, 3.0, 0.5)]     # hit at t = 0.5
    far = [(-1.0, -1.0, 1.0), (3.0, -1.0, 1.0), (-1.0, 3.0, 1.0)]      # hit at t = 1
    rows = leaf_blocks.CORNER_ROWS

    @njit
    def test(corners, offset, count, origin, direction):
        lanes = wide_bvh.lanes_of(np.float32)
        mask = leaf_blocks.tri8(corners, offset, count, ray_frame(origin, direction), np.float32(0),
                                np.float32(np.inf), lanes)
        out = np.empty(8, dtype=np.float32)
        for j in range(8):
            out[j] = lanes[j]
        return mask, out

    origin = (np.float32(0.25), np.float32(0.25), np.float32(0))
    direction = (np.float32(0), np.float32(0), np.float32(1))
    for count in range(1, 9):
        block = np.repeat(np.array(far, dtype=np.float32).reshape(rows, 1), count, axis=1)
        after = np.repeat(np.array(near, dtype=np.float32).reshape(rows, 1), 16, axis=1)
        corners = np.concatenate([block.reshape(-1), after.reshape(-1)])
        mask, out = test(corners, 0, count, origin, direction)
        assert mask & 0xFF == (1 << count) - 1, (count, bin(mask))
        assert (out[:count] == 1).all()
        # the same corners one block later, the near faces before it
        corners = np.concatenate([after.reshape(-1)[:rows * 3], block.reshape(-1), after.reshape(-1)])
        mask, out = test(corners, rows * 3, count, origin, direction)
        assert mask & 0xFF == (1 << count) - 1, (count, bin(mask))
        assert (out[:count] == 1).all()
