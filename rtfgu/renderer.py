"""Rendering a scene: the slide's loop over pixels (lecture 01, "Rendering a Scene") and the
02562 path loop (``main_fs``) that traces each pixel's ray.

``render(scene, width, height)`` returns a float array of shape (height, width, 3), row 0 at
the top (+y), before gamma. The slide's loop counts iy from the bottom (sy = -1), so pixel
(ix, iy) is stored at row height - 1 - iy.
"""
from __future__ import annotations

import importlib.util
import math

import numpy as np

from .float3 import Float3
from .ray import Ray
from .sampling import Jittered, NRooks, concentric_map
from .sampling.random import LENS_SET, check_seed
from .sampling.sampler import sampler_of
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
            result += scene.background_radiance(r.direction)
            break
        if hit.has_hit:
            break
    return result


def render_reference(scene, width: int, height: int, progress=None, sampler=None, seed: int = 0,
                     samples=(0, 1), sums=None) -> np.ndarray:
    """The lecture layer's renderer, pure Python: adds samples ``samples[0]`` up to
    ``samples[1]`` of every pixel to ``sums`` (height, width, 3), a new array of zeros if
    None, and returns it; the image is the sums divided by the number of samples.
    ``progress(rows_done, height)`` is called after each row if given.

    Sample s of a pixel is the point ``sampler.sample_unit_square(pixel, s, seed)`` of the
    pixel's square (Suffern's "pp.x = vp.s * (c - 0.5 * vp.hres + sp.x)"), or its centre
    without a sampler; a ThinLens camera also gets a point of the lens for it."""
    if sums is None:
        sums = np.zeros((height, width, 3), dtype=np.float64)
    camera = scene.camera
    for iy in range(height):
        for ix in range(width):
            pixel = (height - 1 - iy) * width + ix      # the pixel's place, row 0 at the top
            total = sums[height - 1 - iy, ix]
            for s in range(samples[0], samples[1]):
                if sampler is None:
                    sp = (0.5, 0.5)
                else:
                    sp = sampler.sample_unit_square(pixel, s, seed)
                sx = 2 * (ix + sp[0]) / width - 1
                sy = 2 * (iy + sp[1]) / height - 1

                if camera.uses_lens:
                    lens = concentric_map(*lens_sample(sampler, pixel, s, seed))
                    ray = camera.gen_ray(sx, sy, lens)
                else:
                    ray = camera.gen_ray(sx, sy)

                if scene.tracer is None or scene.show_ray_direction:
                    color = trace(scene, ray)
                else:
                    color = scene.tracer.trace_ray(scene, ray, pixel, s, seed)

                total[0] += color.x
                total[1] += color.y
                total[2] += color.z
        if progress is not None:
            progress(iy + 1, height)
    return sums


def lens_sample(sampler, pixel: int, s: int, seed: int) -> tuple:
    """The square sample a ThinLens maps to its lens: the sampler's, from a set of its own
    (the stream's LENS_SET dimension); the centre without a sampler."""
    if sampler is None:
        return (0.5, 0.5)
    return sampler.sample_unit_square(pixel, s, seed, LENS_SET)


def pixel_sampler(scene, spp):
    """The sampler of a render: the scene's (Suffern's view-plane sampler), with ``spp``
    samples if given; without one in the scene, Jittered(spp) for a square spp and
    NRooks(spp) otherwise. None for one sample through each pixel's centre."""
    if spp is None:
        return scene.sampler
    if isinstance(spp, bool) or not isinstance(spp, (int, np.integer)) or spp < 1:
        raise ValueError("spp (samples per pixel) must be an integer >= 1, got %r" % (spp,))
    spp = int(spp)
    if scene.sampler is not None:
        if scene.sampler.num_samples == spp:
            return scene.sampler
        try:
            return scene.sampler.with_num_samples(spp)
        except ValueError as error:
            raise ValueError("spp: %s" % error) from None
    if spp == 1:
        return None
    return sampler_of(Jittered if math.isqrt(spp) ** 2 == spp else NRooks, spp)


