"""Suffern ch. 31's lattice noise for the kernels, operation for operation as rtfgu/noise/:
the tables are rtfgu.noise.lattice_noise's own (numba freezes them into the compiled code),
so float64 gives the lecture layer's values bit for bit. ``noise`` is the row's noise id
(0 LinearNoise, 1 CubicNoise)."""
from __future__ import annotations

import numpy as np
from numba import njit

from ..noise.lattice_noise import PERMUTATION_TABLE, TABLE_MASK, VALUE_TABLE, VECTOR_TABLES
from .float3 import add, lit, scale

PERM = np.array(PERMUTATION_TABLE, dtype=np.int64)
VALUES = np.array(VALUE_TABLE, dtype=np.float64)
VECTOR_X, VECTOR_Y, VECTOR_Z = (np.array(t, dtype=np.float64) for t in VECTOR_TABLES)
LINEAR = 0


@njit(cache=True, error_model="numpy")
def lattice_value(ix, iy, iz, like, table):
    """table[INDEX(ix, iy, iz)] in the precision of ``like``."""
    k = PERM[(ix + PERM[(iy + PERM[iz & TABLE_MASK]) & TABLE_MASK]) & TABLE_MASK]
    return lit(table[k], like)


@njit(cache=True, error_model="numpy")
def lattice_cell(x):
    """(ix, fx): the lattice coordinate below x and x - ix."""
    fi = np.floor(x)
    return int(fi), x - fi


@njit(cache=True, error_model="numpy")
def lerp(f, a, b):
    return a + f * (b - a)


@njit(cache=True, error_model="numpy")
def linear_interpolate(p, t):
    """LinearNoise.interpolate: the eight values of table ``t`` around p."""
    ix, fx = lattice_cell(p[0])
    iy, fy = lattice_cell(p[1])
    iz, fz = lattice_cell(p[2])
    x0 = lerp(fx, lattice_value(ix, iy, iz, fx, t), lattice_value(ix + 1, iy, iz, fx, t))
    x1 = lerp(fx, lattice_value(ix, iy + 1, iz, fx, t), lattice_value(ix + 1, iy + 1, iz, fx, t))
    x2 = lerp(fx, lattice_value(ix, iy, iz + 1, fx, t), lattice_value(ix + 1, iy, iz + 1, fx, t))
    x3 = lerp(fx, lattice_value(ix, iy + 1, iz + 1, fx, t), lattice_value(ix + 1, iy + 1, iz + 1, fx, t))
    y0 = lerp(fy, x0, x1)
    y1 = lerp(fy, x2, x3)
    return lerp(fz, y0, y1)


@njit(cache=True, error_model="numpy")
def four_knot_spline(x, k0, k1, k2, k3):
    """rtfgu.noise.cubic_noise.four_knot_spline."""
    half = lit(0.5, x)
    c3 = -half * k0 + lit(1.5, x) * k1 - lit(1.5, x) * k2 + half * k3
    c2 = k0 - lit(2.5, x) * k1 + lit(2.0, x) * k2 - half * k3
    c1 = half * (-k0 + k2)
    return ((c3 * x + c2) * x + c1) * x + k1


@njit(cache=True, error_model="numpy")
def _cubic_row(ix, iy, iz, fx, t):
    """The spline along x through the four lattice values of row (iy, iz)."""
    return four_knot_spline(fx, lattice_value(ix - 1, iy, iz, fx, t), lattice_value(ix, iy, iz, fx, t),
                            lattice_value(ix + 1, iy, iz, fx, t), lattice_value(ix + 2, iy, iz, fx, t))


@njit(cache=True, error_model="numpy")
def _cubic_plane(ix, iy, iz, fx, fy, t):
    """The spline along y through the four rows of plane iz."""
    return four_knot_spline(fy, _cubic_row(ix, iy - 1, iz, fx, t), _cubic_row(ix, iy, iz, fx, t),
                            _cubic_row(ix, iy + 1, iz, fx, t), _cubic_row(ix, iy + 2, iz, fx, t))


