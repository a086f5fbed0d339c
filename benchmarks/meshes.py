"""The mesh section of docs/bench.md: rtfgu's BVH over triangle meshes, on the numba path and
on the WGSL path (on wgpu's adapter: Mesa's llvmpipe where there is no GPU), against Embree
(through embreex) and Mitsuba 3, on the same meshes and the same rays, in one run; and
Mitsuba 3 on the 64 spheres of the first table. Writes the plot docs/bench_meshes.png.

``benchmarks/bench.py`` puts ``meshes_section()`` into docs/bench.md; run alone,

    python benchmarks/meshes.py [--quick] [--peers wgsl,wgsl-wide,embree,mitsuba]
                                [--wgsl-rays N] [--out FILE]

measures this section only and replaces it in docs/bench.md (or FILE: the text between START
and END; appended when the file has none). --peers runs only the peers named beside rtfgu
numba (the others are named as not chosen); --wgsl-rays sets WGSL_RAYS. A script, not a
test: nothing is asserted, and a peer that cannot be installed or run is named in the
section with the reason instead of a figure (so is the WGSL path where wgpu has no adapter,
or where a mesh's buffers exceed the adapter's storage binding size).

This section times the traversal on given rays. What a mesh costs through ``rtfgu.render``
(the scene compiled, its BVH built, an image traced) is benchmarks/mesh_render.py's
(docs/meshes.md, "A mesh through rtfgu.render").

Meshes (MESHES): an icosphere subdivided ICOSPHERE_SUBDIVISIONS times (1.3 M triangles) whose
vertices are moved along their radius by a smooth, seeded noise (displaced_icosphere), and
the Stanford bunny shipped with rtfgu. Rays, per mesh (RAY_SETS), float64 and seeded:
PRIMARY x PRIMARY primary rays of a pinhole camera whose square view the mesh fills, and
INCOHERENT rays from points uniform in the mesh's bounding box in directions uniform on the
sphere. Every ray is a unit direction, so t is a distance; tmin = 0, tmax = inf; closest hit.
The float32 paths (rtfgu float32, rtfgu WGSL, Embree, Mitsuba) get the same rays rounded to
float32 and the vertices rounded to float32; rtfgu float64 gets the float64 ones.

The paths (``System.paths``):
  rtfgu numba    rtfgu.accelerators.flat_bvh.build over the faces' boxes, the faces permuted
                 into leaf order, and rtfgu.kernels.mesh.mesh_closest called per ray by a
                 prange kernel (closest_hits); float64 and float32 on the one node table.
  rtfgu numba packets  the same wide tree and faces, a camera's rays traced 4 x 4 neighbours
                 at a time (closest_hits_packets, rtfgu.kernels.packet.mesh_closest_packet),
                 float64 and float32; on the primary rays only (incoherent rays are not a camera's
                 tiles: the row says so). Each tile's rays are copied into a packet and
                 their t and face back, within the timed call.
  rtfgu WGSL     the same build's node table, faces and float32 vertices in storage buffers
                 and rtfgu/wgsl/intersect_mesh.wgsl's mesh_closest (the render's traversal)
                 called per ray by a small entry point (WGSL_MAIN), assembled and compiled
                 by rtfgu/wgsl/harness.py (batch_program, compile_batch) on the render's
                 device (rtfgu.wgsl.device: a GPU when there is one, else llvmpipe); the rays
                 go in dispatches of at most WGSL_BATCH (and what one storage binding holds),
                 one submit each, into one result buffer read back at the end. The row's
                 note names the adapter; its threads are "-" (the adapter's own). WGSL_RAYS,
                 when set, limits it to the first rays of a set.
  rtfgu WGSL wide  an experiment, not the render's traversal: the numba path's wide tree
                 (FlatBVH.wide, its (N, 7, 8) float32 nodes uploaded as they are) traversed
                 by benchmarks/wgsl_wide_bvh.wgsl with intersect_mesh.wgsl's face test and
                 leaf loop (cut from that file, wgsl_cut), through the same harness, rays and
                 timing as rtfgu WGSL (tests/test_wgsl_wide_bvh.py: the same face and t).
  Embree         embreex.rtcore_scene.EmbreeScene (robust=True) with one
                 embreex.mesh_construction.TriangleMesh; ``scene.run(origins, directions,
                 output=1)`` traces its rays one by one (rtcIntersect1) without the GIL, so
                 the rays are cut into EMBREE_CHUNKS parts run on numba's thread count of
                 Python threads; a second row runs it on one thread. Embree is the reference
                 of the error columns.
  Mitsuba 3      ``llvm_ad_rgb`` (``scalar_rgb`` when the LLVM backend is missing: the rays are
                 then traced one by one from Python, on the first SCALAR_RAYS rays only): one
                 mi.Mesh filled from the arrays (vertex_positions, faces) in a scene of
                 mi.load_dict, and ``scene.ray_intersect_preliminary`` on all rays at once.

Timing: every path is run once first (the warm-up: numba and Dr.Jit compile then), then RUNS
rounds time each path once (round-robin, so a change in the machine's load hits all alike),
in an order shuffled per round (seeded) so that no path always follows the same other one,
and each time is the second of two calls in a row (second_call: the first wakes the threads
and fills the caches that the path before left to another system); the median is quoted.
A time covers tracing the rays and returning t and the face: not making the rays, nor
turning them into Dr.Jit arrays for Mitsuba, nor uploading them for WGSL (done once, before
the timing; WGSL's timed part is its dispatches and the readback of the
results, and its pipeline is compiled before anything is timed). Build: from the vertex and
face arrays to a structure ready to trace, median of BUILD_RUNS or more (as many as fit in
BUILD_SECONDS) after a warm-up build; rtfgu:
triangle_rows + flat_bvh.build_rows (as compile_scene builds) + the permuted faces (WGSL: and their upload to the
adapter); Embree: a new scene, TriangleMesh and the commit (done by the first ``run``, of one
ray); Mitsuba: mi.Mesh, its buffers and mi.load_dict. Bytes per triangle: rtfgu's node table
+ the (F, 4) int32 faces + the vertices, over the triangles; the peers do not say what they
keep.

Error against Embree (reported, not asserted): the share of rays that one path hits and the
other misses; of rays both hit, the share hitting another face, and of those the share whose
t differs by more than TOL relative (another surface, not a shared edge or vertex); the
largest relative difference in t on rays that hit the same face, and on all rays both hit.
Embree computes in float32, so float32 rounding is in every difference.

The 64 spheres (bench.py's random_spheres_64 at 1024 x 1024): rtfgu.render with the numba
backend (the figure of the first table: it makes the rays and writes the image too) and the
spheres-only kernel of benchmarks/spheres_only.py, against Mitsuba's
``ray_intersect_preliminary`` on 64 ``sphere`` shapes and the camera's primary rays (made by
rtfgu.kernels.camera.gen_ray, rounded to float32), timed the same way. Error: the share of
pixels whose sphere (or background) differs from the numba float64 render.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import random
import statistics
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from importlib import metadata
from pathlib import Path
from typing import Callable

import numpy as np
from numba import njit, prange

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE))

from rtfgu.accelerators import flat_bvh  # noqa: E402
from rtfgu.kernels.camera import gen_ray  # noqa: E402
from rtfgu.kernels.float3 import lit  # noqa: E402
from rtfgu.kernels.mesh import mesh_closest  # noqa: E402
from rtfgu.kernels.packet import PACKET, mesh_closest_packet  # noqa: E402

from bench import cpu_model, replace_section  # noqa: E402

START = "<!-- meshes section: benchmarks/meshes.py -->"
END = "<!-- end of meshes section -->"

ICOSPHERE_SUBDIVISIONS, QUICK_SUBDIVISIONS = 8, 4
NOISE_SEED, RAY_SEED = 2562, 1
PRIMARY, QUICK_PRIMARY = 1024, 128
INCOHERENT, QUICK_INCOHERENT = 1 << 20, 1 << 14
RUNS = 5
# A render of the 64 spheres takes about 10 ms, whose time moves by a third between calls:
# its rows take more rounds (each costs about 0.1 s).
SPHERE_RUNS = 25
BUILD_RUNS = 3
# A build is timed BUILD_RUNS times at least and as many more as fit in BUILD_SECONDS (at most
# BUILD_MOST): a small mesh's build takes a few milliseconds, by which this machine moves one
# call from the next, so its median takes more calls than a large mesh's (repeated()).
BUILD_SECONDS = 0.5
BUILD_MOST = 101
TOL = 1e-4
EMBREE_CHUNKS = 64
SCALAR_RAYS = 1 << 16
WGSL_BATCH = 1 << 16  # rays per dispatch of the WGSL path (fewer if the adapter's limits say so)
WGSL_RAYS = None      # the WGSL path traces only this many first rays of a set (None: all)
SPHERE_SIZE, QUICK_SPHERE_SIZE = 1024, 128


def version(package: str) -> str:
    try:
        return metadata.version(package)
    except metadata.PackageNotFoundError:
        return "not installed"


# ---- meshes and rays --------------------------------------------------------------------

@dataclass
class MeshArrays:
    name: str
    vertices: np.ndarray  # (V, 3) float64
    faces: np.ndarray     # (F, 3) int64
    about: str


def displaced_icosphere(subdivisions: int, seed: int = NOISE_SEED) -> MeshArrays:
    """trimesh's icosphere with each vertex p moved to p (1 + n(p)): n is 0.1 times a sum of
    12 plane waves 0.3 / k sin(k f.p + phase) of seeded directions f and wave numbers k in
    [2, 8], so the surface stays smooth (|grad n| <= 0.03 per wave) and no face loses its
    area."""
    import trimesh
    sphere = trimesh.creation.icosphere(subdivisions=subdivisions)
    p = np.asarray(sphere.vertices, dtype=np.float64)
    rng = np.random.default_rng(seed)
    f = rng.normal(size=(12, 3))
    f /= np.linalg.norm(f, axis=1)[:, None]
    k = rng.uniform(2.0, 8.0, 12)
    phase = rng.uniform(0.0, 2.0 * math.pi, 12)
    noise = (0.3 / k * np.sin(k * (p @ f.T) + phase)).sum(axis=1) * 0.1
    faces = np.asarray(sphere.faces, dtype=np.int64)
    return MeshArrays("displaced icosphere", p * (1.0 + noise)[:, None], faces,
                      "trimesh.creation.icosphere(subdivisions=%d), radially displaced by a "
                      "seeded smooth noise (displaced_icosphere, seed %d)" % (subdivisions, seed))


def bunny() -> MeshArrays:
    from rtfgu.obj import load_obj, mesh_path
    mesh = load_obj(mesh_path("bunny.obj"))
    return MeshArrays("bunny", np.asarray(mesh.vertices, dtype=np.float64),
                      np.asarray(mesh.faces, dtype=np.int64),
                      "the Stanford bunny shipped with rtfgu (rtfgu/meshes/bunny.obj)")


@dataclass
class Rays:
    name: str
    origins: np.ndarray     # (n, 3) float64
    directions: np.ndarray  # (n, 3) float64, unit
    grid: int = 0           # a camera's grid x grid rays, row by row; 0: not a camera's
    origins32: np.ndarray = field(init=False)
    directions32: np.ndarray = field(init=False)

    def __post_init__(self):
        self.origins32 = np.ascontiguousarray(self.origins, dtype=np.float32)
        self.directions32 = np.ascontiguousarray(self.directions, dtype=np.float32)

    def of(self, precision: str):
        if precision == "float64":
            return self.origins, self.directions
        return self.origins32, self.directions32

    def __len__(self):
        return len(self.origins)


def normalized(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def primary_rays(vertices: np.ndarray, size: int, view=(0.35, -0.3, -1.0)) -> Rays:
    """size x size rays of a pinhole camera looking along ``view`` at the centre of the
    mesh's box from 2.5 box diagonals away, with the narrowest square view that holds every
    vertex: the mesh touches two opposite edges of the image. Row 0 is the top."""
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    w = normalized(np.asarray(view, dtype=np.float64))
    eye = (lo + hi) / 2 - w * 2.5 * np.linalg.norm(hi - lo)
    u = normalized(np.cross(w, (0.0, 1.0, 0.0)))
    v = np.cross(u, w)
    rel = vertices - eye
    depth = rel @ w
    half = max(np.abs(rel @ u / depth).max(), np.abs(rel @ v / depth).max())
    s = (2 * (np.arange(size) + 0.5) / size - 1) * half
    sx, sy = np.meshgrid(s, -s)
    directions = normalized(sx[..., None] * u + sy[..., None] * v + w).reshape(-1, 3)
    return Rays("%dx%d primary" % (size, size), np.broadcast_to(eye, directions.shape).copy(),
                directions, size)


def incoherent_rays(vertices: np.ndarray, count: int, seed: int = RAY_SEED) -> Rays:
    """Origins uniform in the mesh's box, directions uniform on the sphere (normalised
    Gaussians)."""
    rng = np.random.default_rng(seed)
    origins = rng.uniform(vertices.min(axis=0), vertices.max(axis=0), (count, 3))
    return Rays("%s incoherent" % count_label(count), origins,
                normalized(rng.normal(size=(count, 3))))


def count_label(n: int) -> str:
    """1048576 -> "1 M", 16384 -> "16 k"."""
    if n % (1 << 20) == 0:
        return "%d M" % (n >> 20)
    if n % (1 << 10) == 0:
        return "%d k" % (n >> 10)
    return str(n)


# ---- the paths --------------------------------------------------------------------------

@dataclass
class Path_:
    """One way to trace: ``prepare(rays)`` once, untimed; ``run(prepared)`` is timed;
    ``result(raw)`` gives t (inf on a miss) and the face index (-1) as numpy arrays."""
    system: str
    precision: str
    threads: int
    run: Callable
    prepare: Callable = None
    result: Callable = None
    note: str = ""
    device: str = ""  # the adapter a GPU path runs on (its threads are then 0: not a count)

    @property
    def label(self) -> str:
        return "%s %s" % (self.system, self.precision)


class System:
    """A ray tracer under test: ``build(mesh)`` makes its structure and returns the seconds
    it took (the last build is kept); ``paths()`` traces with it."""
    name = ""
    about = ""

    def build(self, mesh: MeshArrays) -> float:
        raise NotImplementedError

    def paths(self) -> list:
        raise NotImplementedError

    def bytes_per_triangle(self) -> dict:
        return {}

    def build_note(self) -> str:
        return ""


@njit(parallel=True, error_model="numpy")
def closest_hits(vertices, faces4, nodes, links, origins, directions, t_out, face_out):
    """The nearest face of every ray (origins[i], directions[i]) in [0, inf): its t (inf on
    a miss) and its index in the mesh's face list (-1)."""
    for i in prange(origins.shape[0]):
        origin = (origins[i, 0], origins[i, 1], origins[i, 2])
        direction = (directions[i, 0], directions[i, 1], directions[i, 2])
        tmin = lit(0, origins[i, 0])
        # no spheres in the BVH (None), formula 0 (used by spheres only)
        hit = mesh_closest(vertices, faces4, nodes, links, None, origin, direction, tmin,
                           (lit(math.inf, tmin), -1, -1, -1), 0)
        t_out[i] = hit[0]
        face_out[i] = hit[1]


