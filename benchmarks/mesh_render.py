"""What a mesh costs through ``rtfgu.render``: the table "A mesh through rtfgu.render" of
docs/meshes.md.

    python benchmarks/mesh_render.py SUBDIVISIONS [--bunny] [--triangles] [--size N] [--precision P]
                                              [--cold] [--save IMAGE.npy]

One displaced icosphere (benchmarks/meshes.py's displaced_icosphere; 6 subdivisions: 81 920
triangles, 8: 1 310 720), or with ``--bunny`` the Stanford bunny (SUBDIVISIONS unused), in a
scene of one Matte mesh and one point light, seen by a pinhole camera, rendered with the
numba backend in float64 (or ``--precision float32``) at N x N (128), one sample per pixel.
The scene holds the Mesh itself, or with ``--triangles`` its faces (``mesh.triangles()``,
the only way before a scene could hold a Mesh). Printed, in seconds, as one JSON line:

    construct   Mesh(...) and the scene (with --triangles: the MeshTriangle per face);
    first       the first rtfgu.render: compile_scene (the packing and the BVH build) and
                the trace;
    second      rtfgu.render of the same scene again (the median of ``--runs``, 1), each
                image dropped before the next render;
    kernel      NumbaAccumulator.add on one made beforehand: the kernel alone, its sums
                (of one sample, the image) not made an image (the median of ``--runs``).
    layout      the first render's layout and build alone: compile_scene and the kernel's
                arguments (the wide tree's collapse) of a new scene holding a new Mesh of
                the same arrays, so nothing is cached (the median of ``--runs`` or more:
                meshes.repeated, as the builds of benchmarks/meshes.py).

numba compiles the kernels before anything is timed (a render of a 80-face icosphere); with
``--cold`` it does not, and ``first`` includes loading the compiled kernels from numba's
cache on disk (what a new Python session pays once the kernels were ever compiled).
In float32 the image is compared with the float64 render of the same scene: ``differing``,
the share of pixels with a channel more than 1e-6 apart, and ``largest``, the largest
difference. ``--save`` writes the first image, so that two runs (another commit,
--triangles) can be compared pixel by pixel. One run, one timing each: a measurement to
read, not a test (benchmarks/meshes.py runs it for docs/bench.md).
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

import rtfgu  # noqa: E402
from rtfgu.float3 import Float3  # noqa: E402
from rtfgu.accelerators import flat_bvh  # noqa: E402
from rtfgu.kernels import NumbaAccumulator, kernel_arguments  # noqa: E402
from rtfgu.layout import compile_scene  # noqa: E402

from meshes import bunny, displaced_icosphere, repeated  # noqa: E402


def mesh_scene(mesh: rtfgu.Mesh, as_triangles: bool) -> rtfgu.Scene:
    scene = rtfgu.Scene(rtfgu.PinholeCamera(Float3(1.05, -0.9, -3.0), Float3(0.0), Float3(0, 1, 0), 1.0))
    if as_triangles:
        scene.shapes += mesh.triangles()
    else:
        scene.shapes.append(mesh)
    scene.lights.append(rtfgu.PointLight(Float3(2, 3, -4), Float3(1.0)))
    return scene


def timed(function, *args, **kwargs):
    start = time.perf_counter()
    result = function(*args, **kwargs)
    return result, time.perf_counter() - start


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("subdivisions", type=int)
    parser.add_argument("--bunny", action="store_true", help="the bunny, not an icosphere")
    parser.add_argument("--triangles", action="store_true", help="hold mesh.triangles(), not the Mesh")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--save", help="write the first image to this .npy file")
    parser.add_argument("--precision", default="float64", choices=("float64", "float32"))
    parser.add_argument("--cold", action="store_true", help="no warm-up render before the timing")
    parser.add_argument("--runs", type=int, default=1, help="renders of the second and kernel timings")
    args = parser.parse_args(argv)
    size = args.size

    if not args.cold:
        warm = displaced_icosphere(1)
        rtfgu.render(mesh_scene(rtfgu.Mesh(warm.vertices, warm.faces, (0.8, 0.8, 0.8), material=rtfgu.Matte()),
                                args.triangles), 16, 16, backend="numba", precision=args.precision)
        # The build's parallel part splits only nodes of more than its task size (at most
        # TASK_MIN primitives): the small mesh built once more with TASK_MIN lowered, so that
        # "compiled before" holds for its functions too (numba compiles them, or loads them
        # from its cache, once).
        task_min, flat_bvh.TASK_MIN = flat_bvh.TASK_MIN, 16
        try:
            corners = warm.vertices[warm.faces]
            flat_bvh.build(corners.min(axis=1), corners.max(axis=1))
        finally:
            flat_bvh.TASK_MIN = task_min

    arrays = bunny() if args.bunny else displaced_icosphere(args.subdivisions)
    scene, construct = timed(lambda: mesh_scene(
        rtfgu.Mesh(arrays.vertices, arrays.faces, (0.8, 0.8, 0.8), material=rtfgu.Matte()), args.triangles))
    first_image, first = timed(rtfgu.render, scene, size, size, backend="numba", precision=args.precision)
    # Each image is dropped before the next call (a user's loop that shows or saves a frame):
    # images kept would each be new memory from the system, whose first touch took 48-53 ms
    # per 1024 x 1024 float64 image on the machine of docs/bench.md's run (docs/bvh.md).
    second_image, times = None, []
    for _ in range(max(1, args.runs)):
        image, seconds = timed(rtfgu.render, scene, size, size, backend="numba", precision=args.precision)
        second_image = image if second_image is None else second_image
        del image
        times.append(seconds)
    second = statistics.median(times)
    accumulate = NumbaAccumulator(scene, size, size, args.precision)
    kernel = statistics.median(timed(accumulate.add, (0, 1))[1] for _ in range(max(1, args.runs)))
    kernel_image = accumulate.sums

    def layout():
        fresh = mesh_scene(rtfgu.Mesh(arrays.vertices, arrays.faces, (0.8, 0.8, 0.8), material=rtfgu.Matte()),
                           args.triangles)
        start = time.perf_counter()
        kernel_arguments(compile_scene(fresh, args.precision), size, size)
        return time.perf_counter() - start
    layout_time = statistics.median(repeated(layout, max(1, args.runs)))
    if args.save:
        np.save(args.save, first_image)
    result = {"mesh": arrays.name, "triangles": len(arrays.faces),
              "held": "triangles" if args.triangles else "Mesh", "precision": args.precision,
              "size": size, "cold": args.cold, "construct": construct, "first": first,
              "second": second, "kernel": kernel, "layout": layout_time,
              "same_images": bool(np.array_equal(first_image, second_image)
                                  and np.array_equal(first_image, kernel_image))}
    if args.precision != "float64":
        reference = rtfgu.render(scene, size, size, backend="numba", precision="float64")
        difference = np.abs(first_image - reference)
        result.update(differing=float(np.mean(np.any(difference > 1e-6, axis=2))),
                      largest=float(difference.max()))
    print(json.dumps(result))


if __name__ == "__main__":
    main()