@njit(cache=True, error_model="numpy")
def cubic_interpolate(p, t):
    """CubicNoise.interpolate: the 4 x 4 x 4 values of table ``t`` around p."""
    ix, fx = lattice_cell(p[0])
    iy, fy = lattice_cell(p[1])
    iz, fz = lattice_cell(p[2])
    return four_knot_spline(fz, _cubic_plane(ix, iy, iz - 1, fx, fy, t), _cubic_plane(ix, iy, iz, fx, fy, t),
                            _cubic_plane(ix, iy, iz + 1, fx, fy, t), _cubic_plane(ix, iy, iz + 2, fx, fy, t))


@njit(cache=True, error_model="numpy")
def linear_noise(p):
    """LinearNoise.value_noise."""
    return linear_interpolate(p, VALUES)


@njit(cache=True, error_model="numpy")
def cubic_noise(p):
    """CubicNoise.value_noise: clamped to [-1, 1]."""
    one = lit(1.0, p[0])
    return min(max(cubic_interpolate(p, VALUES), -one), one)


@njit(cache=True, error_model="numpy")
def value_noise(noise, p):
    if noise == LINEAR:
        return linear_noise(p)
    return cubic_noise(p)


@njit(cache=True, error_model="numpy")
def octave_sum(noise, num_octaves, lacunarity, gain, absolute, p):
    """LatticeNoise.octave_sum: sum of gain^j value_noise(lacunarity^j p) (of its absolute
    value when ``absolute``), not mapped, in the precision of ``gain``."""
    amplitude = lit(1.0, gain)
    frequency = lit(1.0, gain)
    total = lit(0.0, gain)
    for _ in range(num_octaves):
        noise_value = value_noise(noise, scale(p, frequency))
        total += amplitude * (abs(noise_value) if absolute else noise_value)
        amplitude *= gain
        frequency *= lacunarity
    return total


@njit(cache=True, error_model="numpy")
def value_fractal_sum(noise, num_octaves, fbm_max, p):
    """LatticeNoise.value_fractal_sum."""
    fractal_sum = octave_sum(noise, num_octaves, lit(2.0, fbm_max), lit(0.5, fbm_max), False, p)
    return (fractal_sum + fbm_max) / (fbm_max + fbm_max)


@njit(cache=True, error_model="numpy")
def value_turbulence(noise, num_octaves, fbm_max, p):
    """LatticeNoise.value_turbulence."""
    return octave_sum(noise, num_octaves, lit(2.0, fbm_max), lit(0.5, fbm_max), True, p) / fbm_max


@njit(cache=True, error_model="numpy")
def value_fbm(noise, num_octaves, lacunarity, gain, fbm_max, p):
    """LatticeNoise.value_fbm."""
    fbm = octave_sum(noise, num_octaves, lacunarity, gain, False, p)
    return (fbm + fbm_max) / (fbm_max + fbm_max)


@njit(cache=True, error_model="numpy")
def row_fbm(rec, first, p):
    """value_fbm of the noise whose fields (rtfgu.registry.NOISE_FIELDS) start at column
    ``first`` of the texture row ``rec``."""
    return value_fbm(int(rec[first]), int(rec[first + 1]), rec[first + 2], rec[first + 3], rec[first + 4], p)


@njit(cache=True, error_model="numpy")
def vector_noise(noise, p):
    """LatticeNoise.vector_noise: the unit vectors' three tables interpolated."""
    if noise == LINEAR:
        return linear_interpolate(p, VECTOR_X), linear_interpolate(p, VECTOR_Y), linear_interpolate(p, VECTOR_Z)
    return cubic_interpolate(p, VECTOR_X), cubic_interpolate(p, VECTOR_Y), cubic_interpolate(p, VECTOR_Z)


@njit(cache=True, error_model="numpy")
def vector_fbm(noise, num_octaves, lacunarity, gain, p):
    """LatticeNoise.vector_fbm."""
    amplitude = lit(1.0, gain)
    frequency = lit(1.0, gain)
    zero = lit(0.0, gain)
    total = (zero, zero, zero)
    for _ in range(num_octaves):
        total = add(total, scale(vector_noise(noise, scale(p, frequency)), amplitude))
        amplitude *= gain
        frequency *= lacunarity
    return total
