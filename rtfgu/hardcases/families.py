# release: solves a03
"""The seeded hard-case families, each with its exact truth.

A family is a batch of rays, each with its own K shapes of one kind (K = 1 for most; 6 for a
triangle fan; 2 for a spawned ray: the surface it leaves and a neighbour just beyond). The
inputs are drawn in float64 from a seeded generator and then rounded once to the precision
of the path under test; the truth is computed from the rounded numbers (``exact``), so a
float32 family and a float64 family share their geometry but not their last bits. A shape
is a row of its lecture constructor's arguments (``rtfgu.hardcases.kinds``).

A family is a builder ``(rng, n) -> dict`` registered with ``@family(name, group, kind,
description)``; FAMILIES keeps them in the order they are defined here.
"""
from __future__ import annotations

import math
import zlib
from dataclasses import dataclass, field
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from ..layout import DTYPES
from ..ray import RAY_EPSILON
from . import exact
from .kinds import KINDS

DEFAULT_RAYS = 200

FAMILIES = {}


class FamilySpec(NamedTuple):
    group: str
    kind: str            # a name of rtfgu.hardcases.kinds.KINDS
    builder: object      # (rng, n) -> the raw rays and shapes, in float64
    description: str


def family(name: str, group: str, kind: str, description: str):
    """Register the builder below as the family ``name`` of ``kind`` shapes."""
    def register(builder):
        FAMILIES[name] = FamilySpec(group, kind, builder, description)
        return builder
    return register


@dataclass
class Family:
    """One family in one precision. ``shapes`` is (K, N, width); ``truth_t`` is the exact
    hit distance as a double-double (truth_t + truth_lo), inf on a miss.

    ``spawn`` (secondary-ray families) holds positions, normals and directions: the path
    turns them into ray origins and tmin with its own spawn rule, and the truth is the first
    real hit beyond the surface left (its own root at t ~ 0 excluded). ``self_threshold``
    separates that root from the real hits: a hit closer than it is a self-hit.
    ``invalid`` marks input the lecture layer must reject with a ValueError."""

    name: str
    group: str
    kind: str            # a name of rtfgu.hardcases.kinds.KINDS
    description: str
    precision: str
    origins: np.ndarray
    directions: np.ndarray
    tmin: np.ndarray
    tmax: np.ndarray
    shapes: np.ndarray
    truth_t: np.ndarray
    truth_lo: np.ndarray
    spawn: dict | None = None
    self_threshold: np.ndarray | None = None
    invalid: bool = False
    meta: dict = field(default_factory=dict)

    @property
    def size(self) -> int:
        return self.origins.shape[0]

    @property
    def truth_hit(self) -> np.ndarray:
        return np.isfinite(self.truth_t)


# --- small geometric helpers (float64, before rounding) -------------------------------

def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _random_unit(rng, n):
    return _unit(rng.normal(size=(n, 3)))


def _perpendicular(rng, u):
    return _unit(np.cross(u, rng.normal(size=u.shape)))


def _log_uniform(rng, lo, hi, n):
    return 10.0 ** rng.uniform(lo, hi, n)


def _aim_at_sphere(rng, center, radius, distance, impact):
    """Origins at ``distance`` from the centre and unit directions whose line passes at
    ``impact`` from it (impact < radius: a hit; > radius: a miss; = radius: tangent)."""
    n = center.shape[0]
    u = _random_unit(rng, n)
    v = _perpendicular(rng, u)
    sin_phi = (impact / distance)[:, None]
    d = -u * np.sqrt(1.0 - sin_phi ** 2) + v * sin_phi
    return center + u * distance[:, None], d


# --- spheres --------------------------------------------------------------------------

@family("sphere_tangent", "sphere", "sphere",
        "tangent and grazing rays: impact parameter r (1 +- 2e-4), origin 20-100 r away")
def _sphere_tangent(rng, n):
    c = rng.uniform(-2, 2, (n, 3))
    r = rng.uniform(0.5, 2.0, n)
    D = r * rng.uniform(20, 100, n)
    p = r * (1.0 + rng.uniform(-2e-4, 2e-4, n))
    o, d = _aim_at_sphere(rng, c, r, D, p)
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, r])])


@family("sphere_far_small", "sphere", "sphere",
        "far, small spheres: 100-1000 away, radius 1e-4..1e-3 of the distance")
def _sphere_far_small(rng, n):
    D = rng.uniform(100, 1000, n)
    r = D * _log_uniform(rng, -4, -3, n)
    o0 = rng.uniform(-1, 1, (n, 3))
    u = _random_unit(rng, n)
    c = o0 + u * D[:, None]
    o, d = _aim_at_sphere(rng, c, r, D, r * rng.uniform(0, 1.5, n))
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, r])])


@family("sphere_tiny_radius", "sphere", "sphere", "radii 1e-6..1e-3, origin 3e2..1e4 radii away")
def _sphere_tiny_radius(rng, n):
    r = _log_uniform(rng, -6, -3, n)
    D = r * _log_uniform(rng, 2.5, 4, n)
    c = _random_unit(rng, n) * (D * rng.uniform(0, 1, n))[:, None]
    o, d = _aim_at_sphere(rng, c, r, D, r * rng.uniform(0, 1.5, n))
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, r])])


@family("sphere_inside", "sphere", "sphere", "rays that start inside the sphere")
def _sphere_inside(rng, n):
    c = rng.uniform(-2, 2, (n, 3))
    r = rng.uniform(0.5, 2.0, n)
    o = c + _random_unit(rng, n) * (r * rng.uniform(0, 0.999, n))[:, None]
    return dict(origins=o, directions=_random_unit(rng, n), shapes=[np.column_stack([c, r])])


def _sphere_scaled_directions(rng, n, exponent: int):
    """Rays aimed at spheres, their directions scaled by 10^-exponent..10^exponent."""
    c = rng.uniform(-2, 2, (n, 3))
    r = rng.uniform(0.5, 2.0, n)
    o, d = _aim_at_sphere(rng, c, r, r * rng.uniform(2, 10, n), r * rng.uniform(0, 1.3, n))
    d = d * _log_uniform(rng, -exponent, exponent, n)[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, r])])


