"""LatticeNoise: Suffern ch. 31's lattice noise and its sums of octaves.

A value noise is a smooth interpolation of pseudo-random values fixed at the integer
lattice points. The book indexes its value table through Peachey's permutation table
(Ebert et al. 2003, p. 70)::

    INDEX(ix, iy, iz) = PERM[(ix + PERM[(iy + PERM[iz & 255]) & 255]) & 255]

and fills the value table with ``1 - 2 rand_float()`` after ``set_rand_seed(253)``. C's
``rand`` is not the same on every system, and a GPU has none, so rtfgu fills it from the
random stream's integer hash (rtfgu.sampling.random.pcg) instead::

    VALUE_TABLE[i] = 1 - 2 (pcg(i + 253) >> 8) 2^-24        (i = 0 .. 255, in [-1, 1))

and the unit vectors of the vector noise (the book's multi-jittered directions) from the
next 512 numbers of the same sequence (VECTOR_TABLE).

A value of 24 bits is exact in float32 and float64, so every path holds the same 256
numbers: this module for the lecture layer and numba (rtfgu/kernels/noise.py reads these
tables), and the literal tables of rtfgu/wgsl/lattice_tables.wgsl (tests/test_solid_textures.py
compares them).

The sums, with the book's names (LatticeNoise.cpp), map into [0, 1] with
fbm_max = (1 - gain^num_octaves) / (1 - gain) (num_octaves if gain = 1), fbm_min = -fbm_max:

    value_fractal_sum   sum of 0.5^j value_noise(2^j p), mapped (gain 0.5, lacunarity 2 always)
    value_turbulence    sum of 0.5^j |value_noise(2^j p)| / fbm_max
    value_fbm           sum of gain^j value_noise(lacunarity^j p), mapped
"""
from __future__ import annotations

import math
from abc import ABC, abstractmethod

from ..float3 import Float3
from ..sampling.random import TO_UNIT, pcg
from ..validation import number, positive

TABLE_SIZE = 256
TABLE_MASK = TABLE_SIZE - 1
SEED = 253          # the book's seed_value

# Peachey's permutation table (Ebert et al. 2003, p. 70), as the book's LatticeNoise.cpp.
PERMUTATION_TABLE = (
    225, 155, 210, 108, 175, 199, 221, 144, 203, 116, 70, 213, 69, 158, 33, 252,
    5, 82, 173, 133, 222, 139, 174, 27, 9, 71, 90, 246, 75, 130, 91, 191,
    169, 138, 2, 151, 194, 235, 81, 7, 25, 113, 228, 159, 205, 253, 134, 142,
    248, 65, 224, 217, 22, 121, 229, 63, 89, 103, 96, 104, 156, 17, 201, 129,
    36, 8, 165, 110, 237, 117, 231, 56, 132, 211, 152, 20, 181, 111, 239, 218,
    170, 163, 51, 172, 157, 47, 80, 212, 176, 250, 87, 49, 99, 242, 136, 189,
    162, 115, 44, 43, 124, 94, 150, 16, 141, 247, 32, 10, 198, 223, 255, 72,
    53, 131, 84, 57, 220, 197, 58, 50, 208, 11, 241, 28, 3, 192, 62, 202,
    18, 215, 153, 24, 76, 41, 15, 179, 39, 46, 55, 6, 128, 167, 23, 188,
    106, 34, 187, 140, 164, 73, 112, 182, 244, 195, 227, 13, 35, 77, 196, 185,
    26, 200, 226, 119, 31, 123, 168, 125, 249, 68, 183, 230, 177, 135, 160, 180,
    12, 1, 243, 148, 102, 166, 38, 238, 251, 37, 240, 126, 64, 74, 161, 40,
    184, 149, 171, 178, 101, 66, 29, 59, 146, 61, 254, 107, 42, 86, 154, 4,
    236, 232, 120, 21, 233, 209, 45, 98, 193, 114, 78, 19, 206, 14, 118, 127,
    48, 79, 147, 85, 30, 207, 219, 54, 88, 234, 190, 122, 95, 67, 143, 109,
    137, 214, 145, 93, 92, 100, 245, 0, 216, 186, 60, 83, 105, 97, 204, 52,
)



def lattice_float(k: int) -> float:
    """The k-th number of the lattice: (pcg(k + 253) >> 8) 2^-24, in [0, 1), 24 bits."""
    return (pcg(k + SEED) >> 8) * TO_UNIT


VALUE_TABLE = tuple(1.0 - 2.0 * lattice_float(i) for i in range(TABLE_SIZE))