def check_size(width, height) -> None:
    for name, value in (("width", width), ("height", height)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
            raise ValueError("%s must be an integer >= 1, got %r" % (name, value))


def check_options(backend, precision, formula):
    """The backend, and its precision (each backend's own if None), checked."""
    if backend not in BACKENDS:
        raise ValueError("backend must be one of %s, got %r" % (", ".join(BACKENDS), backend))
    if precision is None:  # each backend's own: WGSL computes in float32
        precision = "float32" if backend == "wgpu" else "float64"
    if precision not in PRECISIONS:
        raise ValueError("precision must be one of %s, got %r" % (", ".join(PRECISIONS), precision))
    if formula is not None and formula not in FORMULAS:
        raise ValueError("formula must be one of %s, got %r" % (", ".join(FORMULAS), formula))
    if backend == "reference":
        if precision != "float64":
            raise ValueError("precision: the reference backend computes in float64 only")
        if formula not in (None, "slide"):
            raise ValueError("formula: the reference backend computes the slide formulas only, got %r"
                             % formula)
    elif backend == "numba":
        if importlib.util.find_spec(__package__ + ".kernels") is None:
            raise ValueError("backend: the numba path is not part of this release of rtfgu (it computes "
                             "the assignments' functions again); render with backend='reference'")
    elif precision != "float32":
        raise ValueError("precision: the wgpu backend computes in float32 only, got %r" % precision)
    return precision


def render_passes(scene, width: int, height: int, backend: str = "reference",
                  precision: str | None = None, formula: str | None = None, spp: int | None = None,
                  seed: int = 0, passes: int = 1, progress=None):
    """Progressive rendering: yields (samples done, image) after each of ``passes`` passes,
    each adding its share of the ``spp`` samples to every pixel. Every pixel adds its
    samples in the same order whatever the passes, so the last image is the same, bit for
    bit, as one render with all the samples. ``progress(done, total)`` as in ``render``,
    counting rows of every pass (the reference and wgpu) or passes (numba)."""
    check_size(width, height)
    precision = check_options(backend, precision, formula)
    seed = check_seed(seed)
    scene.validate()
    sampler = pixel_sampler(scene, spp)
    total = 1 if sampler is None else sampler.num_samples
    if isinstance(passes, bool) or not isinstance(passes, (int, np.integer)) or not 1 <= passes:
        raise ValueError("passes must be an integer >= 1, got %r" % (passes,))
    passes = min(int(passes), total)
    bounds = [total * k // passes for k in range(passes + 1)]
    if backend == "reference":
        accumulate = None
    elif backend == "numba":
        from .kernels import NumbaAccumulator  # numba is imported only when asked for
        accumulate = NumbaAccumulator(scene, width, height, precision, formula, sampler, seed)
    else:
        from .wgsl import WGPUAccumulator  # wgpu is imported only when asked for
        accumulate = WGPUAccumulator(scene, width, height, formula, sampler, seed)
    sums = None
    for k in range(passes):
        samples = (bounds[k], bounds[k + 1])
        rows = None if progress is None else (lambda done, n, k=k: progress(k * n + done, passes * n))
        if accumulate is None:
            sums = render_reference(scene, width, height, rows, sampler, seed, samples, sums)
            image = sums / samples[1]
        else:
            image = accumulate(samples, rows)
        if not np.all(np.isfinite(image)):
            raise ValueError("the %s backend produced non-finite pixels" % backend)
        yield samples[1], image.astype(np.float64, copy=False)


def render(scene, width: int, height: int, backend: str = "reference",
           precision: str | None = None, progress=None, formula: str | None = None,
           spp: int | None = None, seed: int = 0, passes: int = 1) -> np.ndarray:
    """Render ``scene`` to a (height, width, 3) float64 array, row 0 at the top, before gamma.

    backend: "reference" (the lecture layer, pure Python), "numba" (rtfgu.kernels, all
    cores) or "wgpu" (rtfgu.wgsl, WGSL through wgpu).
    precision: "float64" (the reference computes in Python floats) or "float32" (numba;
    wgpu's only one).
    formula: the sphere test, "slide" or "robust" (numba and wgpu); None is each backend's
    default (the reference's is "slide", its only one).
    spp: samples per pixel; None takes the scene's sampler (Scene.sampler), one sample
    through each pixel's centre without one. seed: the random stream's seed
    (rtfgu.sampling.random); the same seed gives the same image on every run and path.
    passes: render progressively in this many passes (render_passes); the image is the same.
    progress(done, total): called as rows (or passes) finish.
    """
    image = None
    for _, image in render_passes(scene, width, height, backend, precision, formula, spp, seed,
                                  passes, progress):
        pass
    return image
