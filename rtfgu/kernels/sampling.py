# release: solves a09 a10
"""The random stream, the pixel samples and the maps for the kernels, operation for
operation as rtfgu/sampling/ (random.py, sampler.py, maps.py).

Unsigned 32-bit arithmetic is done in int64 and masked: numba widens uint32 products, and
every product here (a 32-bit value times a constant below 2^30) fits in 63 bits.

A scene's sampler reaches the kernels as ``sampler`` = (samples (num_sets * n, 2) in the
render's float type, shuffled int32 (num_sets * n), n, num_sets), or None for one sample
through each pixel's centre; ``pixel_sample`` is typed on that, so the one-sample render
compiles without any of it.
"""
from __future__ import annotations

import math

from numba import njit, types
from numba.extending import overload

from .dispatch_support import as_python
from .float3 import lit

MASK = 0xFFFFFFFF


@njit(cache=True, error_model="numpy", inline="always")
def pcg(v):
    state = (v * 747796405 + 2891336453) & MASK
    word = (((state >> ((state >> 28) + 4)) ^ state) * 277803737) & MASK
    return ((word >> 22) ^ word) & MASK


@njit(cache=True, error_model="numpy", inline="always")
def random_u32(pixel, index, dimension, seed):
    h = pcg(pixel & MASK)
    h = pcg((index + h) & MASK)
    h = pcg((dimension + h) & MASK)
    return pcg((seed + h) & MASK)


@njit(cache=True, error_model="numpy")
def random_float(pixel, index, dimension, seed, like):
    """In [0, 1), 24 random bits, in the float type of ``like``."""
    return lit(random_u32(pixel, index, dimension, seed) >> 8, like) * lit(2.0 ** -24, like)


@njit(cache=True, error_model="numpy", inline="always")
def sample_unit_square(samples, shuffled, n, num_sets, pixel, index, dimension, seed, first=0):
    """Sampler.sample_unit_square: the sample of the set the stream picks for the pixel, of a
    sampler whose sets start at row ``first`` of ``samples`` and ``shuffled``."""
    jump = first + (random_u32(pixel, index // n, dimension, seed) % num_sets) * n
    k = jump + shuffled[jump + index % n]
    return samples[k, 0], samples[k, 1]


@njit(cache=True, error_model="numpy", inline="always")
def stream_point(pixel, index, dimension, seed, like):
    """A point of the unit square from the random stream's ``dimension`` and the next."""
    return random_float(pixel, index, dimension, seed, like), random_float(pixel, index, dimension + 1, seed, like)


def sampler_sets(samples, shuffled):
    """(samples, shuffled), or None where ``samples`` is None: the sets of the samplers lights
    and BRDFs have of their own, as sampler_point takes them, from the two arrays the
    kernels receive them as (numba's parallel loop takes no tuple inside a tuple; typed by
    the overload below)."""
    return as_python(_typed_sampler_sets, samples, shuffled)


@overload(sampler_sets, inline="always")
def _typed_sampler_sets(samples, shuffled):
    if isinstance(samples, types.NoneType):
        return lambda samples, shuffled: None
    return lambda samples, shuffled: (samples, shuffled)


def sampler_point(sets, table, j, column, pixel, index, dimension, seed, like):
    """The point (u, v) row ``j`` of ``table`` (a light, or a material's BRDF) draws from
    (Scene.light_sample, BRDF.sample_point): its own sampler's, where the row's field at
    ``column`` (first sample, num_samples, num_sets) has num_samples > 0, from ``sets`` =
    (the scene's own samples, their orders); else the random stream's (stream_point).
    ``sets`` is None in a scene where nothing has a sampler of its own, and that code
    compiles to nothing (typed by the overload below)."""
    return as_python(_typed_sampler_point, sets, table, j, column, pixel, index, dimension, seed, like)


@overload(sampler_point, inline="always")
def _typed_sampler_point(sets, table, j, column, pixel, index, dimension, seed, like):
    if isinstance(sets, types.NoneType):
        return lambda sets, table, j, column, pixel, index, dimension, seed, like: stream_point(
            pixel, index, dimension, seed, like)

    def sampled(sets, table, j, column, pixel, index, dimension, seed, like):
        n = int(table[j, column + 1])
        if n == 0:
            return stream_point(pixel, index, dimension, seed, like)
        return sample_unit_square(sets[0], sets[1], n, int(table[j, column + 2]), pixel, index, dimension, seed,
                                  int(table[j, column]))
    return sampled


def pixel_sample(sampler, pixel, index, dimension, seed, like):
    """(x, y) in [0, 1)^2 of sample ``index`` of ``pixel``; (0.5, 0.5) without a sampler
    (typed by the overload below)."""
    return as_python(_typed_pixel_sample, sampler, pixel, index, dimension, seed, like)


@overload(pixel_sample, inline="always")
def _typed_pixel_sample(sampler, pixel, index, dimension, seed, like):
    if isinstance(sampler, types.NoneType):
        def centre(sampler, pixel, index, dimension, seed, like):
            half = lit(0.5, like)
            return half, half
        return centre

    def sampled(sampler, pixel, index, dimension, seed, like):
        samples, shuffled, n, num_sets = sampler
        return sample_unit_square(samples, shuffled, n, num_sets, pixel, index, dimension, seed)
    return sampled


@njit(cache=True, error_model="numpy")
def concentric_map(x, y):
    """rtfgu.sampling.maps.concentric_map: [0, 1]^2 onto the unit disk."""
    zero = lit(0, x)
    two = lit(2.0, x)
    sx = two * x - lit(1.0, x)
    sy = two * y - lit(1.0, y)
    if sx > -sy:
        if sx > sy:
            r = sx
            phi = sy / sx
        else:
            r = sy
            phi = two - sx / sy
    else:
        if sx < sy:
            r = -sx
            phi = lit(4.0, x) + sy / sx
        else:
            r = -sy
            if sy != zero:
                phi = lit(6.0, x) - sx / sy
            else:
                phi = zero
    phi *= lit(math.pi / 4.0, x)
    return r * math.cos(phi), r * math.sin(phi)


@njit(cache=True, error_model="numpy")
def hemisphere_map(x, y, e):
    """rtfgu.sampling.maps.hemisphere_map: density (e + 1) / (2 pi) cos^e about +z."""
    one = lit(1.0, x)
    two_pi_x = lit(2.0 * math.pi, x) * x
    cos_phi = math.cos(two_pi_x)
    sin_phi = math.sin(two_pi_x)
    cos_theta = (one - y) ** (one / (e + one))
    sin_theta = math.sqrt(one - cos_theta * cos_theta)
    return sin_theta * cos_phi, sin_theta * sin_phi, cos_theta
