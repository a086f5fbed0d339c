"""What one ray costs in the wide BVH: the table "Where an incoherent ray's time goes" of
docs/bvh.md.

    python benchmarks/traversal_counts.py [--subdivisions 5 8] [--runs 5]

For the bunny and displaced icospheres (benchmarks/meshes.py), on a pinhole's 1024x1024
primary rays and 1 M incoherent rays, float32: per ray, the wide nodes it enters (each one
box8 test of eight child boxes), the children it pushes, the leaves it tests and their
faces, and the stack entries it drops (popped beyond its nearest hit); then the trace's
time per ray on one thread (rtfgu.kernels.mesh.mesh_closest, median of ``--runs``) and
that time over the nodes entered. A mesh whose tree fits the caches gives the traversal's
cost per node; the 1.31 M-triangle one adds what its fetches from memory cost.

``counted`` is rtfgu.kernels.mesh._wide_closest with counters, built from the same pieces
(enter_node, leaf_span, _leaf_closest, block_closest, pop_within; the float32 tree with its
blocks, as a float32 render's), so it makes the same steps: the script
checks that it finds every ray's face and t of mesh_closest. A measurement to read, not a
test.
"""
from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np
from numba import njit, prange, set_num_threads, get_num_threads

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

from rtfgu.kernels import wide_bvh  # noqa: E402
from rtfgu.kernels.float3 import lit  # noqa: E402
from rtfgu.kernels.mesh import _leaf_closest, _wide_start, block_closest  # noqa: E402

import meshes  # noqa: E402

# counts columns
NODES, PUSHED, LEAVES, FACES, DROPPED = range(5)


@njit(error_model="numpy")
def counted(vertices, faces, nodes, links, origin, direction, tmin, counts):
    """mesh_closest's wide traversal (no spheres, no instances) from root 0, adding its steps
    to ``counts``; returns the hit (t, face's index, kind, row)."""
    state = (lit(math.inf, tmin), -1, -1, -1)
    frame, inv, widen, stack, entry_stack, entry = _wide_start(origin, direction, tmin)
    sp = 0
    code = 0
    while True:
        if code >= 0:
            counts[NODES] += 1
            before = sp
            sp = wide_bvh.enter_node(nodes, links, code, origin, inv, tmin, state[0] * widen, widen, entry, stack,
                                     entry_stack, sp)
            counts[PUSHED] += sp - before
        else:
            first, count = wide_bvh.leaf_span(code, links)
            counts[LEAVES] += 1
            counts[FACES] += count
            if wide_bvh.is_block(code):
                state = block_closest(vertices, faces, nodes, wide_bvh.block_at(code), first, count, frame, tmin,
                                      state, entry)
            else:
                state = _leaf_closest(vertices, faces, None, (None, None, None), first, count, frame, origin,
                                      direction, tmin, state, 0)
        before = sp
        code, found, sp = wide_bvh.pop_within(stack, entry_stack, sp, state[0] * widen)
        counts[DROPPED] += before - sp - found
        if not found:
            break
    return state


@njit(parallel=True, error_model="numpy")
def count_all(vertices, faces, nodes, links, origins, directions, counts, t_out, face_out):
    for i in prange(origins.shape[0]):
        origin = (origins[i, 0], origins[i, 1], origins[i, 2])
        direction = (directions[i, 0], directions[i, 1], directions[i, 2])
        hit = counted(vertices, faces, nodes, links, origin, direction, lit(0, origins[i, 0]), counts[i])
        t_out[i] = hit[0]
        face_out[i] = hit[1]


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--subdivisions", type=int, nargs="*", default=[5, 8])
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args(argv)
    threads = get_num_threads()
    print("| mesh | triangles | wide nodes | tree MB | rays | nodes entered | children pushed | leaves "
          "| faces | dropped | ns per ray (1 thread) | ns per node entered | same faces and ts |")
    print("|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---|")
    for mesh in [meshes.bunny()] + [meshes.displaced_icosphere(s) for s in args.subdivisions]:
        system = meshes.Rtfgu(threads)
        system.build(mesh)
        for label, rays in (("1024x1024 primary", meshes.primary_rays(mesh.vertices, 1024)),
                            ("1 M incoherent", meshes.incoherent_rays(mesh.vertices, 1 << 20))):
            origins, directions = rays.of("float32")
            counts = np.zeros((len(origins), 5), dtype=np.int64)
            t = np.empty(len(origins), dtype=np.float32)
            face = np.empty(len(origins), dtype=np.int64)
            tree = system.wide["float32"]

            def single():
                t_run = np.empty(len(origins), dtype=np.float32)
                face_run = np.empty(len(origins), dtype=np.int64)
                meshes.closest_hits(system.vertices["float32"], system.faces4, tree.nodes, tree.links, origins,
                                    directions, t_run, face_run)
                return t_run, face_run
            count_all(system.vertices["float32"], system.faces4, tree.nodes, tree.links, origins, directions, counts,
                      t, face)
            set_num_threads(1)
            try:
                t_ref, face_ref = single()
                seconds = []
                for _ in range(args.runs):
                    start = time.perf_counter()
                    single()
                    seconds.append(time.perf_counter() - start)
            finally:
                set_num_threads(threads)
            same = np.array_equal(face, face_ref) and np.array_equal(t, t_ref)
            per_ray = counts.mean(axis=0)
            ns = 1e9 * statistics.median(seconds) / len(origins)
            print("| %s | %d | %d | %.1f | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.0f | %.0f | %s |" % (
                mesh.name, len(mesh.faces), len(tree.nodes), tree.nbytes / 2 ** 20, label,
                per_ray[NODES], per_ray[PUSHED], per_ray[LEAVES], per_ray[FACES], per_ray[DROPPED], ns,
                ns / per_ray[NODES], "yes" if same else "NO"), flush=True)


if __name__ == "__main__":
    main()