@family("sphere_direction_scale", "sphere", "sphere",
        "unnormalised directions of length 1e-12..1e12")
def _sphere_direction_scale(rng, n):
    return _sphere_scaled_directions(rng, n, 12)


@family("sphere_direction_scale_extreme", "sphere", "sphere",
        "unnormalised directions of length 1e-150..1e150 (d . d under- or overflows)")
def _sphere_direction_scale_extreme(rng, n):
    return _sphere_scaled_directions(rng, n, 150)


# --- instances (Suffern ch. 21): ellipsoids, the unit sphere scaled and moved ------------

def _ellipsoids(rng, n):
    """(scale, translate) of n ellipsoids: axes 0.25..4, within 2 of the origin."""
    return _log_uniform(rng, -0.6, 0.6, 3 * n).reshape(n, 3), rng.uniform(-2, 2, (n, 3))


def _to_world(scale, translate, o, d):
    """Object-space rays of the unit sphere as the world's rays of the ellipsoid."""
    return o * scale + translate, d * scale


@family("instance_tangent", "instance", "instance",
        "rays grazing an ellipsoid: through the unit sphere at impact 1 +- 2e-4 in object space, "
        "20-100 radii away")
def _instance_tangent(rng, n):
    scale, translate = _ellipsoids(rng, n)
    o, d = _aim_at_sphere(rng, np.zeros((n, 3)), np.ones(n), rng.uniform(20, 100, n),
                          1.0 + rng.uniform(-2e-4, 2e-4, n))
    o, d = _to_world(scale, translate, o, d)
    return dict(origins=o, directions=d, shapes=[np.column_stack([scale, translate])])


@family("instance_inside", "instance", "instance", "rays that start inside an ellipsoid")
def _instance_inside(rng, n):
    scale, translate = _ellipsoids(rng, n)
    o = _random_unit(rng, n) * rng.uniform(0, 0.999, n)[:, None]
    o, d = _to_world(scale, translate, o, _random_unit(rng, n))
    return dict(origins=o, directions=d, shapes=[np.column_stack([scale, translate])])


# --- planes ---------------------------------------------------------------------------

_INTEGER_NORMALS = np.array([(0, 0, 1), (1, 2, 2), (3, 4, 0), (1, 1, 1), (2, -1, 2), (0, 3, 4),
                             (1, -2, 5), (-4, 1, 8)], dtype=np.float64)


@family("plane_parallel", "plane", "plane",
        "d . n exactly 0 (a quarter of the rays lie in the plane)")
def _plane_parallel(rng, n):
    # Small integers times powers of two: d . n is exactly 0 in either precision.
    nrm = _INTEGER_NORMALS[rng.integers(0, len(_INTEGER_NORMALS), n)]
    m = rng.integers(-3, 4, (n, 3)).astype(np.float64)
    d = np.cross(nrm, m)
    bad = np.all(d == 0, axis=1)
    d[bad] = np.cross(nrm[bad], nrm[bad][:, ::-1] + np.array([1.0, 0.0, 0.0]))
    d *= 2.0 ** rng.integers(-8, 9, n)[:, None]
    nrm = nrm * 2.0 ** rng.integers(-4, 5, n)[:, None]
    a = rng.uniform(-5, 5, (n, 3))
    o = rng.uniform(-5, 5, (n, 3))
    o[: n // 4] = a[: n // 4]  # some rays lie in the plane itself
    return dict(origins=o, directions=d, shapes=[np.column_stack([a, nrm])])


@family("plane_nearly_parallel", "plane", "plane",
        "angle to the plane 1e-20..1e-2, origin 0.1-10 off the plane")
def _plane_nearly_parallel(rng, n):
    nrm = _random_unit(rng, n)
    along = _perpendicular(rng, nrm)
    theta = rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -20, -2, n)
    d = along * np.cos(theta)[:, None] + nrm * np.sin(theta)[:, None]
    a = rng.uniform(-5, 5, (n, 3))
    h = rng.choice([-1.0, 1.0], n) * rng.uniform(0.1, 10, n)
    o = a + nrm * h[:, None] + _perpendicular(rng, nrm) * rng.uniform(-5, 5, n)[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([a, nrm])])


@family("plane_start_on", "plane", "plane",
        "origins on the plane (rounded), tmin = RAY_EPSILON, coordinates up to 100")
def _plane_start_on(rng, n):
    nrm = _random_unit(rng, n)
    a = rng.uniform(-50, 50, (n, 3))
    o = a + _perpendicular(rng, nrm) * rng.uniform(0, 50, n)[:, None]
    return dict(origins=o, directions=_random_unit(rng, n), shapes=[np.column_stack([a, nrm])],
                tmin=np.full(n, RAY_EPSILON))


# --- triangles ------------------------------------------------------------------------

FAN = 6


def _grid(x):
    """x (inside [2, 4)) rounded to float32: every float32 of [2, 4) is a multiple of the same
    ulp, so sums and differences of such points that stay inside [2, 4) are exact, in
    float32 and in float64 alike (the float64 grid of [2, 4) refines the float32 one)."""
    return np.clip(x, 2.0, np.nextafter(4.0, 0.0)).astype(np.float32).astype(np.float64)


def _fans(rng, n):
    """A closed fan of FAN triangles around a centre vertex per ray, slightly non-planar,
    inside the box [2, 4)^3 where the float grid is uniform. Ring vertex i is vc + 2 e_i, so
    the point vc + e_i lies exactly on the shared edge (vc, ring i), in either precision."""
    vc = _grid(rng.uniform(2.9, 3.1, (n, 3)))
    t1 = _random_unit(rng, n)
    t2 = _perpendicular(rng, t1)
    nz = np.cross(t1, t2)
    half = []
    for i in range(FAN):
        ang = 2 * math.pi * i / FAN + rng.uniform(-0.3, 0.3, n)
        rad = rng.uniform(0.1, 0.4, n)
        e = (t1 * (rad * np.cos(ang))[:, None] + t2 * (rad * np.sin(ang))[:, None]
             + nz * rng.uniform(-0.05, 0.05, n)[:, None])
        half.append(_grid(vc + e) - vc)
    ring = [vc + 2.0 * e for e in half]
    return vc, ring, half, nz


