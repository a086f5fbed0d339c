# release: solves a09 a10
"""The random stream, the pixel samples and the maps for the kernels, operation for
operation as rtfgu/sampling/ (random.py, sampler.py, maps.py).

Unsigned 32-bit arithmetic is done in int64 and masked: numba widens uint32 products, and
every product here (a 32-bit value times a constant below 2^30) fits in 63 bits; Sobol's
scramble multiplies by larger constants, in uint64, whose products wrap (mul32).

A scene's sampler reaches the kernels as ``sampler`` = (samples (num_sets * n, 2) in the
render's float type, shuffled int32 (num_sets * n), n, num_sets), or None for one sample
through each pixel's centre; ``pixel_sample`` is typed on that, so the one-sample render
compiles without any of it; a Sobol sampler (rtfgu.sampling.sobol) reaches them as
(num_samples,), and only such a render compiles Sobol's functions.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import overload

from ..sampling import sobol as lecture_sobol
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
def mul32(a, b):
    """a * b mod 2^32 for a, b below 2^32: one uint64 product (it wraps mod 2^64, whose low
    32 bits are the product's), masked."""
    return np.int64((np.uint64(a) * np.uint64(b)) & np.uint64(MASK))


@njit(cache=True, error_model="numpy", inline="always")
def reverse_bits(x):
    """rtfgu.sampling.sobol.reverse_bits."""
    x = ((x & 0xAAAAAAAA) >> 1) | ((x & 0x55555555) << 1)
    x = ((x & 0xCCCCCCCC) >> 2) | ((x & 0x33333333) << 2)
    x = ((x & 0xF0F0F0F0) >> 4) | ((x & 0x0F0F0F0F) << 4)
    x = ((x & 0xFF00FF00) >> 8) | ((x & 0x00FF00FF) << 8)
    return ((x >> 16) | (x << 16)) & MASK


@njit(cache=True, error_model="numpy", inline="always")
def laine_karras_permutation(x, seed):
    """rtfgu.sampling.sobol.laine_karras_permutation (Burley 2020, listing 3)."""
    x = (x + seed) & MASK
    x ^= mul32(x, 0x6C50B47C)
    x ^= mul32(x, 0xB82F1E52)
    x ^= mul32(x, 0xC7AFE638)
    x ^= mul32(x, 0x8D22F6E6)
    return x


@njit(cache=True, error_model="numpy", inline="always")
def nested_uniform_scramble(x, seed):
    """rtfgu.sampling.sobol.nested_uniform_scramble (Burley 2020, listing 4)."""
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed))


# Sobol's second dimension is linear over GF(2) (an index's point is the XOR of its set
# bits' columns), so it is the XOR of its four bytes' points: rtfgu.sampling.sobol.sobol_1
# of every byte in every place, made once, looked up four times instead of a loop over up
# to 32 bits with a branch on each (a scrambled index has random bits). Same bits.
SOBOL_1_BYTES = np.array([[lecture_sobol.sobol_1(b << (8 * k)) for b in range(256)] for k in range(4)],
                         dtype=np.int64)


@njit(cache=True, error_model="numpy", inline="always")
def sobol_1(index):
    """rtfgu.sampling.sobol.sobol_1 of a 32-bit ``index``."""
    return (SOBOL_1_BYTES[0, index & 255] ^ SOBOL_1_BYTES[1, (index >> 8) & 255]
            ^ SOBOL_1_BYTES[2, (index >> 16) & 255] ^ SOBOL_1_BYTES[3, (index >> 24) & 255])


@njit(cache=True, error_model="numpy")
def sobol_pair_u32(pixel, index, dimension, seed):
    """rtfgu.sampling.sobol.sobol_pair_u32: Burley's shuffled, scrambled Sobol pair."""
    key = pcg((seed + pcg((dimension + pcg(pixel & MASK)) & MASK)) & MASK)
    shuffled = nested_uniform_scramble(index & MASK, key)
    # The first: nested_uniform_scramble(reverse_bits(shuffled)), whose two bit reversals
    # in a row cancel.
    return (reverse_bits(laine_karras_permutation(shuffled, pcg((key + 1) & MASK))),
            nested_uniform_scramble(sobol_1(shuffled), pcg((key + 2) & MASK)))


