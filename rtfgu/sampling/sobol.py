"""Sobol: Burley's shuffled, Owen-scrambled Sobol points, PBRT-v4's default sampler family.

Brent Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020 (listings 1-5), and
PBRT-v4's PaddedSobolSampler (src/pbrt/samplers.h, util/lowdiscrepancy.h): every 2D draw of
a sample takes the first two Sobol dimensions, so each pair of dimensions is a (0, 2)-sequence
of its own; the pairs are decorrelated ("padded") by scrambling each with seeds hashed from
(pixel, dimension, seed):

    key      = pcg(seed + pcg(dimension + pcg(pixel)))      (the pcg of rtfgu.sampling.random)
    shuffled = nested_uniform_scramble(index, key)          (the pixel's own order of the points)
    u        = nested_uniform_scramble(sobol_0(shuffled), pcg(key + 1))
    v        = nested_uniform_scramble(sobol_1(shuffled), pcg(key + 2))
    (u, v)   = ((u >> 8) * 2^-24, (v >> 8) * 2^-24)          exact in float32 and float64

The nested uniform scramble of the index sends every aligned block of 2^k indices onto an
aligned block of 2^k (output bit m depends on input bits m and above), so the first 2^k
samples of a pixel are the points of one block of the Sobol sequence, a (0, k, 2)-net: every
elementary interval of area 2^-k (2^a x 2^b cells, a + b = k) holds exactly one point, and the
Owen scramble of each coordinate keeps that. A count that is not a power of two, 3 say, takes
3 of the 4 points of such a block: 3 different cells of every 2^-2 partition.

The same functions are written in rtfgu/kernels/sampling.py (numba, int64 masked) and
rtfgu/wgsl/sobol.wgsl (u32), kept equal by tests/test_sobol.py.
"""
from __future__ import annotations

from .random import MASK, PIXEL_SET, TO_UNIT, pcg, random_float
from .sampler import Sampler


def reverse_bits(x: int) -> int:
    """The 32 bits of ``x`` in the reverse order (Burley, listing 1)."""
    x = ((x & 0xAAAAAAAA) >> 1) | ((x & 0x55555555) << 1)
    x = ((x & 0xCCCCCCCC) >> 2) | ((x & 0x33333333) << 2)
    x = ((x & 0xF0F0F0F0) >> 4) | ((x & 0x0F0F0F0F) << 4)
    x = ((x & 0xFF00FF00) >> 8) | ((x & 0x00FF00FF) << 8)
    return ((x >> 16) | (x << 16)) & MASK


def laine_karras_permutation(x: int, seed: int) -> int:
    """Laine and Karras's hash (Burley, listing 3): bit j of the result depends only on bits
    0..j of ``x``, so reversed it is an Owen scramble."""
    x = (x + seed) & MASK
    x ^= (x * 0x6C50B47C) & MASK
    x ^= (x * 0xB82F1E52) & MASK
    x ^= (x * 0xC7AFE638) & MASK
    x ^= (x * 0x8D22F6E6) & MASK
    return x


def nested_uniform_scramble(x: int, seed: int) -> int:
    """The base-2 Owen scramble of the 32-bit fraction ``x`` (Burley, listing 4): every bit
    flipped by a hash of the bits above it."""
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed))


def sobol_0(index: int) -> int:
    """Sobol's first dimension (the van der Corput sequence): the index's bits reversed."""
    return reverse_bits(index)


def sobol_1(index: int) -> int:
    """Sobol's second dimension: index bit j adds direction v_j, v_0 = 2^31 and
    v_(j+1) = v_j ^ (v_j >> 1) (Pascal's triangle mod 2; Burley, listing 2's second row)."""
    x = 0
    v = 0x80000000
    while index:
        if index & 1:
            x ^= v
        index >>= 1
        v ^= v >> 1
    return x


def sobol_key(pixel: int, dimension: int, seed: int) -> int:
    """The hash of (pixel, dimension, seed) the pair's three scrambles are seeded from."""
    return pcg((seed + pcg((dimension + pcg(pixel & MASK)) & MASK)) & MASK)


def sobol_pair_u32(pixel: int, index: int, dimension: int, seed: int) -> tuple:
    """The pair's two 32-bit fractions (the module docstring)."""
    key = sobol_key(pixel, dimension, seed)
    shuffled = nested_uniform_scramble(index & MASK, key)
    return (nested_uniform_scramble(sobol_0(shuffled), pcg((key + 1) & MASK)),
            nested_uniform_scramble(sobol_1(shuffled), pcg((key + 2) & MASK)))


def sobol_pair(pixel: int, index: int, dimension: int, seed: int) -> tuple:
    """(u, v) in [0, 1)^2, 24 bits each: sample ``index`` of ``pixel`` in the dimension pair
    that starts at ``dimension``."""
    u, v = sobol_pair_u32(pixel, index, dimension, seed)
    return (u >> 8) * TO_UNIT, (v >> 8) * TO_UNIT


def pair_sample(sampler, pixel: int, index: int, dimension: int, seed: int) -> tuple:
    """The point (u, v) a 2D draw of a render with pixel sampler ``sampler`` takes in the
    dimension pair that starts at ``dimension``: Sobol's pair where ``sampler`` is a Sobol,
    else the random stream's numbers in ``dimension`` and the next."""
    if isinstance(sampler, Sobol):
        return sobol_pair(pixel, index, dimension, seed)
    return random_float(pixel, index, dimension, seed), random_float(pixel, index, dimension + 1, seed)


def check_own_sampler(owner: str, sampler):
    """``sampler``, checked as the sampler a light or a BRDF has of its own (set_sampler): a
    Sampler with sets, or None; a ValueError naming ``owner``'s field otherwise (a Sobol has
    no sets: it is the scene's, and then every 2D draw's)."""
    if sampler is not None and not isinstance(sampler, Sampler):
        raise ValueError("%s.sampler must be a Sampler or None, got %r" % (owner, sampler))
    if isinstance(sampler, Sobol):
        raise ValueError("%s.sampler: a Sobol has no sets to draw from; set it as Scene.sampler, whose "
                         "2D draws then all come from it" % owner)
    return sampler


class Sobol(Sampler):
    """Burley's shuffled, scrambled Sobol points (PBRT-v4's, not Suffern's): a pixel's
    sample ``index`` is sobol_pair(pixel, index, dimension, seed), with no sets to draw from.
    A scene whose sampler is a Sobol takes every 2D draw of a render from it (Scene.pair_sample):
    the pixel (PIXEL_SET), the lens (LENS_SET), a bounce's direction and an area light's or
    the ambient occluder's point; its 1D draws (Russian roulette, a dielectric's choice) stay
    on the independent stream.

    ``samples`` holds ``num_sets`` sets (default one) for plots: set k is "pixel" k's points;
    a light or a BRDF takes no Sobol as a sampler of its own (set_sampler says so)."""

    def __init__(self, num_samples: int = 1, num_sets: int = 1, seed: int = 0):
        super().__init__(num_samples, num_sets, seed)

    def generate_samples(self) -> None:
        for k in range(self.num_sets):
            for index in range(self.num_samples):
                self.samples.append(sobol_pair(k, index, PIXEL_SET, self.seed))

    def sample_unit_square(self, pixel: int, index: int, seed: int = 0,
                           dimension: int = PIXEL_SET) -> tuple:
        return sobol_pair(pixel, index, dimension, seed)