def _fan_shapes(rng, vc, ring):
    """Triangle i is (vc, ring i, ring i+1), its vertex list rotated by a random cyclic
    shift (the winding kept), as in a mesh file: a shared edge is then e0 in one triangle
    and v1 -> v2 in the other, and the two slide tests round it differently. (With vc as
    v0 everywhere the slide test would share one numerator along the edges from vc.)"""
    shapes = []
    for i in range(FAN):
        verts = [vc, ring[i], ring[(i + 1) % FAN]]
        shift = rng.integers(0, 3, vc.shape[0])
        cols = [np.where((shift == 0)[:, None], verts[j],
                         np.where((shift == 1)[:, None], verts[(j + 1) % 3], verts[(j + 2) % 3]))
                for j in range(3)]
        shapes.append(np.column_stack(cols))
    return shapes


def _fan_origins(rng, target, nz, n):
    # target - origin is exact (both on the uniform grid), so the exact ray passes exactly
    # through the target point.
    side = rng.choice([-1.0, 1.0], n)[:, None]
    return _grid(target + nz * side * rng.uniform(0.3, 0.8, n)[:, None]
                 + rng.uniform(-0.2, 0.2, (n, 3)))


@family("tri_fan_edges", "triangle", "triangle",
        "rays exactly through an edge shared by two triangles of a closed 6-triangle fan")
def _tri_fan_edges(rng, n):
    vc, ring, half, nz = _fans(rng, n)
    pick = rng.integers(0, FAN, n)
    target = vc + np.stack(half)[pick, np.arange(n)]
    o = _fan_origins(rng, target, nz, n)
    return dict(origins=o, directions=target - o, shapes=_fan_shapes(rng, vc, ring))


@family("tri_fan_vertex", "triangle", "triangle",
        "rays exactly through the vertex shared by all six triangles of a closed fan")
def _tri_fan_vertex(rng, n):
    vc, ring, half, nz = _fans(rng, n)
    o = _fan_origins(rng, vc, nz, n)
    return dict(origins=o, directions=vc - o, shapes=_fan_shapes(rng, vc, ring))


def _triangle_rays(rng, v0, v1, v2, lo, hi, n, distance=(1.0, 5.0)):
    """Rays from above or below a triangle, aimed at barycentrics drawn from [lo, hi]."""
    e0, e1 = v1 - v0, v2 - v0
    b1 = rng.uniform(lo, hi, n)
    b2 = rng.uniform(lo, hi, n)
    target = v0 + e0 * b1[:, None] + e1 * b2[:, None]
    nrm = _unit(np.cross(e0, e1))
    size = np.linalg.norm(e0, axis=1)
    w = _unit(nrm * rng.choice([-1.0, 1.0], n)[:, None] + rng.uniform(-0.7, 0.7, (n, 3)))
    o = target + w * (size * rng.uniform(*distance, n))[:, None]
    return o, target - o


@family("tri_needle", "triangle", "triangle", "needle triangles 1e-7..1e-3 wide")
def _tri_needle(rng, n):
    v0 = rng.uniform(-2, 2, (n, 3))
    e = _random_unit(rng, n)
    side = _perpendicular(rng, e)
    length = rng.uniform(0.5, 2, n)[:, None]
    v1 = v0 + e * length
    v2 = v0 + e * length * rng.uniform(0, 1, n)[:, None] + side * _log_uniform(rng, -7, -3, n)[:, None]
    o, d = _triangle_rays(rng, v0, v1, v2, -0.5, 1.5, n)
    return dict(origins=o, directions=d, shapes=[np.column_stack([v0, v1, v2])])


@family("tri_zero_area", "triangle", "triangle",
        "zero-area triangles (collinear or repeated vertices): always a miss")
def _tri_zero_area(rng, n):
    # Collinear or repeated vertices with small integer coordinates: the area is exactly 0.
    v0 = rng.integers(-8, 9, (n, 3)).astype(np.float64)
    e = rng.integers(-3, 4, (n, 3)).astype(np.float64)
    e[np.all(e == 0, axis=1)] = (1.0, 2.0, 0.0)
    a = rng.integers(0, 4, n).astype(np.float64)[:, None]
    b = rng.integers(-3, 4, n).astype(np.float64)[:, None]
    v1, v2 = v0 + e * a, v0 + e * b
    target = v0 + e * rng.uniform(-1, 3, n)[:, None]
    o = target + _random_unit(rng, n) * rng.uniform(1, 5, n)[:, None]
    return dict(origins=o, directions=target - o, shapes=[np.column_stack([v0, v1, v2])])


@family("tri_nearly_parallel", "triangle", "triangle", "angle to the triangle's plane 1e-8..1e-1")
def _tri_nearly_parallel(rng, n):
    v0 = rng.uniform(-2, 2, (n, 3))
    v1 = v0 + rng.uniform(-1, 1, (n, 3))
    v2 = v0 + rng.uniform(-1, 1, (n, 3))
    e0, e1 = v1 - v0, v2 - v0
    nrm = _unit(np.cross(e0, e1))
    target = v0 + e0 * rng.uniform(-0.2, 1.2, n)[:, None] + e1 * rng.uniform(-0.2, 1.2, n)[:, None]
    along = _perpendicular(rng, nrm)
    theta = rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -1, n)
    d = along * np.cos(theta)[:, None] + nrm * np.sin(theta)[:, None]
    o = target - d * rng.uniform(1, 5, n)[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([v0, v1, v2])])


# --- disks (Suffern ch. 19) -----------------------------------------------------------

# Pythagorean triples (a, b, c): the rim point c + a u + b v of a disk of radius c with
# axis-aligned u, v and normal is exact in either precision, so a ray can pass exactly
# through the rim.
_TRIPLES = np.array([(3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25), (20, 21, 29)], dtype=np.float64)


@family("disk_rim", "disk", "disk",
        "rays through the rim: exactly (Pythagorean rim points, even rows) or 1e-8..1e-5 r off it")
