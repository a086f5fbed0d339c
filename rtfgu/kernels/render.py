"""The pixel loop on all cores: the lecture's render loop (lecture 01 "Rendering a Scene")
and the 02562 path loop (``main_fs``), in tiles under ``prange``.

Every pixel is computed on its own from the same inputs, so the image is the same bit for
bit for any number of threads. Arguments that a scene does not need are None (planes,
triangles, spheres, lights, bounces); numba compiles a kernel per such combination and
removes the code behind ``is None`` tests, so a scene pays only for what it has.

The per-pixel path (trace, intersect_scene, shade, lambertian, phong) is inlined by numba
(``inline="always"``, each with a single call site to keep the compile time down): an
out-of-line call that takes arrays cost more than the intersections it made.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from ..layout import PLANE, PLANE_NORMAL, SPHERE, SPHERE_CENTER, TRI_N, TRIANGLE
from ..material import BASE_COLOR
from ..shading import SPAWN_EPSILON
from .camera import gen_ray
from .float3 import add, lit, load3, normalize, row3, scale, sub
from .culling import tile_candidates
from .intersect import intersect_scene
from .shaders import shade

# Tiles of TILE x TILE pixels are the unit of parallel work.
TILE = 16

# counts columns: rays cast per tile, by kind.
PRIMARY = 0
SHADOW = 1
SECONDARY = 2


@njit(cache=True, error_model="numpy", inline="always")
def shape_normal(kind, row, position, planes, triangles, spheres):
    """normal_at(position) of the shape hit: the unit normal of a plane or triangle, and
    normalize(position - center) on a sphere."""
    if planes is not None:
        if kind == PLANE:
            return normalize(row3(planes, row, PLANE_NORMAL))
    if triangles is not None:
        if kind == TRIANGLE:
            return normalize(row3(triangles, row, TRI_N))
    if spheres is not None:
        if kind == SPHERE:
            return normalize(sub(position, row3(spheres, row, SPHERE_CENTER)))
    return position  # not reached: a hit has one of the kinds above


@njit(cache=True, error_model="numpy", inline="always")
def trace(origin, direction, tmin, tmax, planes, plane_index, triangles, triangle_index,
          spheres, sphere_index, sphere_eye, candidates, n_candidates, from_eye, sphere_formula,
          materials, shaders, lights, background, shadows, bounces):
    """The 02562 path loop (rtfgu.renderer.trace): shade each hit until a shader ends the
    path or the ray leaves the scene (background), at most ``bounces`` (MAX_DEPTH) times.
    Returns (radiance, shadow rays, secondary rays)."""
    zero = lit(0, tmin)
    result = (zero, zero, zero)
    n_shadow = 0
    n_secondary = 0
    depth = 1 if bounces is None else bounces
    for i in range(depth):
        if i > 0:
            n_secondary += 1
        t, idx, kind, row = intersect_scene(origin, direction, tmin, tmax, planes, plane_index,
                                            triangles, triangle_index, spheres, sphere_index,
                                            sphere_eye, candidates, n_candidates,
                                            from_eye and i == 0, sphere_formula)
        if idx < 0:
            result = add(result, load3(background, 0))
            break
        # HitInfo: position = ray(t) = o + d t, the normal of the shape hit, its material.
        position = add(origin, scale(direction, t))
        shader = shaders[idx]
        if shader == BASE_COLOR:
            normal = position  # base_color reads no normal: a flat-colour scene skips normal_at
        else:
            normal = shape_normal(kind, row, position, planes, triangles, spheres)
        color, has_hit, new_direction, shadow_rays = shade(
            shader, materials[idx], direction, position, normal, lights, shadows, bounces,
            planes, triangles, spheres, sphere_formula)
        result = add(result, color)
        n_shadow += shadow_rays
        if has_hit:
            break
        # The lecture's _continue_path: a new ray with a fresh tmax.
        origin = position
        direction = new_direction
        tmin = lit(SPAWN_EPSILON, zero)
        tmax = lit(math.inf, zero)
    return result, n_shadow, n_secondary


@njit(parallel=True, cache=True, error_model="numpy")
def render_kernel(width, height, camera_kind, camera, planes, plane_index, triangles,
                  triangle_index, spheres, sphere_index, sphere_eye, cones, camera64,
                  sphere_formula, materials, shaders, lights, background, shadows,
                  show_ray_direction, bounces, tile_stride, image, counts):
    """Fill ``image`` (height, width, 3), row 0 at the top, and ``counts`` (tiles, 3).

    For a pinhole camera with spheres, ``sphere_eye`` holds each sphere's temp and c for rays
    from the eye and ``cones`` (culling.sphere_cones, with the float64 ``camera64``) lets each
    tile test only the spheres its primary rays can hit; otherwise cones is None and
    sphere_eye unused (None without spheres). ``sphere_formula`` (intersect.SPHERE_SLIDE or
    SPHERE_ROBUST) picks the sphere test of every ray, primary, secondary and shadow."""
    from_eye = cones is not None
    n_spheres = 0 if spheres is None else spheres.shape[0]
    tiles_x = (width + TILE - 1) // TILE
    tiles_y = (height + TILE - 1) // TILE
    n_tiles = tiles_x * tiles_y
    for k in prange(n_tiles):
        # prange hands each thread a contiguous block of k; the stride (coprime with
        # n_tiles) spreads every block over the whole image, so the threads share the work.
        tile = (k * tile_stride) % n_tiles
        x0 = (tile % tiles_x) * TILE
        y0 = (tile // tiles_x) * TILE
        n_shadow = 0
        n_secondary = 0
        n_primary = 0
        x1 = min(x0 + TILE, width)
        y1 = min(y0 + TILE, height)
        candidates = np.empty(n_spheres, dtype=np.int64)
        n_candidates = 0
        if cones is not None:
            n_candidates = tile_candidates(camera64, cones, x0, x1, y0, y1, width, height,
                                           candidates)
        for iy in range(y0, y1):
            for ix in range(x0, x1):
                one = lit(1, camera[0])
                sx = lit(2, one) * (lit(ix, one) + lit(0.5, one)) / lit(width, one) - one
                sy = lit(2, one) * (lit(iy, one) + lit(0.5, one)) / lit(height, one) - one
                origin, direction, tmin, tmax = gen_ray(camera_kind, camera, sx, sy)
                n_primary += 1
                if show_ray_direction:
                    half = lit(0.5, one)
                    color = add(scale(direction, half), (half, half, half))
                else:
                    color, shadow_rays, secondary_rays = trace(
                        origin, direction, tmin, tmax, planes, plane_index, triangles,
                        triangle_index, spheres, sphere_index, sphere_eye, candidates,
                        n_candidates, from_eye, sphere_formula, materials, shaders, lights,
                        background, shadows, bounces)
                    n_shadow += shadow_rays
                    n_secondary += secondary_rays
                out = image[height - 1 - iy, ix]
                out[0] = color[0]
                out[1] = color[1]
                out[2] = color[2]
        counts[tile, PRIMARY] = n_primary
        counts[tile, SHADOW] = n_shadow
        counts[tile, SECONDARY] = n_secondary
