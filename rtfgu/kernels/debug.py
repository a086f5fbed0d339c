# release: solves a03 a04 a05
"""The pixel debugger's numba side (rtfgu/debug.py): paths traced by the render's own loop
(rtfgu.kernels.render.trace, with the generated intersect_scene, shape_normal and shade of
rtfgu.kernels.dispatch), every bounce written to a record (render.record_bounce): [origin
(3), direction (3), t, scene index, kind, shader, normal (3), colour added (3)] in float64
(a float32 value converts exactly), NaN after the path's end. The scene index is -1 where
the ray left the scene (the colour is then the background); the normal is not computed
for base_color, whose shader reads none.

Every entry of the scene reaches the kernel as an array, empty for what the scene lacks
(render.shape_arrays and render.scene_tuple with ``empty``: shape kinds, texture kinds, the
environment, the samplers' own sets, a tree of no node a ray enters for a scene without a
mesh, an empty index for the spheres or instances the BVH holds), and the path loop is
always on, so one compiled kernel per precision serves every scene: an empty table tests
nothing, and a shader that ends the path ends it after one bounce as in a render. Primary
rays test every sphere with intersect_sphere rather than the render's per-frame eye terms
and culled candidates: the terms are the same operations on the same numbers
(rtfgu.kernels.intersect.sphere_eye_terms), and culling drops only spheres the ray cannot
hit.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ..kernels import own_sets, sphere_formula_id
from ..layout import CAMERA_WIDTH
from ..registry import LIGHTS
from ..tracers.whitted import MAX_DEPTH
from .camera import gen_ray
from .float3 import add, lit, scale
from .render import RECORD_FIELDS, record_bounce, scene_tuple, search_hit, shape_arrays, trace


@njit(cache=True, error_model="numpy")
def trace_records(camera, pixel, rays, shapes, lights, scene, settings, records):
    """With ``pixel`` = (ix, iy, width, height), iy counted from the bottom as in
    render_tile: that pixel's camera ray into ``records[0]``. With ix < 0: every row of
    ``rays`` ([origin, direction, tmin, tmax]) into ``records[k]``."""
    camera_kind, camera_row = camera
    ix, iy, width, height = pixel
    one = lit(1, camera_row[0])
    half = lit(0.5, one)
    no_candidates = np.empty(0, dtype=np.int64)
    for k in range(records.shape[0]):
        if ix >= 0:
            sx = lit(2, one) * (lit(ix, one) + half) / lit(width, one) - one
            sy = lit(2, one) * (lit(iy, one) + half) / lit(height, one) - one
            ray = gen_ray(camera_kind, camera_row, sx, sy)
        else:
            ray = ((rays[k, 0], rays[k, 1], rays[k, 2]), (rays[k, 3], rays[k, 4], rays[k, 5]),
                   rays[k, 6], rays[k, 7])
        if settings[1]:  # show_ray_direction: the direction as a colour, no hit
            color = add(scale(ray[1], half), (half, half, half))
            record_bounce(records[k], 0, ray, (ray[3], -1, -1), -1, ray[1], color)
        else:
            trace(ray, shapes, lights, scene, (None, no_candidates, -1), settings, MAX_DEPTH, (0, 0, 0, False),
                  search_hit, None, records[k])


def scene_arguments(flat, formula=None) -> tuple:
    """trace_records' (camera, shapes, lights, scene, settings) for the FlatScene ``flat``:
    every entry an array, empty for what the scene lacks (the module docstring), so their
    types are the same for every scene of a precision but for what its BVH holds."""
    shapes = shape_arrays(flat, empty=True)
    own_samples, own_shuffled, sobol = own_sets(flat)
    if own_samples is None:   # no sampler of its own: sets no row names (sampling.sampler_point)
        own_samples, own_shuffled = np.zeros((0, 2), dtype=flat.dtype), np.zeros(0, dtype=np.int32)
    lights = tuple(flat.lights[kind.name] for kind in LIGHTS) + (own_samples, own_shuffled, sobol)
    camera = (flat.camera_kind, np.ascontiguousarray(flat.camera.reshape(CAMERA_WIDTH)))
    settings = (flat.shadows, flat.show_ray_direction, sphere_formula_id(formula))
    return camera, shapes, lights, scene_tuple(flat, empty=True), settings


def numba_records(flat, formula=None, pixel=None, rays=None) -> np.ndarray:
    """Records (paths, MAX_DEPTH, RECORD_FIELDS) of the FlatScene ``flat``: of ``pixel``
    (ix, iy, width, height), iy from the bottom, or of every row of ``rays`` ((n, 8):
    origin, direction, tmin, tmax)."""
    camera, shapes, lights, scene, settings = scene_arguments(flat, formula)
    if pixel is None:
        rays = np.ascontiguousarray(rays, dtype=flat.dtype).reshape(-1, 8)
        pixel = (-1, -1, 1, 1)
    else:
        rays = np.zeros((1, 8), dtype=flat.dtype)
    records = np.full((len(rays), MAX_DEPTH, RECORD_FIELDS), np.nan)
    trace_records(camera, tuple(int(v) for v in pixel), rays, shapes, lights, scene, settings, records)
    return records