def _disk_rim(rng, n):
    rows = np.arange(n)
    axis = rng.integers(0, 3, n)
    scale = 2.0 ** rng.integers(-4, 3, n)
    abc = _TRIPLES[rng.integers(0, len(_TRIPLES), n)] * scale[:, None]
    c = rng.integers(-8, 9, (n, 3)).astype(np.float64)
    nrm = np.zeros((n, 3))
    nrm[rows, axis] = rng.choice([-1.0, 1.0], n) * 2.0 ** rng.integers(-2, 3, n)
    rim = np.zeros((n, 3))
    rim[rows, (axis + 1) % 3] = abc[:, 0] * rng.choice([-1.0, 1.0], n)
    rim[rows, (axis + 2) % 3] = abc[:, 1] * rng.choice([-1.0, 1.0], n)
    target = c + rim
    o = target + rng.integers(-6, 7, (n, 3))
    o[rows, axis] = target[rows, axis] + rng.choice([-1.0, 1.0], n) * rng.integers(1, 7, n)
    r = abc[:, 2]
    # odd rows: a tilted disk, aimed just inside or outside its rim
    odd = rows % 2 == 1
    r_t = rng.uniform(0.5, 2.0, n)
    c_t, nrm_t, _, target_t = _disk_in_plane(
        rng, n, r_t, 1.0 + rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -5, n))
    o_t = target_t + _unit(nrm_t * rng.choice([-1.0, 1.0], n)[:, None]
                           + rng.uniform(-0.7, 0.7, (n, 3))) * rng.uniform(1, 5, n)[:, None]
    c, nrm, r = np.where(odd[:, None], c_t, c), np.where(odd[:, None], nrm_t, nrm), np.where(odd, r_t, r)
    target, o = np.where(odd[:, None], target_t, target), np.where(odd[:, None], o_t, o)
    return dict(origins=o, directions=target - o, shapes=[np.column_stack([c, nrm, r])])


def _disk_in_plane(rng, n, radius, reach):
    """A disk per ray and a point of its plane at reach * radius from the centre."""
    c = rng.uniform(-2, 2, (n, 3))
    nrm = _random_unit(rng, n)
    u = _perpendicular(rng, nrm)
    return c, nrm, u, c + u * (radius * reach)[:, None]


def _nearly_in_plane(rng, nrm, theta):
    along = _perpendicular(rng, nrm)
    return along * np.cos(theta)[:, None] + nrm * np.sin(theta)[:, None]


@family("disk_nearly_parallel", "disk", "disk", "angle to the disk's plane 1e-8..1e-1, aimed within 1.3 r")
def _disk_nearly_parallel(rng, n):
    r = rng.uniform(0.5, 2.0, n)
    c, nrm, _, target = _disk_in_plane(rng, n, r, rng.uniform(0, 1.3, n))
    d = _nearly_in_plane(rng, nrm, rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -1, n))
    o = target - d * rng.uniform(1, 5, n)[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, nrm, r])])


@family("disk_grazing_edge", "disk", "disk",
        "nearly parallel (1e-6..1e-2) rays through the rim, 1 +- 1e-4 r from the centre")
def _disk_grazing_edge(rng, n):
    r = rng.uniform(0.5, 2.0, n)
    c, nrm, u, target = _disk_in_plane(rng, n, r, 1.0 + rng.uniform(-1e-4, 1e-4, n))
    d = _nearly_in_plane(rng, nrm, rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -6, -2, n))
    o = target - d * (r * rng.uniform(0.5, 3, n))[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, nrm, r])])


# --- rectangles (Suffern ch. 19) ------------------------------------------------------

def _axis_rectangles(rng, n):
    """Axis-aligned rectangles with dyadic corners and edges (exact in either precision):
    p0, a along axis + 1, b along axis + 2, normal along ``axis``."""
    rows = np.arange(n)
    axis = rng.integers(0, 3, n)
    p0 = rng.integers(-8, 9, (n, 3)) * 0.5
    a = np.zeros((n, 3))
    b = np.zeros((n, 3))
    a[rows, (axis + 1) % 3] = rng.integers(1, 9, n) * 0.25 * rng.choice([-1.0, 1.0], n)
    b[rows, (axis + 2) % 3] = rng.integers(1, 9, n) * 0.25 * rng.choice([-1.0, 1.0], n)
    return rows, axis, p0, a, b


@family("rectangle_edge", "rectangle", "rectangle",
        "rays through an edge or a corner: exactly (even rows) or 1e-8..1e-5 of an edge off it")
def _rectangle_edge(rng, n):
    rows, axis, p0, a, b = _axis_rectangles(rng, n)
    # a point of an edge or a corner: s, t in {0, 1} for one of them at least
    s = rng.choice([0.0, 0.25, 0.5, 1.0], n)
    t = np.where(np.isin(s, (0.0, 1.0)), rng.choice([0.0, 0.5, 1.0], n), rng.choice([0.0, 1.0], n))
    odd = rows % 2 == 1
    nudge = np.where(odd, rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -5, n), 0.0)
    target = p0 + a * (s + nudge)[:, None] + b * (t + nudge)[:, None]
    o = target + rng.integers(-6, 7, (n, 3))
    o[rows, axis] = target[rows, axis] + rng.choice([-1.0, 1.0], n) * rng.integers(1, 7, n)
    return dict(origins=o, directions=target - o, shapes=[np.column_stack([p0, a, b])])


@family("rectangle_nearly_parallel", "rectangle", "rectangle",
        "angle to the rectangle's plane 1e-8..1e-1, aimed within -0.3..1.3 of its edges")
def _rectangle_nearly_parallel(rng, n):
    p0 = rng.uniform(-2, 2, (n, 3))
    nrm = _random_unit(rng, n)
    ua = _perpendicular(rng, nrm)
    ub = np.cross(nrm, ua)
    a = ua * rng.uniform(0.5, 2.0, n)[:, None]
    b = ub * rng.uniform(0.5, 2.0, n)[:, None]
    target = p0 + a * rng.uniform(-0.3, 1.3, n)[:, None] + b * rng.uniform(-0.3, 1.3, n)[:, None]
    d = _nearly_in_plane(rng, nrm, rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -1, n))
    o = target - d * rng.uniform(1, 5, n)[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([p0, a, b])])


