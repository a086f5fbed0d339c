"""Rendering a scene: the slide's loop over pixels (lecture 01, "Rendering a Scene") and the
02562 path loop (``main_fs``) that traces each pixel's ray.

``render(scene, width, height)`` returns a float array of shape (height, width, 3), row 0 at
the top (+y), before gamma. The slide's loop counts iy from the bottom (sy = -1), so pixel
(ix, iy) is stored at row height - 1 - iy.
"""
from __future__ import annotations


from .lazy_import import numpy as np

from .float3 import Float3
from .ray import Ray
from .options import (BACKENDS, DEFAULT_BACKEND, DEFAULT_FORMULAS, FORMULAS, PRECISIONS, check_options,  # noqa: F401
                      check_finite_image, check_size, lens_sample, pixel_sampler)
from .sampling import concentric_map
from .sampling.random import check_seed

def trace(scene, r: Ray, stream=(0, 0, 0)) -> Float3:
    """The colour of the eye ray ``r``: the scene's tracer's ``trace_ray(r, 0)`` (Whitted by
    default, the 02562 path loop), or with ``show_ray_direction`` the ray's direction as a
    colour, d * 0.5 + 0.5 (02562 week 1). ``stream``: the (pixel, sample, seed) whose random
    numbers a stochastic tracer draws."""
    if scene.show_ray_direction:
        return r.direction * 0.5 + Float3(0.5)
    tracer = scene.tracer
    tracer.world = scene
    tracer.stream = stream
    return tracer.trace_ray(r, 0)


def render_reference(scene, width: int, height: int, progress=None, sampler=None, seed: int = 0,
                     samples=(0, 1), sums=None) -> np.ndarray:
    """The lecture layer's renderer, pure Python: adds samples ``samples[0]`` up to
    ``samples[1]`` of every pixel to ``sums`` (height, width, 3), a new array of zeros if
    None, and returns it; the image is the sums divided by the number of samples.
    ``progress(rows_done, height)`` is called after each row if given.

    Sample s of a pixel is the point ``sampler.sample_unit_square(pixel, s, seed)`` of the
    pixel's square (Suffern's "pp.x = vp.s * (c - 0.5 * vp.hres + sp.x)"), or its centre
    without a sampler; a ThinLens camera also gets a point of the lens for it. A Mesh in
    Scene.shapes is traced as its faces (Scene.with_faces)."""
    if sums is None:
        sums = np.zeros((height, width, 3), dtype=np.float64)
    scene = scene.with_faces()      # a Mesh in Scene.shapes traced as its faces
    camera = scene.camera
    for iy in range(height):
        # The row's sums as Python floats while it renders (a numpy element costs more to add
        # to than a float, and float64 adds the same either way).
        row = sums[height - 1 - iy].tolist()
        for ix in range(width):
            pixel = (height - 1 - iy) * width + ix      # the pixel's place, row 0 at the top
            total = row[ix]
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

                color = trace(scene, ray, (pixel, s, seed))

                total[0] += color.x
                total[1] += color.y
                total[2] += color.z
        sums[height - 1 - iy] = row
        if progress is not None:
            progress(iy + 1, height)
    return sums


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
            check_finite_image(image, backend)
        else:
            image = accumulate(samples, rows, last=k + 1 == passes)   # float64, refused where not finite
        yield samples[1], image


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
