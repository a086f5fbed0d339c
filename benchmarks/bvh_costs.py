"""The binary build's constants against the speed and size of the tree the numba render
traverses: the 1.3-million-triangle icosphere and the bunny of benchmarks/meshes.py, their
binary tree built with each (C_TRAVERSE, LEAF_SIZE, BINS) of VARIANTS (C_INTERSECT 1),
collapsed to the wide tree with its leaf blocks (the render's where the CPU has AVX,
rtfgu.accelerators.wide_bvh) and traced with the same primary and incoherent rays on one
thread. Prints the markdown table of docs/bvh.md, "Cost constants". A script, not a test:
nothing is asserted.

    python benchmarks/bvh_costs.py [--quick]

Time: the median of RUNS rounds after a warm-up, a round tracing with every tree once (in
turn forward and backward). One thread: two threads of one kernel move by up to a third
from call to call on a virtual machine (docs/bvh.md), more than these trees differ. Every
tree must give every ray the same face and t: the constants change the tree, never the hit
(checked, and the script stops if not).
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numba
import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

from rtfgu.accelerators import flat_bvh  # noqa: E402

from meshes import (ICOSPHERE_SUBDIVISIONS, INCOHERENT, PRIMARY, QUICK_INCOHERENT,  # noqa: E402
                    QUICK_PRIMARY, QUICK_SUBDIVISIONS, bunny, bvh_of, closest_hits, count_blocks,
                    count_nodes, displaced_icosphere, incoherent_rays, primary_rays)

# (C_TRAVERSE, LEAF_SIZE, BINS); the first is the build's own (flat_bvh's constants).
VARIANTS = ((flat_bvh.C_TRAVERSE, flat_bvh.LEAF_SIZE, flat_bvh.BINS), (1.0, 4, 16), (1.5, 4, 16),
            (3.0, 4, 16), (2.0, 8, 16), (3.0, 8, 16), (2.0, 4, 32))
RUNS = 5


def build(mesh, constants):
    """bvh_of(mesh) with flat_bvh's C_TRAVERSE, LEAF_SIZE and BINS set to ``constants`` (module
    constants its build reads when it runs), and its wide trees with blocks in both
    precisions: (binary table, faces in leaf order, {precision: (vertices, wide tree)},
    seconds of the binary build)."""
    saved = flat_bvh.C_TRAVERSE, flat_bvh.LEAF_SIZE, flat_bvh.BINS
    flat_bvh.C_TRAVERSE, flat_bvh.LEAF_SIZE, flat_bvh.BINS = constants
    try:
        bvh, faces4 = bvh_of(mesh)
    finally:
        flat_bvh.C_TRAVERSE, flat_bvh.LEAF_SIZE, flat_bvh.BINS = saved
    wide = {}
    for precision in ("float64", "float32"):
        vertices = np.ascontiguousarray(mesh.vertices, dtype=precision)
        wide[precision] = (vertices, bvh.wide_with_blocks((0,), vertices, faces4))
    return bvh, faces4, wide, bvh.build_seconds


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small meshes and few rays")
    args = parser.parse_args(argv)
    numba.set_num_threads(1)
    meshes = [displaced_icosphere(QUICK_SUBDIVISIONS if args.quick else ICOSPHERE_SUBDIVISIONS), bunny()]
    primary, incoherent = (QUICK_PRIMARY, QUICK_INCOHERENT) if args.quick else (PRIMARY, INCOHERENT)
    print("| mesh | C_TRAVERSE | LEAF_SIZE | BINS | binary nodes per triangle | wide nodes | blocks | "
          "bytes per triangle (float64 / float32) | binary build | primary float64 | primary float32 | "
          "incoherent float64 | incoherent float32 |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for mesh in meshes:
        trees = {}
        for constants in VARIANTS:
            build(mesh, constants)  # the warm-up (numba's compile)
            trees[constants] = build(mesh, constants)
        rates = {}
        for rays in (primary_rays(mesh.vertices, primary), incoherent_rays(mesh.vertices, incoherent)):
            for precision in ("float64", "float32"):
                origins, directions = rays.of(precision)
                times = {constants: [] for constants in VARIANTS}
                hits = {}
                for run in range(RUNS + 1):
                    for constants in (VARIANTS if run % 2 else VARIANTS[::-1]):
                        _, faces, wide, _ = trees[constants]
                        vertices, tree = wide[precision]
                        t = np.empty(len(origins), dtype=origins.dtype)
                        face = np.empty(len(origins), dtype=np.int64)
                        start = time.perf_counter()
                        closest_hits(vertices, faces, tree.nodes, tree.links, origins, directions, t, face)
                        if run:
                            times[constants].append(time.perf_counter() - start)
                        hits[constants] = (t, face)
                for constants in VARIANTS:
                    if not (np.array_equal(hits[constants][0], hits[VARIANTS[0]][0])
                            and np.array_equal(hits[constants][1], hits[VARIANTS[0]][1])):
                        sys.exit("%s gives other hits than %s" % (constants, VARIANTS[0]))
                    rates[constants, rays.name.split()[-1], precision] = \
                        len(origins) / statistics.median(times[constants])
        n = len(mesh.faces)
        for constants in VARIANTS:
            bvh, faces, wide, seconds = trees[constants]
            size = {p: (tree.nbytes + faces.nbytes + vertices.nbytes) / n for p, (vertices, tree) in wide.items()}
            chosen = " (chosen)" if constants == VARIANTS[0] else ""
            print("| %s | %g%s | %d | %d | %.3f | %d | %d | %.1f / %.1f | %.3g s | %s |" % (
                mesh.name, constants[0], chosen, constants[1], constants[2], bvh.num_nodes / n,
                count_nodes(wide["float32"][1]), count_blocks(wide["float32"][1]), size["float64"],
                size["float32"], seconds,
                " | ".join("%.2f M/s" % (rates[constants, r, p] / 1e6) for r in ("primary", "incoherent")
                           for p in ("float64", "float32"))))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
