"""A single ray's time in rtfgu's wide tree beside Embree's, one thread, the same rays, one
process: the table of docs/bvh.md, "Embree's loop on the same rays".

    python benchmarks/one_thread_embree.py [--meshes bunny 5 8] [--runs 7]

Each mesh of benchmarks/meshes.py (the bunny, or the displaced icosphere of that many
subdivisions) is built by rtfgu numba (its float32 wide tree with blocks, as a render's) and
by embreex in its fast (``robust=False``) and robust modes; its 1024x1024 primary rays and
1 M incoherent rays are traced by rtfgu.kernels.mesh.mesh_closest (through meshes.py's
``closest_hits``, numba on one thread) and by Embree's rtcIntersect1 on one thread, ``--runs``
times round-robin. The ns a ray are medians; with Embree in the same process, the ratio of
the two moves less from process to process than either time (docs/bvh.md, "Measuring").
Also printed: the share of rays whose face Embree fast and rtfgu agree on (a faster path
that finds other faces is not faster).

Needs the bench extra (embreex): ``make .venv/.installed-bench``. A measurement to read, not
a test.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np
from numba import set_num_threads

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

import meshes  # noqa: E402


def mesh_of(name: str):
    return meshes.bunny() if name == "bunny" else meshes.displaced_icosphere(int(name))


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", nargs="+", default=["bunny", "5", "8"],
                        help="bunny, or a displaced icosphere's subdivisions (5: 20480 triangles, 8: 1.31 M)")
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args(argv)
    set_num_threads(1)
    print("| mesh | rays | rtfgu | Embree fast | Embree robust | rtfgu / Embree fast (speed) | faces as Embree fast's |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for name in args.meshes:
        mesh = mesh_of(name)
        rtfgu = meshes.Rtfgu(1)
        rtfgu.build(mesh)
        fast, robust = meshes.Embree(1, robust=False), meshes.Embree(1, robust=True)
        fast.build(mesh)
        robust.build(mesh)
        tree = rtfgu.wide["float32"]
        for kind in ("primary", "incoherent"):
            rays = (meshes.primary_rays(mesh.vertices, 1024) if kind == "primary"
                    else meshes.incoherent_rays(mesh.vertices, 1 << 20))
            origins, directions = rays.of("float32")
            n = len(origins)
            t = np.empty(n, np.float32)
            face = np.empty(n, np.int64)
            hits = (rtfgu.vertices["float32"], rtfgu.faces4, tree.nodes, tree.links, origins, directions, t, face)
            meshes.closest_hits(*hits)
            same = float(np.mean(fast.trace(rays, 1)[1] == face))
            times = {"rtfgu": [], "fast": [], "robust": []}
            for _ in range(args.runs):
                for label, run in (("rtfgu", lambda: meshes.closest_hits(*hits)),
                                   ("fast", lambda: fast.trace(rays, 1)),
                                   ("robust", lambda: robust.trace(rays, 1))):
                    start = time.perf_counter()
                    run()
                    times[label].append(time.perf_counter() - start)
            ns = {label: 1e9 * statistics.median(v) / n for label, v in times.items()}
            print("| %s | %s | %.0f | %.0f | %.0f | %.2fx | %.4f |" % (
                name, kind, ns["rtfgu"], ns["fast"], ns["robust"], ns["fast"] / ns["rtfgu"], same))


if __name__ == "__main__":
    main()