# --- boxes (Suffern ch. 19) -----------------------------------------------------------

def _boxes(rng, n):
    """Boxes with dyadic corners (exact in either precision)."""
    p0 = rng.integers(-8, 9, (n, 3)) * 0.5
    return p0, p0 + rng.integers(1, 9, (n, 3)) * 0.25


@family("box_edge", "box", "box",
        "rays through an edge or a corner: exactly (even rows) or 1e-8..1e-5 of the size off it")
def _box_edge(rng, n):
    p0, p1 = _boxes(rng, n)
    # a point with two (an edge) or three (a corner) coordinates on the box's bounds
    s = rng.choice([0.0, 1.0], (n, 3))
    rows = np.arange(n)
    free = rng.integers(0, 3, n)
    s[rows, free] = np.where(rng.random(n) < 0.5, rng.uniform(0.1, 0.9, n), s[rows, free])
    odd = rows % 2 == 1
    s = s + np.where(odd, 1.0, 0.0)[:, None] * rng.choice([-1.0, 1.0], (n, 3)) * _log_uniform(rng, -8, -5, n)[:, None]
    target = p0 + (p1 - p0) * s
    o = target + _random_unit(rng, n) * rng.uniform(1, 6, n)[:, None]
    return dict(origins=o, directions=target - o, shapes=[np.column_stack([p0, p1])])


@family("box_parallel", "box", "box",
        "rays parallel to a face (a direction component exactly 0) in its plane, or nearly parallel "
        "(1e-8..1e-1)")
def _box_parallel(rng, n):
    p0, p1 = _boxes(rng, n)
    rows = np.arange(n)
    axis = rng.integers(0, 3, n)
    target = p0 + (p1 - p0) * rng.uniform(-0.2, 1.2, (n, 3))
    # the target on the face plane of ``axis`` (p0's or p1's), or just off it
    on = np.where(rng.random(n) < 0.5, p0[rows, axis], p1[rows, axis])
    target[rows, axis] = on
    d = rng.normal(size=(n, 3))
    odd = rows % 2 == 1
    d[rows, axis] = np.where(odd, rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -1, n), 0.0)
    d = _unit(d)
    o = target - d * rng.uniform(1, 5, n)[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([p0, p1])])


# --- open cylinders (Suffern ch. 19) --------------------------------------------------

@family("open_cylinder_rim", "open_cylinder", "open_cylinder",
        "rays through a rim: exactly (Pythagorean rim points, even rows) or 1e-8..1e-5 r off it, "
        "from outside or through the open end")
def _open_cylinder_rim(rng, n):
    rows = np.arange(n)
    scale = 2.0 ** rng.integers(-3, 2, n)
    abc = _TRIPLES[rng.integers(0, len(_TRIPLES), n)] * scale[:, None]
    r = abc[:, 2]
    y0 = rng.integers(-8, 1, n) * 0.5
    y1 = y0 + rng.integers(1, 9, n) * 0.5
    target = np.column_stack([abc[:, 0] * rng.choice([-1.0, 1.0], n), np.where(rng.random(n) < 0.5, y0, y1),
                              abc[:, 1] * rng.choice([-1.0, 1.0], n)])
    odd = rows % 2 == 1
    target[:, 1] += np.where(odd, rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -5, n) * r, 0.0)
    o = target + np.round(_random_unit(rng, n) * (r * rng.uniform(1, 4, n))[:, None] * 4) / 4
    return dict(origins=o, directions=target - o, shapes=[np.column_stack([y0, y1, r])])


@family("open_cylinder_grazing", "open_cylinder", "open_cylinder",
        "rays in a plane of constant y at r (1 +- 2e-4) from the axis, 2..20 r away, within the "
        "heights or on a rim")
def _open_cylinder_grazing(rng, n):
    r = rng.uniform(0.5, 2.0, n)
    y0 = rng.uniform(-2, 0, n)
    y1 = y0 + rng.uniform(0.5, 3, n)
    phi = rng.uniform(0, 2 * np.pi, n)
    radial = np.column_stack([np.cos(phi), np.zeros(n), np.sin(phi)])
    along = np.column_stack([-np.sin(phi), np.zeros(n), np.cos(phi)])
    impact = r * (1.0 + rng.uniform(-2e-4, 2e-4, n))
    height = np.where(rng.random(n) < 0.25, y1, rng.uniform(y0, y1))
    d = along + np.column_stack([np.zeros(n), rng.uniform(-1e-3, 1e-3, n), np.zeros(n)])
    o = radial * impact[:, None] - along * (r * rng.uniform(2, 20, n))[:, None]
    o[:, 1] = height
    return dict(origins=o, directions=d, shapes=[np.column_stack([y0, y1, r])])


# --- tori (Suffern ch. 19) ------------------------------------------------------------

def _torus_radii(rng, n):
    a = rng.uniform(1.0, 3.0, n)
    return a, a * rng.uniform(0.1, 0.6, n)


def _torus_meridians(rng, n):
    """(a, b, radial): n tori's radii and a unit direction from the axis in the xz plane each
    (the meridian's angle phi about y, uniform)."""
    a, b = _torus_radii(rng, n)
    phi = rng.uniform(0, 2 * np.pi, n)
    return a, b, np.column_stack([np.sin(phi), np.zeros(n), np.cos(phi)])


@family("torus_tangent_tube", "torus", "torus",
        "rays nearly tangent to the tube: b 1e-8..1e-4 off a tangent line at a random point of the "
        "surface (either side), origin 2..10 (a + b) back")
def _torus_tangent_tube(rng, n):
    a, b, radial = _torus_meridians(rng, n)
    theta = rng.uniform(0, 2 * np.pi, n)
    normal = radial * np.cos(theta)[:, None] + np.array([0.0, 1.0, 0.0]) * np.sin(theta)[:, None]
    point = radial * (a + b * np.cos(theta))[:, None] + np.array([0.0, 1.0, 0.0]) * (b * np.sin(theta))[:, None]
    off = rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -4, n) * b
    d = _perpendicular(rng, normal)
    o = point + normal * off[:, None] - d * ((a + b) * rng.uniform(2, 10, n))[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([a, b])])


