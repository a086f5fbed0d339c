"""The numba path: the lecture layer's renderer as jitted kernels over the flat layout.

``render_numba(scene, width, height, precision)`` compiles the scene (rtfgu.layout, which
validates it), picks the kernel for what the scene has, and runs it on all cores. The
kernel modules follow the slides: camera.gen_ray, intersect.intersect_plane /
intersect_triangle / intersect_sphere / intersect_scene, lights.sample_point_light,
shaders.lambertian / phong / mirror / transparent / shade, render.trace / render_kernel.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..layout import CAMERA_WIDTH, PINHOLE, PINHOLE_EYE, compile_scene
from ..material import GLOSSY, MIRROR, TRANSPARENT
from ..shading import MAX_DEPTH
from .culling import cone_table
from .intersect import SPHERE_FORMULAS, sphere_eye_terms
from .render import PRIMARY, SECONDARY, SHADOW, TILE, render_kernel

__all__ = ["render_numba", "RayCounts", "DEFAULT_SPHERE_FORMULA"]

# The sphere formula of a numba render unless one is asked for: the slide's, because Ray
# Tracing Gems ch. 7 cost 16-18 % on the 64-sphere render (docs/robust_defaults.md).
DEFAULT_SPHERE_FORMULA = "slide"


def sphere_formula_id(formula) -> int:
    """intersect.SPHERE_SLIDE / SPHERE_ROBUST for "slide" / "robust" (None: the default)."""
    if formula is None:
        formula = DEFAULT_SPHERE_FORMULA
    if formula not in SPHERE_FORMULAS:
        raise ValueError("formula must be one of %s, got %r"
                         % (", ".join(SPHERE_FORMULAS), formula))
    return SPHERE_FORMULAS[formula]


@dataclass
class RayCounts:
    primary: int
    shadow: int
    secondary: int

    @property
    def total(self) -> int:
        return self.primary + self.shadow + self.secondary


def _coprime_stride(n: int) -> int:
    """A stride near n / golden ratio with gcd(stride, n) = 1, so k -> k * stride mod n
    visits every tile once and neighbouring k land far apart."""
    stride = max(1, int(n * 0.6180339887))
    while math.gcd(stride, n) != 1:
        stride += 1
    return stride


def kernel_arguments(flat, width: int, height: int, formula=None):
    """The render_kernel arguments for a FlatScene, with None for what the scene lacks;
    ``formula`` the sphere formula ("slide", "robust" or None for the default)."""
    sphere_formula = sphere_formula_id(formula)
    def present(array, index):
        return (array, index) if len(array) else (None, None)

    planes, plane_index = present(flat.planes, flat.plane_index)
    triangles, triangle_index = present(flat.triangles, flat.triangle_index)
    spheres, sphere_index = present(flat.spheres, flat.sphere_index)
    camera = np.ascontiguousarray(flat.camera.reshape(CAMERA_WIDTH))
    sphere_eye = cones = None
    camera64 = camera.astype(np.float64)
    if spheres is not None:
        sphere_eye = np.zeros((len(spheres), 4), dtype=flat.dtype)  # one type for both cameras
    if spheres is not None and flat.camera_kind == PINHOLE:
        # Every primary ray starts at the eye: temp and c per sphere once per frame, and a
        # cone per sphere for the per-tile culling.
        sphere_eye_terms(camera[PINHOLE_EYE:PINHOLE_EYE + 3].copy(), spheres, sphere_eye)
        cones = cone_table(camera64, spheres)
    lights = flat.lights if len(flat.lights) else None
    continues = any(int(s) in (MIRROR, TRANSPARENT, GLOSSY) for s in flat.shaders)
    bounces = MAX_DEPTH if continues else None
    tiles = ((width + TILE - 1) // TILE) * ((height + TILE - 1) // TILE)
    return (width, height, flat.camera_kind, camera, planes, plane_index, triangles,
            triangle_index, spheres, sphere_index, sphere_eye, cones, camera64, sphere_formula,
            flat.materials, flat.shaders,
            lights, flat.background, flat.shadows, flat.show_ray_direction, bounces,
            _coprime_stride(tiles)), tiles


def render_numba(scene, width: int, height: int, precision: str = "float64",
                 with_counts: bool = False, formula: str | None = None):
    """Render on the numba path; a (height, width, 3) float64 array, row 0 at the top.
    With ``with_counts`` also the RayCounts of the render. ``formula``: the sphere test,
    "slide" (lecture 01) or "robust" (Ray Tracing Gems ch. 7); None is
    DEFAULT_SPHERE_FORMULA."""
    sphere_formula_id(formula)  # a bad formula is refused before the scene is compiled
    flat = compile_scene(scene, precision)
    args, tiles = kernel_arguments(flat, width, height, formula)
    image = np.empty((height, width, 3), dtype=flat.dtype)
    counts = np.zeros((tiles, 3), dtype=np.int64)
    render_kernel(*args, image, counts)
    image = image.astype(np.float64, copy=False)  # float64 already: no second 1.5 MB pass
    if with_counts:
        total = counts.sum(axis=0)
        return image, RayCounts(int(total[PRIMARY]), int(total[SHADOW]), int(total[SECONDARY]))
    return image
