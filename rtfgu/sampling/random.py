"""The random stream: one counter-based generator, the same numbers on every path.

A number is a hash of (pixel, index, dimension, seed), not the next state of a generator,
so every pixel draws its numbers on its own: the image is the same on any number of
threads and on every path, and a stochastic assignment can be graded exactly. The hash
is PCG's output permutation used as a hash (Jarzynski and Olano, "Hash Functions for GPU
Rendering", JCGT 9(3), 2020), applied once per input:

    random_u32(p, i, d, s) = pcg(s + pcg(d + pcg(i + pcg(p))))      (all mod 2^32)
    random_float(p, i, d, s) = (random_u32(p, i, d, s) >> 8) * 2^-24  in [0, 1)

The float has 24 significant bits, so it is the same number in float32 and float64. The
same functions are written in rtfgu/kernels/random.py (numba, uint32) and
rtfgu/wgsl/random.wgsl (u32): three copies of a dozen lines, kept equal by
tests/test_random.py on a million inputs.

``pixel`` is the pixel's place in the image, row 0 at the top (row * width + column);
``index`` the sample; ``dimension`` which number of the sample (DIMENSIONS).
"""
from __future__ import annotations

MASK = 0xFFFFFFFF
TO_UNIT = 2.0 ** -24

# The dimensions a sample draws; each path draws these numbers for these purposes only.
PIXEL_SET = 0       # which set of the pixel sampler a pixel's samples come from
LENS_SET = 1        # which set the lens samples (ThinLens) come from
DIMENSIONS = {"pixel_set": PIXEL_SET, "lens_set": LENS_SET}

# PathTrace: vertex ``depth`` of a path (0 where the eye ray lands) draws dimension
# path_dimension(depth, k) for k = BOUNCE_U, BOUNCE_V (the next direction), ROULETTE (Russian
# roulette: whether the path goes on from the vertex), CHOICE (a dielectric's), LOBE (a
# GlossyReflector's lobe) and LIGHT_U + 2 j, LIGHT_V + 2 j (a point of the path's j-th area
# light, in the order of Scene.lights); k below LIGHT_U is kept for the vertex's own numbers.
VERTEX_DIMENSIONS = 1 << 16
BOUNCE_U = 0
BOUNCE_V = 1
ROULETTE = 2
CHOICE = 3          # a dielectric's choice between reflection and refraction
LOBE = 4            # a GlossyReflector's choice between its diffuse and its glossy lobe
LIGHT_U = 8
LIGHT_V = 9


def pcg(v: int) -> int:
    """PCG's state step and RXS-M-XS output on 32 bits (Jarzynski and Olano, listing "pcg")."""
    state = (v * 747796405 + 2891336453) & MASK
    word = (((state >> ((state >> 28) + 4)) ^ state) * 277803737) & MASK
    return ((word >> 22) ^ word) & MASK


def random_u32(pixel: int, index: int, dimension: int, seed: int) -> int:
    """An unsigned 32-bit hash of the four counters."""
    h = pcg(pixel & MASK)
    h = pcg((index + h) & MASK)
    h = pcg((dimension + h) & MASK)
    return pcg((seed + h) & MASK)


def random_float(pixel: int, index: int, dimension: int, seed: int) -> float:
    """A number in [0, 1) with 24 random bits: exact in float32 and float64."""
    return (random_u32(pixel, index, dimension, seed) >> 8) * TO_UNIT


def check_seed(seed) -> int:
    """``seed`` as an unsigned 32-bit integer; a ValueError naming the field otherwise."""
    if isinstance(seed, bool) or not isinstance(seed, int) and not hasattr(seed, "__index__"):
        raise ValueError("seed must be an integer in [0, 2^32), got %r" % (seed,))
    seed = int(seed)
    if not 0 <= seed <= MASK:
        raise ValueError("seed must be an integer in [0, 2^32), got %r" % (seed,))
    return seed


def path_dimension(depth: int, k: int) -> int:
    """The dimension of number ``k`` at vertex ``depth`` of a path (the constants above)."""
    return 2 + depth * VERTEX_DIMENSIONS + k