@family("torus_hole_rim", "torus", "torus",
        "rays nearly along the axis (tilt up to 1e-3) through the hole at (a - b)(1 +- 1e-8..1e-3) from "
        "the axis at y = 0: grazing the inner equator, inside or outside it")
def _torus_hole_rim(rng, n):
    a, b, radial = _torus_meridians(rng, n)
    rho = (a - b) * (1.0 + rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -3, n))
    target = radial * rho[:, None]
    d = np.column_stack([np.zeros(n), -np.ones(n), np.zeros(n)]) + _random_unit(rng, n) * _log_uniform(rng, -9, -3, n)[:, None]
    d[: n // 4] = (0.0, -1.0, 0.0)   # exactly along the axis
    d = _unit(d) * rng.choice([-1.0, 1.0], n)[:, None]
    o = target - d * (b * rng.uniform(2, 10, n))[:, None]
    return dict(origins=o, directions=d, shapes=[np.column_stack([a, b])])


@family("torus_far", "torus", "torus",
        "origins 1e2..1e4 (a + b) away, aimed at a random point of the torus's box")
def _torus_far(rng, n):
    a, b = _torus_radii(rng, n)
    target = rng.uniform(-1, 1, (n, 3)) * np.column_stack([a + b, b, a + b])
    o = target + _random_unit(rng, n) * ((a + b) * _log_uniform(rng, 2, 4, n))[:, None]
    return dict(origins=o, directions=target - o, shapes=[np.column_stack([a, b])])


@family("torus_axis", "torus", "torus",
        "rays along the axis (even rows: always a miss) and rays through the centre in random "
        "directions, 2..10 (a + b) away (odd rows: the inner equator when nearly horizontal)")
def _torus_axis(rng, n):
    rows = np.arange(n)
    a, b = _torus_radii(rng, n)
    u = _random_unit(rng, n)
    u[rows % 2 == 0] = np.column_stack([np.zeros(n), rng.choice([-1.0, 1.0], n), np.zeros(n)])[rows % 2 == 0]
    o = u * ((a + b) * rng.uniform(2, 10, n))[:, None]
    return dict(origins=o, directions=-u, shapes=[np.column_stack([a, b])])


# --- part spheres and annuli (Suffern ch. 19, "Part objects") -------------------------

def _part_angles(rng, n):
    """Ranges of whole degrees, in steps of 15: phi within [0, 360], theta within [15, 165]
    (a polar bound of 0 or 180 is a pole, a rim of one point whose azimuth is undefined)."""
    phi_min = rng.integers(0, 20, n) * 15.0
    phi_max = np.minimum(phi_min + rng.integers(1, 13, n) * 15.0, 360.0)
    theta_min = rng.integers(1, 11, n) * 15.0
    theta_max = np.minimum(theta_min + rng.integers(1, 9, n) * 15.0, 165.0)
    return phi_min, phi_max, theta_min, theta_max


def _on_sphere(c, r, phi_deg, theta_deg):
    """The point of the sphere at azimuth phi (atan2(x, z)) and polar angle theta, in degrees."""
    phi, theta = np.radians(phi_deg), np.radians(theta_deg)
    return c + r[:, None] * np.column_stack([np.sin(theta) * np.sin(phi), np.cos(theta), np.sin(theta) * np.cos(phi)])


@family("part_sphere_rim", "part_sphere", "convex_part_sphere",
        "rays at a rim of the part (an azimuth or polar bound, whole degrees): on it as float64 "
        "puts it (even rows) or 1e-8..1e-5 degrees off, from 1..4 r away")
def _part_sphere_rim(rng, n):
    rows = np.arange(n)
    c = rng.uniform(-2, 2, (n, 3))
    r = rng.uniform(0.5, 2.0, n)
    phi_min, phi_max, theta_min, theta_max = _part_angles(rng, n)
    off = np.where(rows % 2 == 1, rng.choice([-1.0, 1.0], n) * _log_uniform(rng, -8, -5, n), 0.0)
    rim = rng.integers(0, 4, n)      # phi_min, phi_max, theta_min, theta_max
    phi = np.where(rim == 0, phi_min, np.where(rim == 1, phi_max, rng.uniform(phi_min, phi_max))) \
        + np.where(rim < 2, off, 0.0)
    theta = np.where(rim == 2, theta_min, np.where(rim == 3, theta_max, rng.uniform(theta_min, theta_max))) \
        + np.where(rim >= 2, off, 0.0)
    target = _on_sphere(c, r, phi, theta)
    o = target + _random_unit(rng, n) * (r * rng.uniform(1, 4, n))[:, None]
    return dict(origins=o, directions=target - o,
                shapes=[np.column_stack([c, r, phi_min, phi_max, theta_min, theta_max])])


@family("part_sphere_gap", "part_sphere", "convex_part_sphere",
        "rays into half a sphere (phi over 180 degrees) through its open side, aimed within "
        "0.9 r of the centre: the near root is outside the part, the far one mostly within")
def _part_sphere_gap(rng, n):
    c = rng.uniform(-2, 2, (n, 3))
    r = rng.uniform(0.5, 2.0, n)
    phi_min = rng.integers(0, 13, n) * 15.0
    phi_max = phi_min + 180.0
    outside = _on_sphere(np.zeros((n, 3)), np.ones(n), phi_min - 90.0, rng.uniform(30.0, 150.0, n))
    o = c + outside * (r * rng.uniform(2, 5, n))[:, None]
    aim = c + _random_unit(rng, n) * (r * rng.uniform(0, 0.9, n))[:, None]
    return dict(origins=o, directions=aim - o,
                shapes=[np.column_stack([c, r, phi_min, phi_max, np.zeros(n), np.full(n, 180.0)])])


@family("annulus_rim", "annulus", "annulus",
        "rays through the inner or the outer rim: exactly (Pythagorean rim points, even rows) or "
        "1e-8..1e-5 r off it")
def _annulus_rim(rng, n):
    disk = _disk_rim(rng, n)          # rays through the rim of radius r of a disk
    rows = disk["shapes"][0]
    r = rows[:, 6]
    inner = rng.random(n) < 0.5       # that rim is the inner one (outer 2r) or the outer one (inner r/2)
    return dict(origins=disk["origins"], directions=disk["directions"],
                shapes=[np.column_stack([rows[:, :6], np.where(inner, r, r / 2), np.where(inner, 2 * r, r)])])


@family("annulus_nearly_parallel", "annulus", "annulus",
        "angle to the annulus's plane 1e-8..1e-1, aimed within 1.3 r_o, r_i = 0.2..0.8 r_o")
def _annulus_nearly_parallel(rng, n):
    disk = _disk_nearly_parallel(rng, n)
    rows = disk["shapes"][0]
    return dict(origins=disk["origins"], directions=disk["directions"],
                shapes=[np.column_stack([rows[:, :6], rows[:, 6] * rng.uniform(0.2, 0.8, n), rows[:, 6]])])


# --- large offsets and tiny scenes ----------------------------------------------------

@family("offset_sphere", "offset", "sphere", "spheres 1e4..1e7 from the world origin")
def _offset_sphere(rng, n):
    offset = _random_unit(rng, n) * _log_uniform(rng, 4, 7, n)[:, None]
    r = _log_uniform(rng, 0, 1, n)
    c = offset + rng.uniform(-1, 1, (n, 3)) * r[:, None]
    o, d = _aim_at_sphere(rng, c, r, r * rng.uniform(3, 10, n), r * rng.uniform(0, 1.3, n))
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, r])])


