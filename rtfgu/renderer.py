"""Rendering a scene: the slide's loop over pixels (lecture 01, "Rendering a Scene") and the
02562 path loop (``main_fs``) that traces each pixel's ray.

``render(scene, width, height)`` returns a float array of shape (height, width, 3), row 0 at
the top (+y), before gamma. The slide's loop counts iy from the bottom (sy = -1), so pixel
(ix, iy) is stored at row height - 1 - iy.
"""
from __future__ import annotations

import importlib.util

import numpy as np

from .float3 import Float3
from .ray import Ray
from .shading import MAX_DEPTH, HitInfo, shade

BACKENDS = ("reference", "numba", "wgpu")
DEFAULT_BACKEND = "reference"
PRECISIONS = ("float64", "float32")
# Intersection formulas: the lecture's and the robust ones (Ray Tracing Gems ch. 7 for the
# sphere, rtfgu/robust.py). The reference computes the slide formulas only. Each path's
# default, decided once here from the measured cost and hard-case counts in
# docs/robust_defaults.md: numba keeps the slide formula (the robust sphere costs it
# speed on many spheres), WGSL takes the robust one (no measurable cost there).
FORMULAS = ("slide", "robust")
DEFAULT_FORMULAS = {"reference": "slide", "numba": "slide", "wgpu": "robust"}


def trace(scene, r: Ray) -> Float3:
    """The 02562 path loop: shade each hit until a shader ends the path (has_hit stays
    true) or the ray leaves the scene (background), at most MAX_DEPTH times."""
    if scene.show_ray_direction:
        return r.direction * 0.5 + Float3(0.5)
    result = Float3(0.0)
    hit = HitInfo()
    for i in range(MAX_DEPTH):
        if scene.intersect(r, hit):
            result += shade(scene, r, hit)
        else:
            result += scene.background
            break
        if hit.has_hit:
            break
    return result


def render_reference(scene, width: int, height: int, progress=None) -> np.ndarray:
    """The lecture layer's renderer, pure Python. ``progress(rows_done, height)`` is called
    after each row if given."""
    image = np.zeros((height, width, 3), dtype=np.float64)
    for iy in range(height):
        for ix in range(width):
            sx = 2 * (ix + 0.5) / width - 1
            sy = 2 * (iy + 0.5) / height - 1

            ray = scene.camera.gen_ray(sx, sy)

            color = trace(scene, ray)

            image[height - 1 - iy, ix] = (color.x, color.y, color.z)
        if progress is not None:
            progress(iy + 1, height)
    return image


def check_size(width, height) -> None:
    for name, value in (("width", width), ("height", height)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
            raise ValueError("%s must be an integer >= 1, got %r" % (name, value))


def render(scene, width: int, height: int, backend: str = "reference",
           precision: str | None = None, progress=None, formula: str | None = None) -> np.ndarray:
    """Render ``scene`` to a (height, width, 3) float64 array, row 0 at the top, before gamma.

    backend: "reference" (the lecture layer, pure Python) or "numba" (rtfgu.kernels, all cores).
    precision: "float64" (the reference computes in Python floats) or "float32" (numba only).
    formula: the sphere test, "slide" or "robust" (numba and wgpu); None is each backend's
    default (the reference's is "slide", its only one).
    """
    check_size(width, height)
    if backend not in BACKENDS:
        raise ValueError("backend must be one of %s, got %r" % (", ".join(BACKENDS), backend))
    if precision is None:  # each backend's own: WGSL computes in float32
        precision = "float32" if backend == "wgpu" else "float64"
    if precision not in PRECISIONS:
        raise ValueError("precision must be one of %s, got %r" % (", ".join(PRECISIONS), precision))
    if formula is not None and formula not in FORMULAS:
        raise ValueError("formula must be one of %s, got %r" % (", ".join(FORMULAS), formula))
    scene.validate()
    if backend == "reference":
        if precision != "float64":
            raise ValueError("precision: the reference backend computes in float64 only")
        if formula not in (None, "slide"):
            raise ValueError("formula: the reference backend computes the slide formulas only, got %r"
                             % formula)
        image = render_reference(scene, width, height, progress)
    elif backend == "numba":
        if importlib.util.find_spec(__package__ + ".kernels") is None:
            raise ValueError("backend: the numba path is not part of this release of rtfgu (it computes "
                             "the assignments' functions again); render with backend='reference'")
        from .kernels import render_numba  # numba is imported only when asked for
        image = render_numba(scene, width, height, precision, formula=formula)
    elif backend == "wgpu":
        if precision != "float32":
            raise ValueError("precision: the wgpu backend computes in float32 only, got %r" % precision)
        from .wgsl import render_wgpu  # wgpu is imported only when asked for
        image = render_wgpu(scene, width, height, progress, formula=formula)
    if not np.all(np.isfinite(image)):
        raise ValueError("the %s backend produced non-finite pixels" % backend)
    return image
