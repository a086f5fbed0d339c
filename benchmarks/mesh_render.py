"""What a mesh costs through ``rtfgu.render``: the table "A mesh through rtfgu.render" of
docs/meshes.md.

    python benchmarks/mesh_render.py SUBDIVISIONS [--triangles] [--size N] [--precision P] [--save IMAGE.npy]

One displaced icosphere (benchmarks/meshes.py's displaced_icosphere; 6 subdivisions: 81 920
triangles, 8: 1 310 720) in a scene of one Matte mesh and one point light, seen by a pinhole
camera, rendered with the numba backend in float64 (or ``--precision float32``) at N x N (128),
one sample per pixel.
The scene holds the Mesh itself, or with ``--triangles`` its faces (``mesh.triangles()``,
the only way before a scene could hold a Mesh). Printed, in seconds, as one JSON line:

    construct   Mesh(...) and the scene (with --triangles: the MeshTriangle per face);
    first       the first rtfgu.render: compile_scene (the packing and the BVH build) and
                the trace;
    second      rtfgu.render of the same scene again;
    kernel      one call of a NumbaAccumulator made beforehand: the trace alone.

numba compiles the kernels before anything is timed (a render of a 80-face icosphere).
``--save`` writes the first image, so that two runs (another commit, --triangles) can be
compared pixel by pixel. One run, one timing each: a measurement to read, not a test.
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

import rtfgu  # noqa: E402
from rtfgu.float3 import Float3  # noqa: E402
from rtfgu.kernels import NumbaAccumulator  # noqa: E402

from meshes import displaced_icosphere  # noqa: E402


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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("subdivisions", type=int)
    parser.add_argument("--triangles", action="store_true", help="hold mesh.triangles(), not the Mesh")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--save", help="write the first image to this .npy file")
    parser.add_argument("--precision", default="float64", choices=("float64", "float32"))
    args = parser.parse_args()
    size = args.size

    warm = displaced_icosphere(1)
    rtfgu.render(mesh_scene(rtfgu.Mesh(warm.vertices, warm.faces, (0.8, 0.8, 0.8), material=rtfgu.Matte()),
                            args.triangles), 16, 16, backend="numba", precision=args.precision)

    arrays = displaced_icosphere(args.subdivisions)
    scene, construct = timed(lambda: mesh_scene(
        rtfgu.Mesh(arrays.vertices, arrays.faces, (0.8, 0.8, 0.8), material=rtfgu.Matte()), args.triangles))
    first_image, first = timed(rtfgu.render, scene, size, size, backend="numba", precision=args.precision)
    second_image, second = timed(rtfgu.render, scene, size, size, backend="numba", precision=args.precision)
    accumulate = NumbaAccumulator(scene, size, size, args.precision)
    kernel_image, kernel = timed(accumulate, (0, 1))
    if args.save:
        np.save(args.save, first_image)
    print(json.dumps({"triangles": len(arrays.faces), "held": "triangles" if args.triangles else "Mesh",
                      "precision": args.precision, "size": size,
                      "construct": construct, "first": first, "second": second, "kernel": kernel,
                      "same_images": bool(np.array_equal(first_image, second_image)
                                          and np.array_equal(first_image, kernel_image))}))


if __name__ == "__main__":
    main()