@family("offset_triangle", "offset", "triangle", "triangles 1e4..1e7 from the world origin")
def _offset_triangle(rng, n):
    offset = _random_unit(rng, n) * _log_uniform(rng, 4, 7, n)[:, None]
    size = _log_uniform(rng, 0, 1, n)[:, None]
    v0 = offset + rng.uniform(-1, 1, (n, 3)) * size
    v1 = v0 + rng.uniform(-1, 1, (n, 3)) * size
    v2 = v0 + rng.uniform(-1, 1, (n, 3)) * size
    o, d = _triangle_rays(rng, v0, v1, v2, -0.2, 1.2, n)
    return dict(origins=o, directions=d, shapes=[np.column_stack([v0, v1, v2])])


@family("tiny_sphere", "offset", "sphere", "scenes of size 1e-6..1e-3, tmin 0")
def _tiny_sphere(rng, n):
    scale = _log_uniform(rng, -6, -3, n)
    c = rng.uniform(-1, 1, (n, 3)) * scale[:, None]
    r = scale * rng.uniform(0.3, 1, n)
    o, d = _aim_at_sphere(rng, c, r, r * rng.uniform(2, 10, n), r * rng.uniform(0, 1.3, n))
    return dict(origins=o, directions=d, shapes=[np.column_stack([c, r])])


@family("tiny_triangle", "offset", "triangle", "scenes of size 1e-6..1e-3, tmin 0")
def _tiny_triangle(rng, n):
    size = _log_uniform(rng, -6, -3, n)[:, None]
    v0 = rng.uniform(-1, 1, (n, 3)) * size
    v1 = v0 + rng.uniform(-1, 1, (n, 3)) * size
    v2 = v0 + rng.uniform(-1, 1, (n, 3)) * size
    o, d = _triangle_rays(rng, v0, v1, v2, -0.2, 1.2, n)
    return dict(origins=o, directions=d, shapes=[np.column_stack([v0, v1, v2])])


# --- secondary rays -------------------------------------------------------------------
# mode per ray: 0 "out" (shadow or mirror ray, a neighbour surface just beyond),
# 1 "in" (refracted ray, a neighbour just inside), 2 "none" (out, nothing beyond).

def _spawn_directions(rng, nrm, mode):
    n = nrm.shape[0]
    cos = rng.uniform(0.2, 1.0, n)[:, None]
    v = _perpendicular(rng, nrm)
    sign = np.where(mode == 1, -1.0, 1.0)[:, None]
    return nrm * (cos * sign) + v * np.sqrt(1 - cos ** 2)


@family("spawn_sphere", "secondary", "sphere",
        "rays leaving a sphere (out, in, out with nothing beyond), scale 1e-3..1e4")
def _spawn_sphere(rng, n):
    scale = _log_uniform(rng, -3, 4, n)
    c = rng.uniform(-1, 1, (n, 3)) * scale[:, None]
    r = scale * rng.uniform(0.5, 2, n)
    u = _random_unit(rng, n)
    mode = np.arange(n) % 3
    delta = r * _log_uniform(rng, -3, -2, n)
    r2 = np.where(mode == 0, r + delta, np.where(mode == 1, r - delta, 0.5 * r))
    return dict(positions=c + u * r[:, None], normals=u, directions=_spawn_directions(rng, u, mode),
                shapes=[np.column_stack([c, r]), np.column_stack([c, r2])],
                self_threshold=1e-4 * r, mode=mode)


@family("spawn_plane", "secondary", "plane",
        "rays leaving a plane, a parallel plane 1e-3..1e-2 beyond, scale 1e-3..1e4")
def _spawn_plane(rng, n):
    scale = _log_uniform(rng, -3, 4, n)
    a = rng.uniform(-1, 1, (n, 3)) * scale[:, None]
    nrm = _random_unit(rng, n)
    p = a + _perpendicular(rng, nrm) * (scale * rng.uniform(0, 1, n))[:, None]
    mode = np.arange(n) % 3
    delta = scale * _log_uniform(rng, -3, -2, n)
    shift = np.where(mode == 0, delta, -delta)[:, None]
    return dict(positions=p, normals=nrm, directions=_spawn_directions(rng, nrm, mode),
                shapes=[np.column_stack([a, nrm]), np.column_stack([a + nrm * shift, nrm])],
                self_threshold=1e-4 * scale, mode=mode)


@family("spawn_triangle", "secondary", "triangle",
        "rays leaving a triangle, a parallel one 1e-3..1e-2 beyond, scale 1e-3..1e4")
