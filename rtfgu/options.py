"""The options of a render, below both the renderer and the backends: which backends,
precisions and intersection formulas there are and each backend's defaults, the pixel
sampler of a render, and the checks of a render's arguments. rtfgu.renderer, rtfgu.kernels
and rtfgu.wgsl all import them from here (and the backends never import the renderer)."""
from __future__ import annotations

import importlib.util
import math

from .lazy_import import numpy as np

from .sampling import Jittered, NRooks
from .sampling.random import LENS_SET
from .sampling.sampler import sampler_of

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


def check_finite_image(image: np.ndarray, backend: str) -> None:
    """A ValueError if ``image`` (a render's, before gamma) holds a value that is not finite:
    no path writes NaN or infinite pixels silently."""
    if not np.all(np.isfinite(image)):
        raise ValueError("the %s backend produced non-finite pixels" % backend)


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