@njit(cache=True, error_model="numpy")
def sobol_pair(pixel, index, dimension, seed, like):
    """rtfgu.sampling.sobol.sobol_pair in the float type of ``like``."""
    u, v = sobol_pair_u32(pixel, index, dimension, seed)
    unit = lit(2.0 ** -24, like)
    return lit(u >> 8, like) * unit, lit(v >> 8, like) * unit


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


def sampler_sets(samples, shuffled, sobol):
    """What sampler_point draws from, out of the three last entries of the kernels' ``lights``
    (numba's parallel loop takes no tuple inside a tuple): None where nothing has a sampler
    of its own and the render's sampler is not a Sobol; (samples, shuffled), the sets of the
    samplers lights and BRDFs have of their own, where ``sobol`` is None; (samples, shuffled,
    sobol) in a Sobol render, ``samples`` and ``shuffled`` None where nothing has a sampler
    of its own (typed by the overload below)."""
    return as_python(_typed_sampler_sets, samples, shuffled, sobol)


@overload(sampler_sets, inline="always")
def _typed_sampler_sets(samples, shuffled, sobol):
    if not isinstance(sobol, types.NoneType):
        return lambda samples, shuffled, sobol: (samples, shuffled, sobol)
    if isinstance(samples, types.NoneType):
        return lambda samples, shuffled, sobol: None
    return lambda samples, shuffled, sobol: (samples, shuffled)


def sampler_point(sets, table, j, column, pixel, index, dimension, seed, like):
    """The point (u, v) row ``j`` of ``table`` (a light, or a material's BRDF) draws from
    (Scene.light_sample, BRDF.sample_point): its own sampler's, where the row's field at
    ``column`` (first sample, num_samples, num_sets) has num_samples > 0, from ``sets``'
    (the scene's own samples, their orders); else the render's pair (pair_sample): Sobol's in
    a Sobol render (``sets`` holds three entries), the random stream's otherwise. ``sets`` is
    None in a scene where nothing has a sampler of its own and the render is not Sobol, and
    that code compiles to nothing (typed by the overload below)."""
    return as_python(_typed_sampler_point, sets, table, j, column, pixel, index, dimension, seed, like)


@overload(sampler_point, inline="always")
def _typed_sampler_point(sets, table, j, column, pixel, index, dimension, seed, like):
    if isinstance(sets, types.NoneType):
        return lambda sets, table, j, column, pixel, index, dimension, seed, like: stream_point(
            pixel, index, dimension, seed, like)
    sobol = len(sets) == 3
    if sobol and isinstance(sets.types[0], types.NoneType):
        return lambda sets, table, j, column, pixel, index, dimension, seed, like: sobol_pair(
            pixel, index, dimension, seed, like)

    def sampled(sets, table, j, column, pixel, index, dimension, seed, like):
        n = int(table[j, column + 1])
        if n == 0:
            if sobol:
                return sobol_pair(pixel, index, dimension, seed, like)
            return stream_point(pixel, index, dimension, seed, like)
        return sample_unit_square(sets[0], sets[1], n, int(table[j, column + 2]), pixel, index, dimension, seed,
                                  int(table[j, column]))
    return sampled


def pixel_sample(sampler, pixel, index, dimension, seed, like):
    """(x, y) in [0, 1)^2 of sample ``index`` of ``pixel``; (0.5, 0.5) without a sampler;
    Sobol's pair for a Sobol sampler, which reaches the kernels as (num_samples,) (typed by
    the overload below)."""
    return as_python(_typed_pixel_sample, sampler, pixel, index, dimension, seed, like)


@overload(pixel_sample, inline="always")
def _typed_pixel_sample(sampler, pixel, index, dimension, seed, like):
    if isinstance(sampler, types.NoneType):
        def centre(sampler, pixel, index, dimension, seed, like):
            half = lit(0.5, like)
            return half, half
        return centre
    if len(sampler) == 1:
        return lambda sampler, pixel, index, dimension, seed, like: sobol_pair(pixel, index, dimension, seed, like)

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