def _spawn_triangle(rng, n):
    scale = _log_uniform(rng, -3, 4, n)[:, None]
    v0 = rng.uniform(-1, 1, (n, 3)) * scale
    v1 = v0 + _random_unit(rng, n) * scale
    v2 = v0 + _unit(_perpendicular(rng, v1 - v0) + (v1 - v0) / scale * 0.3) * scale
    nrm = _unit(np.cross(v1 - v0, v2 - v0))
    p = v0 + (v1 - v0) * rng.uniform(0.2, 0.4, n)[:, None] + (v2 - v0) * rng.uniform(0.2, 0.4, n)[:, None]
    mode = np.arange(n) % 3
    delta = scale[:, 0] * _log_uniform(rng, -3, -2, n)
    shift = nrm * np.where(mode == 0, delta, -delta)[:, None]
    return dict(positions=p, normals=nrm, directions=_spawn_directions(rng, nrm, mode),
                shapes=[np.column_stack([v0, v1, v2]), np.column_stack([v0 + shift, v1 + shift, v2 + shift])],
                self_threshold=1e-4 * scale[:, 0], mode=mode)


# --- NaN and infinite input -----------------------------------------------------------

def _corrupt(rng, built, kind):
    """Put a NaN, +inf or -inf into one field of each ray: origin, direction (or a zero
    direction), tmin, or the shape. The truth of every such ray is a miss."""
    n = built["origins"].shape[0]
    o, d = built["origins"].copy(), built["directions"].copy()
    s = built["shapes"][0].copy()
    tmin = np.zeros(n)
    bad = rng.choice([math.nan, math.inf, -math.inf], n)
    field_of = rng.integers(0, 5, n)
    for i in range(n):
        f = field_of[i]
        if f == 0:
            o[i, rng.integers(0, 3)] = bad[i]
        elif f == 1:
            d[i, rng.integers(0, 3)] = bad[i]
        elif f == 2:
            d[i] = 0.0
        elif f == 3:
            tmin[i] = math.nan
        else:
            s[i, rng.integers(0, KINDS[kind].width)] = bad[i]
    return dict(origins=o, directions=d, shapes=[s], tmin=tmin, field_of=field_of)


@family("invalid_sphere", "invalid", "sphere", "NaN, inf or zero direction in one field")
def _invalid_sphere(rng, n):
    return _corrupt(rng, _sphere_inside(rng, n), "sphere")


@family("invalid_plane", "invalid", "plane", "NaN, inf or zero direction in one field")
def _invalid_plane(rng, n):
    return _corrupt(rng, _plane_nearly_parallel(rng, n), "plane")


@family("invalid_triangle", "invalid", "triangle", "NaN, inf or zero direction in one field")
def _invalid_triangle(rng, n):
    return _corrupt(rng, _tri_needle(rng, n), "triangle")


def _round_ulps(rng, x, dtype):
    """x rounded to dtype, then moved by -1, 0 or +1 ulp per component: a hit point as a
    path computes it, within a few roundings of the surface."""
    x = x.astype(dtype)
    step = rng.integers(-1, 2, x.shape)
    up = np.nextafter(x, np.array(np.inf, dtype))
    down = np.nextafter(x, np.array(-np.inf, dtype))
    return np.where(step > 0, up, np.where(step < 0, down, x))


def _truth(kind, o, d, tmin, tmax, shape):
    return getattr(exact, kind)(o, d, tmin, tmax, *KINDS[kind].split(shape))


def _spawn_truth(kind, p, w, tmax, own, neighbour, threshold):
    """The first real hit from p along w: the neighbour (t > 0) or the surface left, except
    its root at t ~ 0 (only a sphere has a second, real root)."""
    best = exact.MISS
    if kind == "sphere":
        roots = exact.sphere_roots(p, w, own[:3], own[3])
        if roots is not None:
            for t in roots[:2]:
                if t > threshold and (math.isinf(tmax) or t < tmax):
                    best = min(best, exact.dd_from_mpf(t))
                    break
    return min(best, _truth(kind, p, w, 0.0, tmax, neighbour))


@lru_cache(maxsize=None)
def build(name: str, precision: str, n: int = DEFAULT_RAYS, seed: int = 2024) -> Family:
    """The family ``name`` in ``precision`` ("float32" or "float64"), with its exact truth."""
    if name not in FAMILIES:
        raise ValueError("family must be one of %s, got %r" % (", ".join(FAMILIES), name))
    if precision not in DTYPES:
        raise ValueError("precision must be one of %s, got %r" % (", ".join(DTYPES), precision))
    dtype = DTYPES[precision]
    group, kind, builder, description = FAMILIES[name]
    rng = np.random.default_rng([seed, zlib.crc32(name.encode())])
    with np.errstate(all="ignore"):
        raw = builder(rng, n)
        shapes = np.stack(raw["shapes"]).astype(dtype)
        tmax = np.full(n, np.inf, dtype)
        spawn = None
        threshold = None
        if "positions" in raw:
            positions = _round_ulps(rng, raw["positions"], dtype)
            spawn = dict(positions=positions, normals=raw["normals"].astype(dtype),
                         directions=raw["directions"].astype(dtype), mode=raw["mode"])
            origins, directions = positions, spawn["directions"]
            tmin = np.zeros(n, dtype)
            threshold = raw["self_threshold"]
        else:
            origins = raw["origins"].astype(dtype)
            directions = raw["directions"].astype(dtype)
            tmin = np.asarray(raw.get("tmin", np.zeros(n)), dtype=dtype)
    truth = []
    for i in range(n):
        if spawn is not None:
            truth.append(_spawn_truth(kind, origins[i], directions[i], float(tmax[i]),
                                      shapes[0, i], shapes[1, i], threshold[i]))
        else:
            truth.append(min(_truth(kind, origins[i], directions[i], float(tmin[i]), float(tmax[i]),
                                    shapes[k, i]) for k in range(shapes.shape[0])))
    meta = {key: raw[key] for key in ("field_of",) if key in raw}
    return Family(name=name, group=group, kind=kind, description=description, precision=precision,
                  origins=origins, directions=directions, tmin=tmin, tmax=tmax, shapes=shapes,
                  truth_t=np.array([t[0] for t in truth]), truth_lo=np.array([t[1] for t in truth]),
                  spawn=spawn, self_threshold=threshold, invalid=(group == "invalid"), meta=meta)
