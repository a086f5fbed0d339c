"""The SAH's cost constants against speed and size: the numba BVH of the 1.3-million-triangle
icosphere and of the bunny of benchmarks/meshes.py, built with C_TRAVERSE in COSTS (and
C_INTERSECT 1), each traced with the same primary and incoherent rays. Prints the markdown
table of docs/bvh.md, "Cost constants". A script, not a test: nothing is asserted.

    python benchmarks/bvh_costs.py [--quick]

Time: the median of RUNS rounds after a warm-up, a round tracing with every tree once
(round-robin). Every tree must give every ray the same face and t: the constants change
the tree, never the hit (checked, and the script stops if not).
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

from rtfgu.accelerators import flat_bvh  # noqa: E402
from rtfgu.accelerators.flat_bvh import C_TRAVERSE  # noqa: E402

from meshes import (ICOSPHERE_SUBDIVISIONS, INCOHERENT, PRIMARY, QUICK_INCOHERENT,  # noqa: E402
                    QUICK_PRIMARY, QUICK_SUBDIVISIONS, bunny, closest_hits, displaced_icosphere,
                    incoherent_rays, primary_rays)

COSTS = (1.0, 1.5, 2.0, 3.0)
RUNS = 3


def build(lo, hi, c_traverse):
    """flat_bvh.build with another C_TRAVERSE (a module constant its build reads when it
    runs): (nodes, order, seconds)."""
    saved, flat_bvh.C_TRAVERSE = flat_bvh.C_TRAVERSE, c_traverse
    try:
        bvh = flat_bvh.build(lo, hi)
    finally:
        flat_bvh.C_TRAVERSE = saved
    return bvh.nodes, bvh.order, bvh.build_seconds


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small meshes and few rays")
    args = parser.parse_args(argv)
    meshes = [displaced_icosphere(QUICK_SUBDIVISIONS if args.quick else ICOSPHERE_SUBDIVISIONS), bunny()]
    primary, incoherent = (QUICK_PRIMARY, QUICK_INCOHERENT) if args.quick else (PRIMARY, INCOHERENT)
    print("| mesh | C_TRAVERSE | nodes per triangle | bytes per triangle (float64 / float32) | build | "
          "primary float64 | primary float32 | incoherent float64 | incoherent float32 |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for mesh in meshes:
        lo, hi = flat_bvh.triangle_bounds(mesh.vertices, mesh.faces)
        trees = {}
        for cost in COSTS:
            build(lo, hi, cost)  # the warm-up (numba's compile)
            nodes, order, seconds = build(lo, hi, cost)
            faces = np.empty((len(order), 4), dtype=np.int32)
            faces[:, :3], faces[:, 3] = mesh.faces[order], order
            trees[cost] = (nodes, faces, seconds)
        rates = {}
        for rays in (primary_rays(mesh.vertices, primary), incoherent_rays(mesh.vertices, incoherent)):
            for precision in ("float64", "float32"):
                origins, directions = rays.of(precision)
                vertices = np.ascontiguousarray(mesh.vertices, dtype=origins.dtype)
                times = {cost: [] for cost in COSTS}
                hits = {}
                for run in range(RUNS + 1):
                    for cost in COSTS:
                        nodes, faces, _ = trees[cost]
                        t = np.empty(len(origins), dtype=origins.dtype)
                        face = np.empty(len(origins), dtype=np.int64)
                        start = time.perf_counter()
                        closest_hits(vertices, faces, nodes, nodes.view(np.int32), origins, directions, t, face)
                        if run:
                            times[cost].append(time.perf_counter() - start)
                        hits[cost] = (t, face)
                for cost in COSTS:
                    if not (np.array_equal(hits[cost][0], hits[COSTS[0]][0])
                            and np.array_equal(hits[cost][1], hits[COSTS[0]][1])):
                        sys.exit("C_TRAVERSE %g gives other hits than %g" % (cost, COSTS[0]))
                    rates[cost, rays.name.split()[-1], precision] = len(origins) / statistics.median(times[cost])
        n = len(mesh.faces)
        for cost in COSTS:
            nodes, faces, seconds = trees[cost]
            size = {p: (nodes.nbytes + faces.nbytes + len(mesh.vertices) * 3 * b) / n
                    for p, b in (("float64", 8), ("float32", 4))}
            chosen = " (chosen)" if cost == C_TRAVERSE else ""
            print("| %s | %g%s | %.3f | %.1f / %.1f | %.3g s | %s |" % (
                mesh.name, cost, chosen, len(nodes) / n, size["float64"], size["float32"], seconds,
                " | ".join("%.2f M/s" % (rates[cost, r, p] / 1e6) for r in ("primary", "incoherent")
                           for p in ("float64", "float32"))))


if __name__ == "__main__":
    main()