def _unit_vector(r1: float, r2: float) -> tuple:
    """The book's init_vector_table: (r1, r2) of the unit square to the unit sphere
    (Pharr and Humphreys), normalised."""
    z = 1.0 - 2.0 * r1
    r = math.sqrt(1.0 - z * z)
    phi = 2.0 * math.pi * r2
    x = r * math.cos(phi)
    y = r * math.sin(phi)
    length = math.sqrt(x * x + y * y + z * z)
    return x / length, y / length, z / length


# The book draws its 256 unit vectors from a multi-jittered set seeded with rand(); here
# (r1, r2) = (lattice_float(256 + j), lattice_float(512 + j)). Each component is a table of
# its own, so a vector noise is three value noises over these tables.
VECTOR_TABLE = tuple(_unit_vector(lattice_float(TABLE_SIZE + j), lattice_float(2 * TABLE_SIZE + j))
                     for j in range(TABLE_SIZE))
VECTOR_TABLES = tuple(tuple(v[c] for v in VECTOR_TABLE) for c in range(3))


def lattice_value(ix: int, iy: int, iz: int, table=VALUE_TABLE) -> float:
    """The value at the lattice point (ix, iy, iz): table[INDEX(ix, iy, iz)]."""
    perm = PERMUTATION_TABLE
    return table[perm[(ix + perm[(iy + perm[iz & TABLE_MASK]) & TABLE_MASK]) & TABLE_MASK]]


class LatticeNoise(ABC):
    def __init__(self, num_octaves: int = 1, lacunarity: float = 2.0, gain: float = 0.5):
        name = type(self).__name__
        if isinstance(num_octaves, bool) or not isinstance(num_octaves, int) or num_octaves < 1:
            raise ValueError("%s.num_octaves must be an integer >= 1, got %r" % (name, num_octaves))
        self.num_octaves = num_octaves
        self.lacunarity = positive(lacunarity, name + ".lacunarity")
        self.gain = positive(gain, name + ".gain")
        # compute_fbm_bounds: the largest |sum| of the octaves.
        if self.gain == 1.0:
            self.fbm_max = float(num_octaves)
        else:
            self.fbm_max = (1.0 - math.pow(self.gain, num_octaves)) / (1.0 - self.gain)
        number(self.fbm_max, name + ".gain ** num_octaves", positive=True)

    @abstractmethod
    def value_noise(self, p: Float3) -> float:
        """The noise at p, in [-1, 1]: the lattice values interpolated."""

    @staticmethod
    @abstractmethod
    def interpolate(p: Float3, table) -> float:
        """The lattice values of ``table`` (VALUE_TABLE or one of VECTOR_TABLES) around p,
        interpolated: the scheme that names the subclass."""

    def vector_noise(self, p: Float3) -> Float3:
        """The lattice's unit vectors interpolated at p (the book's vector_noise): one
        interpolation per component table, not clamped."""
        return Float3(*(self.interpolate(p, table) for table in VECTOR_TABLES))

    def vector_fbm(self, p: Float3) -> Float3:
        """The sum of gain^j vector_noise(lacunarity^j p), not mapped (the book's vector_fbm)."""
        amplitude = 1.0
        frequency = 1.0
        total = Float3(0.0)
        for _ in range(self.num_octaves):
            total = total + self.vector_noise(p * frequency) * amplitude
            amplitude *= self.gain
            frequency *= self.lacunarity
        return total

    def octave_sum(self, p: Float3, lacunarity: float, gain: float, absolute: bool = False) -> float:
        """The sum over j < num_octaves of gain^j value_noise(lacunarity^j p) (of its
        absolute value when ``absolute``), not mapped: the loop the book's three sums share."""
        amplitude = 1.0
        frequency = 1.0
        total = 0.0
        for _ in range(self.num_octaves):
            noise = self.value_noise(p * frequency)
            total += amplitude * (abs(noise) if absolute else noise)
            amplitude *= gain
            frequency *= lacunarity
        return total

    def value_fractal_sum(self, p: Float3) -> float:
        """Gain 0.5 and lacunarity 2 whatever the noise's own, mapped into [0, 1]."""
        fractal_sum = self.octave_sum(p, 2.0, 0.5)
        return (fractal_sum + self.fbm_max) / (self.fbm_max + self.fbm_max)

    def value_turbulence(self, p: Float3) -> float:
        """Gain 0.5 and lacunarity 2 over |value_noise|, divided by fbm_max."""
        return self.octave_sum(p, 2.0, 0.5, absolute=True) / self.fbm_max

    def value_fbm(self, p: Float3) -> float:
        """The noise's gain and lacunarity, mapped into [0, 1]."""
        fbm = self.octave_sum(p, self.lacunarity, self.gain)
        return (fbm + self.fbm_max) / (self.fbm_max + self.fbm_max)


def lattice_cell(x: float) -> tuple:
    """(ix, fx): the lattice coordinate below x and x's place between it and the next."""
    ix = math.floor(x)
    return ix, x - ix