# A packet: TILE_W x TILE_H neighbouring rays of a camera's grid (PACKET of them).
TILE_W = TILE_H = 4
assert TILE_W * TILE_H == PACKET


@njit(parallel=True, error_model="numpy")
def closest_hits_packets(vertices, faces4, nodes, links, origins, directions, size, t_out, face_out):
    """closest_hits for a camera's size x size rays (row by row) on the wide tree, traced as
    packets of the TILE_W x TILE_H rays of a tile (rtfgu.kernels.packet): each tile's rays
    are copied into a packet, traced, and their t and face copied back. A thread takes a
    block of rows of tiles and its packet buffers once."""
    tiles_x = (size + TILE_W - 1) // TILE_W
    tiles_y = (size + TILE_H - 1) // TILE_H
    blocks = min(tiles_y, 64)
    tmin = lit(0, origins[0, 0])
    for b in prange(blocks):
        o = np.empty(3 * PACKET, dtype=origins.dtype)
        d = np.empty(3 * PACKET, dtype=origins.dtype)
        t = np.empty(PACKET, dtype=origins.dtype)
        best = np.empty(PACKET, dtype=np.int64)
        kind = np.empty(PACKET, dtype=np.int64)
        row = np.empty(PACKET, dtype=np.int64)
        for ty in range(b * tiles_y // blocks, (b + 1) * tiles_y // blocks):
            for tx in range(tiles_x):
                count = 0
                for y in range(ty * TILE_H, min(ty * TILE_H + TILE_H, size)):
                    for x in range(tx * TILE_W, min(tx * TILE_W + TILE_W, size)):
                        r = y * size + x
                        for a in range(3):
                            o[3 * count + a] = origins[r, a]
                            d[3 * count + a] = directions[r, a]
                        t[count] = math.inf
                        best[count] = -1
                        kind[count] = -1
                        row[count] = -1
                        count += 1
                # no spheres in the BVH (None), formula 0 (used by spheres only)
                mesh_closest_packet(vertices, faces4, nodes, links, None, (o, d, count, tmin), (t, best, kind, row), 0)
                count = 0
                for y in range(ty * TILE_H, min(ty * TILE_H + TILE_H, size)):
                    for x in range(tx * TILE_W, min(tx * TILE_W + TILE_W, size)):
                        t_out[y * size + x] = t[count]
                        face_out[y * size + x] = best[count]
                        count += 1


def bvh_of(mesh: MeshArrays):
    """rtfgu's BVH over the mesh's faces and the (F, 4) faces in its leaf order, each with
    its index in the mesh's face list (what rtfgu.layout.compile_scene makes of a mesh)."""
    bvh = flat_bvh.build_rows(flat_bvh.triangle_rows(mesh.vertices, mesh.faces))
    faces4 = np.empty((len(mesh.faces), 4), dtype=np.int32)
    faces4[:, :3] = mesh.faces[bvh.order]
    faces4[:, 3] = bvh.order
    return bvh, faces4


def _reached(wide):
    """(nodes, block codes) reached from the wide tree's roots."""
    from rtfgu.accelerators.wide_bvh import BLOCK_BIT, CODE_ROW, WIDTH
    links, stack, nodes, blocks = wide.links, list(wide.roots), 0, 0
    while stack:
        n = stack.pop()
        nodes += 1
        for j in range(WIDTH):
            code = int(links[n, CODE_ROW, j])
            if np.isfinite(wide.nodes[n, 0, j]):
                if code >= 0:
                    stack.append(code)
                elif (~code) >> BLOCK_BIT:
                    blocks += 1
    return nodes, blocks


def count_nodes(wide):
    return _reached(wide)[0]


def count_blocks(wide):
    return _reached(wide)[1]


class Rtfgu(System):
    name = "rtfgu numba"

    def __init__(self, threads):
        self.threads = threads
        self.tree_seconds = []

    def build(self, mesh):
        if getattr(self, "mesh", None) is not mesh:
            self.mesh, self.tree_seconds = mesh, []
        start = time.perf_counter()
        bvh, faces4 = bvh_of(mesh)
        wide = bvh.wide()
        self.vertices = {"float64": np.ascontiguousarray(mesh.vertices, dtype=np.float64),
                         "float32": np.ascontiguousarray(mesh.vertices, dtype=np.float32)}
        blocks_start = time.perf_counter()
        # The tree each precision's render traverses (rtfgu.kernels.render.numba_tree).
        self.wide = {p: bvh.wide_with_blocks((0,), self.vertices[p], faces4) for p in ("float64", "float32")}
        seconds = time.perf_counter() - start
        self.tree_seconds.append((bvh.build_seconds, wide.build_seconds, time.perf_counter() - blocks_start))
        self.bvh, self.faces4 = bvh, faces4
        return seconds

    def paths(self):
        def path(precision, nodes, note=""):
            def run(rays):
                origins, directions = rays.of(precision)
                t = np.empty(len(origins), dtype=origins.dtype)
                face = np.empty(len(origins), dtype=np.int64)
                closest_hits(self.vertices[precision], self.faces4, nodes, nodes.view(np.int32), origins, directions,
                             t, face)
                return t, face
            return Path_(self.name, precision, self.threads, run, note=note)
        def packets(precision):
            def run(rays):
                if not rays.grid:
                    raise ValueError("packets are a camera's tiles; these rays are not a camera's")
                origins, directions = rays.of(precision)
                t = np.empty(len(origins), dtype=origins.dtype)
                face = np.empty(len(origins), dtype=np.int64)
                closest_hits_packets(self.vertices[precision], self.faces4, self.wide[precision].nodes,
                                     self.wide[precision].links, origins, directions, rays.grid, t, face)
                return t, face
            return Path_(self.name + " packets", precision, self.threads, run,
                         note="the wide tree, packets of %dx%d rays (rtfgu.kernels.packet)" % (TILE_W, TILE_H))
        binary = "the binary tree (the render's where the CPU has no AVX)"
        return [path("float64", self.wide["float64"].nodes, "the wide tree with blocks of gathered corners (the "
                     "render's in float64)"), packets("float64"),
                path("float32", self.wide["float32"].nodes, "the wide tree with blocks (the render's in float32)"),
                packets("float32"),
                path("float64", self.bvh.nodes, binary), path("float32", self.bvh.nodes, binary)]

    def bytes_per_triangle(self):
        n = len(self.faces4)
        return {p: (self.wide[p].nbytes + self.faces4.nbytes + v.nbytes) / n
                for p, v in self.vertices.items()}

    def build_note(self):
        binary, wide, blocks = zip(*(self.tree_seconds[1:] or self.tree_seconds))
        return ("flat_bvh.build alone: %.3g s, the collapse to the wide tree %.3g s, its blocks in both precisions "
                "%.3g s (medians); %d binary nodes, depth %d; %d wide nodes (%d bytes each) and %d blocks (with "
                "their corners in float32); the binary table (%.1f bytes per triangle, the WGSL path's) is not "
                "counted" % (
                    statistics.median(binary), statistics.median(wide), statistics.median(blocks),
                    self.bvh.num_nodes, self.bvh.depth(), count_nodes(self.wide["float32"]),
                    self.wide["float32"].nodes[0].nbytes, count_blocks(self.wide["float32"]),
                    self.bvh.nbytes / len(self.faces4)))


class Embree(System):
    name = "Embree"

    def __init__(self, threads, robust=True):
        from embreex import mesh_construction, rtcore_scene
        self.rtcore_scene, self.mesh_construction = rtcore_scene, mesh_construction
        self.threads = threads
        self.robust = robust
        self.pool = ThreadPoolExecutor(threads)
        if robust:
            self.about = ("embreex %s (Embree 4; \"Embree\": robust=True, its default, Embree's robust mode; "
                          "\"Embree fast\": robust=False; its run traces one ray at a time with rtcIntersect1)"
                          % version("embreex"))
        else:
            self.name, self.about = "Embree fast", ""

    def build(self, mesh):
        self.scene = None  # the previous scene is released before the next one is built
        vertices = np.ascontiguousarray(mesh.vertices, dtype=np.float32)
        faces = np.ascontiguousarray(mesh.faces, dtype=np.int32)
        one = np.zeros((1, 3), dtype=np.float32)
        start = time.perf_counter()
        scene = self.rtcore_scene.EmbreeScene(robust=self.robust)
        self.mesh_construction.TriangleMesh(scene, vertices, faces)
        scene.run(one, one + np.float32(1), output=1)  # embreex commits at the first run
        seconds = time.perf_counter() - start
        self.scene = scene
        return seconds

    def trace(self, rays, threads):
        origins, directions = rays.of("float32")
        cuts = np.linspace(0, len(origins), EMBREE_CHUNKS + 1).astype(int)

        def part(k):
            a, b = cuts[k], cuts[k + 1]
            return self.scene.run(origins[a:b], directions[a:b], output=1)
        if threads == 1:
            parts = [part(k) for k in range(EMBREE_CHUNKS)]
        else:
            parts = list(self.pool.map(part, range(EMBREE_CHUNKS)))
        face = np.concatenate([p["primID"] for p in parts]).astype(np.int64)
        t = np.concatenate([p["tfar"] for p in parts])
        t[face < 0] = np.inf  # a miss keeps tfar at embreex's 1e37
        return t, face

    def paths(self):
        out = [Path_(self.name, "float32", self.threads,
                     lambda rays: self.trace(rays, self.threads),
                     note="%d Python threads over %d parts" % (self.threads, EMBREE_CHUNKS))]
        if self.threads > 1:
            out.append(Path_(self.name, "float32", 1, lambda rays: self.trace(rays, 1),
                             note="one thread"))
        return out


def load_mitsuba():
    """(mitsuba module, variant, why not LLVM or ""). The LLVM variant is tried on a small
    scene, since it can import without the LLVM library and fail at the first kernel."""
    import drjit as dr
    import mitsuba as mi
    try:
        mi.set_variant("llvm_ad_rgb")
        scene = mi.load_dict({"type": "scene", "s": {"type": "sphere"}})
        ray = mi.Ray3f(mi.Point3f(0, 0, 5), mi.Vector3f(0, 0, -1))
        t = scene.ray_intersect_preliminary(ray).t
        dr.eval(t)
        if abs(float(t.numpy()[0]) - 4.0) > 1e-5:
            raise RuntimeError("a test ray hit at t = %s, not 4" % t)
        return mi, "llvm_ad_rgb", ""
    except Exception as error:
        mi.set_variant("scalar_rgb")
        return mi, "scalar_rgb", "llvm_ad_rgb failed: %s" % str(error).splitlines()[0]


class Mitsuba(System):
    name = "Mitsuba 3"

    def __init__(self, threads):
        import drjit as dr
        self.dr = dr
        self.mi, self.variant, self.why = load_mitsuba()
        self.llvm = self.variant.startswith("llvm")
        self.threads = dr.thread_count() if self.llvm else 1
        self.about = "mitsuba %s, drjit %s, variant %s (%sintersected by %s)" % (
            version("mitsuba"), version("drjit"), self.variant,
            "all rays in one Dr.Jit kernel on %d threads, " % self.threads if self.llvm else "",
            "its own Embree 3" if getattr(self.mi, "MI_ENABLE_EMBREE", False)
            else "its own kd-tree")
        if self.why:
            self.about += "; %s" % self.why

    def build(self, mesh):
        mi = self.mi
        self.scene = None
        vertices = np.ascontiguousarray(mesh.vertices, dtype=np.float32).ravel()
        faces = np.ascontiguousarray(mesh.faces, dtype=np.uint32).ravel()
        start = time.perf_counter()
        shape = mi.Mesh("mesh", len(mesh.vertices), len(mesh.faces), has_vertex_normals=False,
                        has_vertex_texcoords=False)
        params = mi.traverse(shape)
        # The buffers' own types: mi.Float and mi.UInt in the LLVM variant, dynamic arrays in
        # the scalar one.
        params["vertex_positions"] = type(params["vertex_positions"])(vertices)
        params["faces"] = type(params["faces"])(faces)
        params.update()
        self.scene = mi.load_dict({"type": "scene", "mesh": shape})
        return time.perf_counter() - start

    def ray_array(self, origins, directions):
        mi = self.mi
        ray = mi.Ray3f(o=mi.Point3f(*(mi.Float(origins[:, i]) for i in range(3))),
                       d=mi.Vector3f(*(mi.Float(directions[:, i]) for i in range(3))))
        self.dr.eval(ray)
        return ray

    def intersect(self, ray):
        pi = self.scene.ray_intersect_preliminary(ray)
        self.dr.eval(pi.t, pi.prim_index, pi.shape)
        self.dr.sync_thread()  # LLVM kernels run asynchronously
        return pi

    def paths(self):
        mi = self.mi
        if self.llvm:
            def prepare(rays):
                return self.ray_array(*rays.of("float32"))

            def result(pi):
                t = pi.t.numpy().astype(np.float32)
                face = pi.prim_index.numpy().astype(np.int64)
                face[~np.isfinite(t)] = -1
                return t, face
            return [Path_(self.name, "float32", self.threads, self.intersect, prepare, result)]

        def prepare_scalar(rays):
            origins, directions = rays.of("float32")
            return origins[:SCALAR_RAYS].tolist(), directions[:SCALAR_RAYS].tolist()

        def run_scalar(prepared):
            t, face = [], []
            for o, d in zip(*prepared):
                pi = self.scene.ray_intersect_preliminary(mi.Ray3f(mi.Point3f(o), mi.Vector3f(d)))
                t.append(pi.t)
                face.append(pi.prim_index if math.isfinite(pi.t) else -1)
            return np.array(t, dtype=np.float32), np.array(face, dtype=np.int64)
        return [Path_(self.name, "float32", 1, run_scalar, prepare_scalar,
                      note="scalar_rgb from Python, on at most the first %d rays" % SCALAR_RAYS)]


# The entry point of the WGSL path's program (rtfgu/wgsl/harness.py's conventions: inputs at
# bindings 0 .. 3, the result at 4, ``main`` with @workgroup_size(64)): one invocation per
# ray, through intersect_mesh.wgsl's mesh_closest with no feature on (flat faces, no spheres
# in the BVH), as intersect_scene calls it for a scene of one mesh. Rays: [o, tmin],
# [w, tmax] per ray; result: [t (-1 on a miss), bitcast face (-1), 0, 0] per ray. $nodes and
# $closest: the tree's binding and its traversal (wgsl_main).
WGSL_MAIN_TEMPLATE = """\
@group(0) @binding(0) var<storage, read> mesh_vertices: array<f32>;
@group(0) @binding(1) var<storage, read> mesh_faces: array<vec4i>;
@group(0) @binding(2) var<storage, read> $nodes;
@group(0) @binding(3) var<storage, read> rays: array<vec4f>;
@group(0) @binding(4) var<storage, read_write> result: array<vec4f>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3u)
{
    let i = gid.x;
    if (i >= arrayLength(&result)) {
        return;
    }
    let a = rays[2u * i];
    let b = rays[2u * i + 1u];
    var r = Ray(a.xyz, b.xyz, a.w, b.w);
    var hit = empty_hit();
    var shape = -1;
    var kind = -1;
    var row = 0u;
    let found = $closest(&r, &hit, &shape, &kind, &row, 0u);
    result[i] = vec4f(select(-1.0, hit.dist, found), bitcast<f32>(select(-1, shape, found)), 0.0, 0.0);
}
"""


def wgsl_main(nodes: str, closest: str) -> str:
    """WGSL_MAIN_TEMPLATE with the tree's binding ``nodes`` and its traversal ``closest``."""
    from string import Template
    return Template(WGSL_MAIN_TEMPLATE).substitute(nodes=nodes, closest=closest)


WGSL_MAIN = wgsl_main("bvh_nodes: array<BVHNode>", "mesh_closest")


def wgsl_cut(piece: str, names) -> str:
    """The declarations ``names`` (functions, structs, constants) of rtfgu/wgsl/``piece``, in
    the file's order, cut from it: the rest of the file needs bindings the program lacks."""
    import re

    from rtfgu.wgsl.assemble import read_piece
    text = read_piece(piece)
    found = []
    for name in names:
        m = re.search(r"^(?:fn %s\(|struct %s \{).*?^\};?\n|^const %s = [^\n]*\n"
                      % (name, name, name), text, re.M | re.S)
        if m is None:
            raise RuntimeError("no fn, struct or const %s in rtfgu/wgsl/%s" % (name, piece))
        found.append(m)
    return "\n".join(m.group(0) for m in sorted(found, key=lambda m: m.start()))


def wgsl_next_up() -> str:
    """intersect_scene.wgsl's next_up (mesh_closest calls it)."""
    return wgsl_cut("intersect_scene.wgsl", ["next_up"])


class Wgsl(System):
    """rtfgu's WGSL BVH traversal (intersect_mesh.wgsl, the render's) through the batch
    harness on wgpu's adapter: the pipeline is compiled once (here), ``build`` makes the
    node table as ``Rtfgu`` does and uploads the vertices (float32), faces and nodes;
    ``prepare`` uploads the rays and makes one bind group per dispatch of at most WGSL_BATCH
    rays (and no more than a storage binding holds); a timed run is the dispatches and the
    readback of t and the face."""
    name = "rtfgu WGSL"
    traversal = "rtfgu's WGSL path (rtfgu/wgsl/intersect_mesh.wgsl's mesh_closest)"
    built = "rtfgu numba's flat_bvh.build"

    @staticmethod
    def program(batch_program):
        return batch_program(["ray.wgsl", "hitinfo.wgsl", "next_up.wgsl", "intersect_mesh.wgsl",
                              "mesh_bench_main.wgsl"],
                             overrides={"next_up.wgsl": wgsl_next_up(), "mesh_bench_main.wgsl": WGSL_MAIN})

    @staticmethod
    def tree(bvh):
        """The node table the program's binding 2 reads: the binary one (flat_bvh)."""
        return bvh.nodes

    def __init__(self, threads):
        from rtfgu.wgsl.device import adapter_description, get_device
        from rtfgu.wgsl.harness import batch_program, compile_batch

        self.adapter, self.device = get_device()  # NoAdapterError: the section names why
        self.adapter_name = adapter_description()
        info = self.adapter.info
        self.device_name = info.get("device", "?").split(" (")[0]
        self.limits = self.device.limits
        self.max_binding = int(self.limits["max-storage-buffer-binding-size"])
        self.max_groups = int(self.limits["max-compute-workgroups-per-dimension"])
        self.alignment = int(self.limits["min-storage-buffer-offset-alignment"])
        start = time.perf_counter()
        self.batch = compile_batch(self.program(batch_program))
        self.layout, self.pipeline = self.batch.pipeline(4)
        self.compile_seconds = time.perf_counter() - start
        self.threads = 0  # not a thread count: the adapter's
        self.about = ("%s through rtfgu/wgsl/harness.py with wgpu %s on %s (pipeline compile %.2g s)"
                      % (self.traversal, version("wgpu"), self.adapter_name, self.compile_seconds))
        self.upload_seconds, self.buffers, self.mesh = [], None, None

    def build(self, mesh):
        import wgpu

        if self.mesh is not mesh:
            self.mesh, self.upload_seconds = mesh, []
        self.buffers = None  # the previous mesh's buffers are released first
        start = time.perf_counter()
        bvh, faces4 = bvh_of(mesh)
        vertices = np.ascontiguousarray(mesh.vertices, dtype=np.float32)
        arrays = (vertices, faces4, self.tree(bvh))
        self.nbytes = sum(a.nbytes for a in arrays)
        too_big = [(name, a.nbytes) for name, a in zip(("vertices", "faces", "BVH nodes"), arrays)
                   if a.nbytes > self.max_binding]
        if too_big:
            raise RuntimeError("over the max storage buffer binding size of %s (%d bytes): "
                               "%s" % (self.adapter_name, self.max_binding,
                                       ", ".join("%s %d bytes" % kv for kv in too_big)))
        upload = time.perf_counter()
        buffers = []
        for a in arrays:
            raw = a.tobytes()
            raw += bytes(-len(raw) % 16 if raw else 16)  # whole vec4s, as the harness pads
            buffers.append(self.device.create_buffer_with_data(
                data=raw, usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_SRC))
        # create_buffer_with_data has copied the data when it returns; a tiny round trip
        # through the queue makes sure the upload is done before the clock stops.
        self.device.queue.read_buffer(buffers[-1], 0, 16)
        end = time.perf_counter()
        self.upload_seconds.append(end - upload)
        self.buffers, self.bvh = buffers, bvh
        return end - start

    def prepare(self, rays):
        import wgpu

        from rtfgu.layout import FAR
        origins, directions = rays.of("float32")
        n = len(origins) if WGSL_RAYS is None else min(len(origins), WGSL_RAYS)
        data = np.zeros((n, 2, 4), dtype=np.float32)
        data[:, 0, :3], data[:, 1, :3] = origins[:n], directions[:n]
        data[:, 1, 3] = FAR  # tmin 0, tmax "infinity" as the render passes it
        # Rays per dispatch: WGSL_BATCH at most, within one binding and one dispatch's
        # workgroups, and a multiple of what keeps every binding's offset aligned.
        step = math.lcm(64, self.alignment // math.gcd(self.alignment, 16))
        batch = min(WGSL_BATCH, self.max_binding // 32, self.max_groups * 64) // step * step
        usage = wgpu.BufferUsage
        ray_buffer = self.device.create_buffer_with_data(data=data.tobytes(), usage=usage.STORAGE)
        output = self.device.create_buffer(size=16 * n, usage=usage.STORAGE | usage.COPY_SRC)
        groups = []
        for a in range(0, n, batch):
            b = min(n, a + batch)
            groups.append((self.device.create_bind_group(layout=self.layout, entries=[
                *({"binding": k, "resource": {"buffer": buffer, "offset": 0,
                                              "size": buffer.size}}
                  for k, buffer in enumerate(self.buffers)),
                {"binding": 3, "resource": {"buffer": ray_buffer, "offset": 32 * a,
                                            "size": 32 * (b - a)}},
                {"binding": 4, "resource": {"buffer": output, "offset": 16 * a,
                                            "size": 16 * (b - a)}}]), b - a))
        return ray_buffer, output, groups

    def run(self, prepared):
        _, output, groups = prepared
        for group, count in groups:  # one submit per dispatch, as the render's tiles
            encoder = self.device.create_command_encoder()
            compute = encoder.begin_compute_pass()
            compute.set_pipeline(self.pipeline)
            compute.set_bind_group(0, group)
            compute.dispatch_workgroups(-(-count // 64), 1, 1)
            compute.end()
            self.device.queue.submit([encoder.finish()])
        return np.frombuffer(self.device.queue.read_buffer(output), dtype=np.float32)

    @staticmethod
    def result(raw):
        out = raw.reshape(-1, 4)
        face = out[:, 1].view(np.int32).astype(np.int64)
        t = out[:, 0].copy()
        t[face < 0] = np.inf
        return t, face

    def paths(self):
        note = self.adapter_name
        if WGSL_RAYS is not None:
            note += "; on at most the first %d rays" % WGSL_RAYS
        return [Path_(self.name, "float32", self.threads, self.run, self.prepare, self.result,
                      note=note, device=self.device_name)]

    def bytes_per_triangle(self):
        return {"float32": self.nbytes / len(self.mesh.faces)}

    def build_note(self):
        return "%s, uploaded to %s: upload %.3g s " \
               "(median), %.1f MB" % (self.built, self.device_name,
                                      statistics.median(self.upload_seconds[1:]
                                                        or self.upload_seconds),
                                      self.nbytes / 1e6)


class WgslWide(Wgsl):
    """An experiment, not the render's traversal: the numba path's wide tree (FlatBVH.wide,
    (N, 7, 8) float32 nodes uploaded as they are) traversed in WGSL by
    benchmarks/wgsl_wide_bvh.wgsl, with intersect_mesh.wgsl's face test and leaf loop cut from
    that file; otherwise the harness, the rays and the timing of ``Wgsl``. Faces only."""
    name = "rtfgu WGSL wide"
    traversal = ("the wide tree's traversal in WGSL (benchmarks/wgsl_wide_bvh.wgsl's mesh_closest_wide, "
                 "intersect_mesh.wgsl's face test)")
    built = "rtfgu numba's flat_bvh.build and its collapse to the wide tree"

    @staticmethod
    def program(batch_program):
        from rtfgu.accelerators.wide_bvh import CODE_ROW, LEAF_BITS, ROWS, WIDTH
        from rtfgu.kernels.wide_bvh import STACK
        face_functions = wgsl_cut("intersect_mesh.wgsl", [
            "CULL_WIDEN", "Shear", "ray_shear", "mesh_vertex", "intersect_face", "safe_inverse", "face_frame",
            "mesh_normal"])
        return batch_program(["ray.wgsl", "hitinfo.wgsl", "next_up.wgsl", "mesh_faces.wgsl", "wgsl_wide_bvh.wgsl",
                              "mesh_bench_main.wgsl"],
                             constants={"WIDE_WIDTH": WIDTH, "WIDE_ROWS": ROWS, "WIDE_CODE_ROW": CODE_ROW,
                                        "WIDE_STACK": STACK, "LEAF_BITS": LEAF_BITS},
                             overrides={"next_up.wgsl": wgsl_next_up(), "mesh_faces.wgsl": face_functions,
                                        "wgsl_wide_bvh.wgsl": (HERE / "wgsl_wide_bvh.wgsl").read_text(),
                                        "mesh_bench_main.wgsl": wgsl_main("wide_nodes: array<f32>",
                                                                          "mesh_closest_wide")})

    def build(self, mesh):
        self.faces_only(mesh)
        return super().build(mesh)

    @staticmethod
    def faces_only(mesh):
        if mesh.faces.ndim != 2 or mesh.faces.shape[1] != 3 or (mesh.faces < 0).any():
            raise ValueError("%s: benchmarks/wgsl_wide_bvh.wgsl traverses faces only: mesh.faces must be "
                             "(F, 3) vertex indices >= 0, not spheres or instances" % mesh.name)

    @staticmethod
    def tree(bvh):
        """The wide table (FlatBVH.wide) as (N * 8 * 8) float32, its link rows as stored."""
        wide = bvh.wide()
        if wide.roots != (0,):
            raise ValueError("wide BVH: one tree rooted at node 0 expected, not roots %s" % (wide.roots,))
        return wide.nodes


# The peers of rtfgu numba, by their key for --peers: (class, package, whether the bench extra
# installs the package).
PEERS = {"wgsl": (Wgsl, "wgpu", False), "wgsl-wide": (WgslWide, "wgpu", False),
         "embree": (Embree, "embreex", True), "mitsuba": (Mitsuba, "mitsuba", True)}


# ---- measuring --------------------------------------------------------------------------

@dataclass
class Measured:
    mesh: str
    triangles: int
    rays: str
    path: Path_
    count: int = 0
    times: list = field(default_factory=list)
    first_call: float = float("nan")
    t: np.ndarray = None
    face: np.ndarray = None
    error: dict = None
    failed: str = ""
    reference: bool = False  # the others' error is measured against this one

    @property
    def rate(self) -> float:
        return self.count / statistics.median(self.times)


@dataclass
class Built:
    mesh: str
    triangles: int
    system: str
    seconds: float = None
    first: float = None
    per_triangle: dict = None
    note: str = ""
    failed: str = ""


def compare(t, face, t_ref, face_ref) -> dict:
    """The error columns of ``t, face`` against the reference on the same rays (the first
    len(t) of them)."""
    t = np.asarray(t, dtype=np.float64)
    t_ref = np.asarray(t_ref[:len(t)], dtype=np.float64)
    face_ref = face_ref[:len(t)]
    hit, hit_ref = face >= 0, face_ref >= 0
    both = hit & hit_ref
    with np.errstate(invalid="ignore"):  # inf - inf on rays both miss; not read
        rel = np.abs(t - t_ref) / np.maximum(np.abs(t_ref), np.finfo(np.float64).tiny)
    other = both & (face != face_ref)
    same = both & (face == face_ref)
    return {"hit_miss": float(np.mean(hit != hit_ref)),
            "other_face": float(np.sum(other)) / max(1, int(np.sum(both))),
            "other_far": float(np.sum(other & (rel > TOL))) / max(1, int(np.sum(both))),
            "rel_same": float(rel[same].max()) if same.any() else float("nan"),
            "rel_both": float(rel[both].max()) if both.any() else float("nan"),
            "hits": float(np.mean(hit_ref))}


def timed(fn, *args):
    start = time.perf_counter()
    result = fn(*args)
    return result, time.perf_counter() - start


def repeated(measure, runs):
    """The seconds ``measure()`` returns, ``runs`` calls at least and as many more as fit in
    BUILD_SECONDS (at most BUILD_MOST calls)."""
    seconds, start = [], time.perf_counter()
    while len(seconds) < runs or (len(seconds) < BUILD_MOST and time.perf_counter() - start < BUILD_SECONDS):
        seconds.append(measure())
    return seconds


def measure_builds(system, mesh, runs, log):
    """(median seconds of ``runs`` builds or more (repeated()) after a warm-up one, the
    warm-up's seconds)."""
    first = system.build(mesh)
    seconds = repeated(lambda: system.build(mesh), runs)
    log("  %s: build %.3g s (first %.3g s)" % (system.name, statistics.median(seconds), first))
    return statistics.median(seconds), first


def second_call(fn, *args) -> float:
    """Seconds of the second of two calls in a row: the call a user makes again, after the
    threads and caches another system's call used have been woken and filled by the first."""
    fn(*args)
    return timed(fn, *args)[1]


def shuffled(items, number):
    """``items`` in round ``number``'s order (seeded), so that no row always runs right after
    the same other system (one that leaves the caches cold or its threads spinning)."""
    order = list(items)
    random.Random(number).shuffle(order)
    return order


def round_robin(measured, prepared, runs, log, what):
    for number in range(runs):
        for m in shuffled(measured, number):
            if not m.failed:
                m.times.append(second_call(m.path.run, prepared[id(m)]))
        log("  %s: round %d of %d done" % (what, number + 1, runs))


def bench_mesh(mesh, systems, ray_sets, runs, build_runs, log):
    """(build rows, trace rows) of one mesh: every system built, then every path timed on
    every ray set."""
    builds, measured, built, unbuilt = [], [], [], []
    for system in systems:
        row = Built(mesh.name, len(mesh.faces), system.name)
        try:
            row.seconds, row.first = measure_builds(system, mesh, build_runs, log)
            row.per_triangle, row.note = system.bytes_per_triangle(), system.build_note()
            built.append(system)
        except Exception as error:
            row.failed = str(error).splitlines()[0] if str(error) else repr(error)
            log("  %s: build failed: %s" % (system.name, row.failed))
            unbuilt.append(row)
        builds.append(row)
    for rays in ray_sets:
        # a system that could not build (the WGSL path on a mesh over the adapter's limits)
        # is named on every ray set with the reason
        rows = [Measured(mesh.name, len(mesh.faces), rays.name, Path_(b.system, "float32", 0, None),
                         failed="build failed: %s" % b.failed) for b in unbuilt]
        prepared = {}
        for system in built:
            for path in system.paths():
                m = Measured(mesh.name, len(mesh.faces), rays.name, path)
                try:
                    prepared[id(m)] = path.prepare(rays) if path.prepare else rays
                    raw, m.first_call = timed(path.run, prepared[id(m)])  # the warm-up
                    m.t, m.face = path.result(raw) if path.result else raw
                    m.count = len(m.t)
                except Exception as error:
                    m.failed = str(error).splitlines()[0] if str(error) else repr(error)
                    log("  %s on %s: failed: %s" % (path.label, rays.name, m.failed))
                rows.append(m)
        log("%s, %s: warm-up done" % (mesh.name, rays.name))
        round_robin(rows, prepared, runs, log, "%s, %s" % (mesh.name, rays.name))
        reference = next((m for m in rows if m.path.system == Embree.name and not m.failed),
                         None)
        if reference is not None:
            reference.reference = True
        for m in rows:
            if reference is not None and not m.failed:
                m.error = compare(m.t, m.face, reference.t, reference.face)
        for m in rows:
            m.t = m.face = None  # the arrays of 1 M rays are not kept past their comparison
        measured += rows
    return builds, measured


# ---- the 64 spheres ---------------------------------------------------------------------

@njit(parallel=True, error_model="numpy")
def camera_rays(camera_kind, camera, width, height, origins, directions):
    """The primary ray of every pixel as rtfgu's render makes it (pixel centres; row 0 of
    the image, the first ``width`` rays, is the top)."""
    for iy in prange(height):
        for ix in range(width):
            sx = 2.0 * (ix + 0.5) / width - 1.0
            sy = 2.0 * (iy + 0.5) / height - 1.0
            origin, direction, _, _ = gen_ray(camera_kind, camera, sx, sy)
            k = (height - 1 - iy) * width + ix
            for c in range(3):
                origins[k, c] = origin[c]
                directions[k, c] = direction[c]


def bench_spheres(mitsuba, size, runs, log):
    """Rows (label, precision, threads, rays/s, pixels differing, what is timed, note) for
    the 64-sphere scene."""
    from rtfgu.kernels import NumbaAccumulator
    from rtfgu.layout import CAMERA_WIDTH, MAT_COLOR, SPHERE_RADIUS, compile_scene
    from rtfgu.renderer import render

    import scenes as bench_scenes
    import spheres_only

    scene = bench_scenes.random_spheres_64()
    flat = compile_scene(scene, "float64")
    spheres = flat.table("sphere")
    colors = np.vstack([flat.materials[flat.material_of, MAT_COLOR:MAT_COLOR + 3], flat.background[None, :3]])
    reference = render(scene, size, size, backend="numba", precision="float64")

    def differ(image):
        return float(np.mean(np.any(np.abs(image - reference) > 1e-6, axis=2)))

    rows = []  # [label, precision, threads, run, prepared, times, differ, timed what, note]
    import numba
    for precision in ("float64", "float32"):
        def run_render(_, precision=precision):
            return render(scene, size, size, backend="numba", precision=precision)
        rows.append(["rtfgu.render numba (slide)", precision, numba.get_num_threads(),
                     run_render, None, [], differ(run_render(None)),
                     "whole render: rays, intersection, image", ""])
        accumulate = NumbaAccumulator(scene, size, size, precision)

        def run_accumulate(_, accumulate=accumulate):
            accumulate.add((0, 1))
            return accumulate.sums      # of one sample, the image
        rows.append(["rtfgu numba kernel (slide)", precision, numba.get_num_threads(),
                     run_accumulate, None, [], differ(run_accumulate(None)),
                     "the render's kernel alone: NumbaAccumulator.add", ""])
        flat_p = compile_scene(scene, precision)

        def run_kernel(_, flat_p=flat_p):
            return spheres_only.run_spheres_only(flat_p, size, size)
        rows.append(["spheres-only kernel", precision, numba.get_num_threads(), run_kernel, None,
                     [], differ(run_kernel(None)), "rays, intersection, image", ""])
    if isinstance(mitsuba, str):
        rows.append(["Mitsuba 3", "float32", 0, None, None, [], float("nan"), "-", mitsuba])
    else:
        mi, dr = mitsuba.mi, mitsuba.dr
        try:
            if not mitsuba.llvm:
                raise RuntimeError("the scalar variant is not timed on the spheres")
            camera = np.ascontiguousarray(flat.camera.reshape(CAMERA_WIDTH), dtype=np.float64)
            origins = np.empty((size * size, 3))
            directions = np.empty((size * size, 3))
            camera_rays(flat.camera_kind, camera, size, size, origins, directions)
            shapes = {"sphere_%02d" % i: {"type": "sphere", "center": s[:3].tolist(),
                                          "radius": float(s[SPHERE_RADIUS])}
                      for i, s in enumerate(spheres)}
            start = time.perf_counter()
            mscene = mi.load_dict({"type": "scene", **shapes})
            load = time.perf_counter() - start
            # Dr.Jit names a shape by its registry number: map those to the rows of ``spheres``.
            number = dict(zip(dr.reinterpret_array(mi.UInt32, mscene.shapes_dr()).numpy(),
                              (int(s.id().split("_")[1]) for s in mscene.shapes())))
            ray = mitsuba.ray_array(origins.astype(np.float32), directions.astype(np.float32))

            def run_mitsuba(ray):
                pi = mscene.ray_intersect_preliminary(ray)
                dr.eval(pi.t, pi.shape)
                dr.sync_thread()
                return pi
            pi = run_mitsuba(ray)
            hit = dr.reinterpret_array(mi.UInt32, pi.shape).numpy()
            which = np.array([number.get(h, len(spheres)) for h in range(max(number) + 1)])
            index = np.where(hit == 0, len(spheres), which[np.minimum(hit, len(which) - 1)])
            image = colors[index].reshape(size, size, 3)
            rows.append(["Mitsuba 3 ray_intersect_preliminary", "float32", mitsuba.threads,
                         run_mitsuba, ray, [], differ(image), "intersection only",
                         "scene load %.3g s" % load])
        except Exception as error:
            rows.append(["Mitsuba 3", "float32", 0, None, None, [], float("nan"), "-",
                         "not run: %s" % str(error).splitlines()[0]])
    for number in range(runs):
        for row in shuffled(rows, number):
            if row[3] is not None:
                row[5].append(second_call(row[3], row[4]))
        log("  64 spheres: round %d of %d done" % (number + 1, runs))
    return [(label, precision, threads, size * size / statistics.median(times) if times else None,
             d, what, note)
            for label, precision, threads, _, _, times, d, what, note in rows]


def bench_render(meshes, subdivisions, size, builds, runs, log) -> list:
    """What each mesh costs through rtfgu.render (benchmarks/mesh_render.py, float32, at size
    x size, each in a Python process of its own): once with numba's kernels compiled before
    ("warm"), once loading them from numba's cache on disk ("cold": a new session). Each
    row is mesh_render.py's JSON with Embree's build time of this run."""
    embree = {b.mesh: b.seconds for b in builds if b.system == Embree.name and b.seconds}
    rows = []
    for mesh, which in ((meshes[0], [str(subdivisions)]), (meshes[1], ["0", "--bunny"])):
        for cold in (False, True):
            command = [sys.executable, str(HERE / "mesh_render.py"), *which, "--size", str(size),
                       "--precision", "float32", "--runs", str(runs)] + (["--cold"] if cold else [])
            try:
                done = subprocess.run(command, capture_output=True, text=True, check=True)
                row = json.loads(done.stdout.strip().splitlines()[-1])
            except (subprocess.CalledProcessError, ValueError, IndexError) as error:
                row = {"mesh": mesh.name, "triangles": len(mesh.faces), "cold": cold,
                       "failed": (getattr(error, "stderr", "") or str(error)).strip().splitlines()[-1:]}
            row["embree_build"] = embree.get(mesh.name)
            rows.append(row)
            log("  through rtfgu.render: %s" % row)
    return rows


def render_table(rows) -> list:
    lines = ["| mesh | triangles | kernels | `Mesh(...)` | first render | `Mesh` + first render "
             "| second render | kernel alone | second / kernel | first - kernel "
             "| layout and build alone | Embree build | layout and build / Embree build "
             "| pixels differing from float64 | largest difference |",
             "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        kernels = "from disk (cold)" if r["cold"] else "compiled before"
        if r.get("failed"):
            lines.append("| %s | %d | %s | not run: %s ||||||||||||" % (
                r["mesh"], r["triangles"], kernels, " ".join(r["failed"])))
            continue
        embree = r.get("embree_build")
        setup = r["first"] - r["kernel"]
        lines.append("| %s | %d | %s | %.3g s | %.3g s | %.3g s | %.3g s | %.3g s | %.2f | %.3g s | "
                     "%.3g s | %s | %s | %s | %.2g |" % (
                         r["mesh"], r["triangles"], kernels, r["construct"], r["first"],
                         r["construct"] + r["first"], r["second"], r["kernel"],
                         r["second"] / r["kernel"], setup, r["layout"],
                         "%.3g s" % embree if embree else "-",
                         "%.2f" % (r["layout"] / embree) if embree else "-",
                         fmt_share(r["differing"]), r["largest"]))
    return lines


# ---- the section ------------------------------------------------------------------------

def fmt_rate(x) -> str:
    return "-" if x is None else ("%.2f M" % (x / 1e6) if x >= 1e5 else "%.0f k" % (x / 1e3))


def fmt_share(x) -> str:
    if x is None or x != x:
        return "-"
    return "0" if x == 0 else "%.2g %%" % (100 * x)


def fmt_rel(x) -> str:
    return "-" if x is None or x != x else ("0" if x == 0 else "%.1e" % x)


def trace_table(measured) -> list:
    lines = ["| mesh | rays | path | precision | threads | rays/s | / Embree | / Embree fast | hit/miss differ "
             "| other face | ... at another t | max rel dt, same face | max rel dt, both hit "
             "| note |",
             "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    groups = list(dict.fromkeys((m.mesh, m.rays) for m in measured))
    measured = sorted(measured, key=lambda m: groups.index((m.mesh, m.rays)))
    embree = {(m.mesh, m.rays): m.rate for m in measured
              if m.path.system == Embree.name and m.path.threads > 1 and not m.failed}
    embree1 = {(m.mesh, m.rays): m.rate for m in measured
               if m.path.system == Embree.name and not m.failed}
    fast = {(m.mesh, m.rays): m.rate for m in measured
            if m.path.system == "Embree fast" and m.path.threads > 1 and not m.failed}
    for m in measured:
        p = m.path
        if m.failed:
            lines.append("| %s | %s | %s | %s | %s | - | - | - | - | - | - | - | - | not run: %s |"
                         % (m.mesh, m.rays, p.system, p.precision, p.threads or "-", m.failed))
            continue
        base = embree.get((m.mesh, m.rays)) or embree1.get((m.mesh, m.rays))
        base_fast = fast.get((m.mesh, m.rays))
        e = m.error or {}
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            m.mesh, m.rays, p.system, p.precision, p.threads or "-", fmt_rate(m.rate),
            "%.2f" % (m.rate / base) if base else "-", "%.2f" % (m.rate / base_fast) if base_fast else "-",
            fmt_share(e.get("hit_miss")),
            fmt_share(e.get("other_face")), fmt_share(e.get("other_far")),
            fmt_rel(e.get("rel_same")), fmt_rel(e.get("rel_both")),
            "; ".join(x for x in (p.note, "the reference: %s of the rays hit" % fmt_share(
                e["hits"]) if m.reference else "") if x)))
    return lines


def build_table(builds) -> list:
    lines = ["| mesh | triangles | system | build (median) | first build | / Embree "
             "| bytes per triangle | note |",
             "|---|---:|---|---:|---:|---:|---:|---|"]
    embree = {b.mesh: b.seconds for b in builds if b.system == Embree.name}
    for b in builds:
        if b.seconds is None:
            lines.append("| %s | %d | %s | - | - | - | - | not run: %s |" % (
                b.mesh, b.triangles, b.system, b.failed))
            continue
        lines.append("| %s | %d | %s | %.3g s | %.3g s | %s | %s | %s |" % (
            b.mesh, b.triangles, b.system, b.seconds, b.first,
            "%.2f" % (b.seconds / embree[b.mesh]) if embree.get(b.mesh) else "-",
            ", ".join("%.1f (%s)" % (n, p) for p, n in b.per_triangle.items()) or "-", b.note))
    return lines


def sphere_table(rows, size) -> list:
    lines = ["| path | precision | threads | rays/s | timed | pixels differing from numba "
             "float64 | note |", "|---|---|---:|---:|---|---:|---|"]
    for label, precision, threads, rate, d, what, note in rows:
        lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            label, precision, threads or "-", fmt_rate(rate), what, fmt_share(d), note))
    return lines


def sphere_verdicts(rows) -> list:
    """rtfgu.render against its own kernel (within 1.25x) and against Mitsuba 3 LLVM (at or
    above), per precision."""
    rate = {(label, precision): r for label, precision, _, r, _, _, _ in rows if r}
    mitsuba = rate.get(("Mitsuba 3 ray_intersect_preliminary", "float32"))
    out = []
    for precision in ("float64", "float32"):
        whole = rate.get(("rtfgu.render numba (slide)", precision))
        kernel = rate.get(("rtfgu numba kernel (slide)", precision))
        if whole and kernel:
            out.append("- %s: rtfgu.render takes %.2fx its kernel's time (target: within 1.25x): %s."
                       % (precision, kernel / whole, "met" if kernel / whole <= 1.25 else "NOT met"))
        if whole and mitsuba and precision == "float32":
            out.append("- float32: rtfgu.render's rays/s are %.2fx Mitsuba 3 LLVM's (target: at "
                       "or above 1): %s." % (whole / mitsuba, "met" if whole >= mitsuba else "NOT met"))
    return out


def plot(measured, title, path):
    import matplotlib
    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt
    import matplotlib.ticker

    def label_of(p):
        return "%s%s %s, %s" % (p.system, " (binary tree)" if p.note.startswith("the binary tree") else "",
                                p.precision,
                              p.device if p.device else "%d thr." % p.threads)

    groups = list(dict.fromkeys((m.mesh, m.rays) for m in measured))
    labels = list(dict.fromkeys(label_of(m.path) for m in measured if not m.failed))
    fig, ax = plt.subplots(figsize=(9, 4.2))
    width = 0.8 / max(1, len(labels))
    for j, label in enumerate(labels):
        xs, ys = [], []
        for i, g in enumerate(groups):
            for m in measured:
                if (m.mesh, m.rays) == g and not m.failed and label == label_of(m.path):
                    xs.append(i + (j - (len(labels) - 1) / 2) * width)
                    ys.append(m.rate / 1e6)
        ax.bar(xs, ys, width, label=label, color=plt.get_cmap("tab10")(j))
    ax.set_xticks(range(len(groups)))
    ax.set_xticklabels(["%s\n%s" % g for g in groups], fontsize=8)
    ax.set_yscale("log")
    ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.yaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.tick_params(axis="y", which="minor", labelsize=7)
    ax.set_ylabel("million rays/s (closest hit; median)")
    ax.grid(True, axis="y", which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    ax.set_title("rtfgu's BVH (numba; WGSL on the adapter), Embree and Mitsuba 3 on %s" % title,
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def meshes_section(plot_path=None, quick=False, log=print, peers=None) -> str:
    """Measure, write the plot at ``plot_path`` (None: no plot), and return the markdown
    section (from START to END) for a file in ``plot_path``'s folder. ``peers``: the keys of
    PEERS to run beside rtfgu numba (None: all); the others are named as not chosen."""
    import numba
    started = time.perf_counter()
    load_start = os.getloadavg()
    threads = numba.get_num_threads()
    runs, build_runs = (1, 1) if quick else (RUNS, BUILD_RUNS)
    primary = QUICK_PRIMARY if quick else PRIMARY
    incoherent = QUICK_INCOHERENT if quick else INCOHERENT
    sphere_size = QUICK_SPHERE_SIZE if quick else SPHERE_SIZE

    systems, missing = [Rtfgu(threads)], {}
    bench_extra = " (`make bench` installs the bench extra)"
    # the WGSL path's reason (rtfgu.wgsl.device.NoAdapterError) names what to install
    for key, (cls, package, hint) in PEERS.items():
        if peers is not None and key not in peers:
            missing[cls.name] = "not chosen (--peers)"
            continue
        hint = bench_extra if hint else ""
        try:
            systems.append(cls(threads))
            if cls is Embree:
                systems.append(cls(threads, robust=False))
        except Exception as error:  # the section says which peer did not run, and why
            missing[cls.name] = "%s: %s%s" % (
                package, str(error).splitlines()[0] if str(error) else repr(error), hint)
            log("%s: not run: %s" % (cls.name, missing[cls.name]))
    mitsuba = next((s for s in systems if isinstance(s, Mitsuba)), None)
    wgsl = {cls: next((s for s in systems if type(s) is cls), None) for cls in (Wgsl, WgslWide)}

    meshes = [displaced_icosphere(QUICK_SUBDIVISIONS if quick else ICOSPHERE_SUBDIVISIONS),
              bunny()]
    builds, measured = [], []
    for mesh in meshes:
        log("meshes: %s, %d triangles" % (mesh.name, len(mesh.faces)))
        ray_sets = [primary_rays(mesh.vertices, primary),
                    incoherent_rays(mesh.vertices, incoherent)]
        b, m = bench_mesh(mesh, systems, ray_sets, runs, build_runs, log)
        builds += b + [Built(mesh.name, len(mesh.faces), name, failed=why)
                       for name, why in missing.items()]
        measured += m
        for rays in ray_sets:
            measured += [Measured(mesh.name, len(mesh.faces), rays.name,
                                  Path_(name, "float32", 0, None), failed=why)
                         for name, why in missing.items()]

    log("meshes: through rtfgu.render at %dx%d" % (sphere_size, sphere_size))
    render_rows = bench_render(meshes, QUICK_SUBDIVISIONS if quick else ICOSPHERE_SUBDIVISIONS,
                               sphere_size, builds, runs, log)
    log("meshes: the 64 spheres at %dx%d" % (sphere_size, sphere_size))
    sphere_runs = 1 if quick else SPHERE_RUNS
    sphere_rows = bench_spheres(mitsuba or "not run: %s" % missing.get(Mitsuba.name),
                                sphere_size, sphere_runs, log)
    load_end = os.getloadavg()

    machine = "%s, %d cores, numba %d threads" % (cpu_model(), os.cpu_count(), threads)
    figure = []
    if plot_path is not None:
        try:
            plot(measured, machine, Path(plot_path))
            figure = ["![rays/s per mesh, ray set and path](%s)" % Path(plot_path).name, ""]
        except ImportError as error:  # no matplotlib: the tables still get written
            figure = ["(No plot: %s. `make bench` installs matplotlib.)" % error, ""]
    first_calls = {}
    for m in measured:
        if m.path.system == Rtfgu.name and not m.failed:
            first_calls.setdefault(m.path.precision, m.first_call)
    others = [s.about for s in systems if s.about and not isinstance(s, Wgsl)] + [
        "%s not run (%s)" % kv for kv in missing.items() if kv[0] not in (Wgsl.name, WgslWide.name)]
    wgsl_lines = {}
    for cls, system in wgsl.items():
        if system is not None:
            # the adapter may compile the shader at the first dispatch (llvmpipe via OpenGL does)
            first = next((m.first_call for m in measured if m.path.system == cls.name and not m.failed), math.nan)
            wgsl_lines[cls] = ("%s; the first run of the first ray set (warm-up) %.2g s; float32; the rays "
                               "in dispatches of at most %d, one submit each; the mesh's buffers (vertices, "
                               "faces, nodes) must each fit one storage binding (%.4g MiB on this adapter)%s" % (
                                   system.about, first, WGSL_BATCH, system.max_binding / 2 ** 20,
                                   "; only the first %d rays of a set" % WGSL_RAYS if WGSL_RAYS else ""))
        else:
            wgsl_lines[cls] = "not run (%s)" % missing.get(cls.name)
    lines = [
        START,
        "## Meshes and the BVH",
        "",
        "Generated by benchmarks/meshes.py%s (also part of `make bench`); never edited by hand."
        % (" --quick" if quick else ""),
        "",
        "- Meshes: %s." % "; ".join("**%s**, %d triangles: %s" % (
            m.name, len(m.faces), m.about) for m in meshes),
        "- Rays per mesh, closest hit in [0, inf), unit directions, seeded: %dx%d primary rays "
        "of a pinhole camera whose square view the mesh fills; %d incoherent rays (origins "
        "uniform in the mesh's bounding box, directions uniform on the sphere). float32 paths "
        "get the rays and vertices rounded to float32." % (primary, primary, incoherent),
        "- rtfgu WGSL: %s." % wgsl_lines[Wgsl],
        "- rtfgu WGSL wide (an experiment, not the render's traversal): %s." % wgsl_lines[WgslWide],
        "- Peers: %s." % "; ".join(others),
        "- Time: median of %d round(s) after a warm-up run of every path (so numba's and "
        "Dr.Jit's compile, and the adapter's first dispatch, are excluded; rtfgu numba's "
        "first calls, compile included: %s); a round times every path once (round-robin), "
        "in an order shuffled per round, each time the second of two calls in a row. "
        "Timed: tracing and returning t and the face, not making the rays (WGSL: the "
        "dispatches and the readback of the results, not the upload of the rays). Build: "
        "median of %d or more (as many as fit in %g s, at most %d: a small mesh's build takes "
        "milliseconds, as much as this machine moves one call from the next) after a warm-up "
        "build, from the arrays to a structure ready to trace "
        "(rtfgu WGSL: rtfgu numba's build and the upload of its arrays; Embree: scene, "
        "TriangleMesh, commit; Mitsuba: mi.Mesh and mi.load_dict)." % (
            runs, ", ".join("%s %.1f s" % kv for kv in first_calls.items()) or "-",
            build_runs, BUILD_SECONDS, BUILD_MOST),
        "- Error against Embree (float32, the multi-threaded row), reported, not asserted: "
        "rays one path hits and the other misses (share of all rays); rays both hit on "
        "another face (share of rays both hit), and of those the ones whose t differs by "
        "more than %g relative (another surface, not a shared edge or vertex); the largest "
        "relative t difference on the same face and on all rays both hit." % TOL,
        "- Machine: %s; load average %.2f at the start, %.2f at the end; %.0f s in all."
        % (machine, load_start[0], load_end[0], time.perf_counter() - started),
        "",
        *figure,
        "### Rays per second and error against Embree",
        "",
        *trace_table(measured),
        "",
        "/ Embree: this row's rays/s over those of Embree on %d threads on the same rays. "
        "A relative t difference is large where t is small: an incoherent ray can start a "
        "hair from a face, and rounding its origin to float32 moves it by up to 6e-8 of its "
        "coordinates." % threads,
        "",
        "### Build time and size",
        "",
        *build_table(builds),
        "",
        "rtfgu's bytes per triangle: the BVH's nodes (32 bytes each) + the faces (16 bytes) + "
        "the vertices in that precision, over the triangles (WGSL: what is uploaded, the "
        "float32 arrays).",
        "",
        "### Through rtfgu.render",
        "",
        "Each mesh in a scene as a user renders it (benchmarks/mesh_render.py: the Mesh, a "
        "Matte, a point light, a pinhole camera; float32, %dx%d, 1 sample per pixel, numba on "
        "%d threads), in a Python process of its own: `Mesh(...)` from the arrays, the first "
        "`rtfgu.render` (the layout, the BVH build and the wide tree, the trace), the second "
        "(median of %d, each image dropped before the next; nothing is built again), the "
        "kernel alone (NumbaAccumulator.add, median of %d), and the first render's layout and "
        "build alone (compile_scene and the kernel's arguments, the wide tree's collapse "
        "included, of a new scene of a new Mesh of the same arrays, median of %d or more, as "
        "many as fit in %g s; first - "
        "kernel also holds the first image's new memory). Kernels \"compiled before\": a "
        "render of another mesh ran first in the process; \"from disk (cold)\": the first "
        "render also loads numba's compiled kernels from its cache. Embree build: this run's "
        "(the table above). The difference columns compare the first image with numba "
        "float64's." % (sphere_size, sphere_size, threads, runs, runs, runs, BUILD_SECONDS),
        "",
        *render_table(render_rows),
        "",
        "### The 64 spheres",
        "",
        "random_spheres_64 (benchmarks/scenes.py) at %dx%d, primary rays only (flat colours); "
        "rtfgu's rows are the paths of the first table, timed again here in the same run. "
        "Mitsuba traces the camera's rays made by rtfgu.kernels.camera.gen_ray, rounded to "
        "float32, through 64 `sphere` shapes. Time: median of %d rounds, each timing every "
        "row once in an order shuffled per round, the second of two calls in a row." % (
            sphere_size, sphere_size, sphere_runs),
        "",
        *sphere_table(sphere_rows, sphere_size),
        "",
        *sphere_verdicts(sphere_rows),
        "",
        END,
    ]
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs" / "bench.md"))
    parser.add_argument("--quick", action="store_true",
                        help="a check that everything runs: a %d-times subdivided icosphere, "
                             "%dx%d and %d rays, 1 run" % (QUICK_SUBDIVISIONS, QUICK_PRIMARY,
                                                          QUICK_PRIMARY, QUICK_INCOHERENT))
    parser.add_argument("--peers", help="the peers to run beside rtfgu numba, comma-separated, of: %s "
                                        "(default: all)" % ", ".join(PEERS))
    parser.add_argument("--wgsl-rays", type=int, help="trace only this many first rays of a set on the WGSL "
                                                      "paths (WGSL_RAYS; default: all)")
    args = parser.parse_args(argv)
    peers = None if args.peers is None else [p.strip() for p in args.peers.split(",") if p.strip()]
    unknown = sorted(set(peers or ()) - set(PEERS))
    if unknown:
        parser.error("--peers: unknown %s (known: %s)" % (", ".join(unknown), ", ".join(PEERS)))
    if args.wgsl_rays is not None:
        if args.wgsl_rays < 1:
            parser.error("--wgsl-rays: at least 1, not %d" % args.wgsl_rays)
        global WGSL_RAYS
        WGSL_RAYS = args.wgsl_rays
    out = Path(args.out)
    started = time.perf_counter()

    def log(message):
        print("[%5.0f s] %s" % (time.perf_counter() - started, message), flush=True)

    section = meshes_section(out.parent / "bench_meshes.png", args.quick, log, peers)
    print(section)
    out.write_text(replace_section(out.read_text() if out.exists() else "", section, START, END))
    log("wrote %s" % out)


if __name__ == "__main__":
    main()
