"""LinearNoise: Suffern ch. 31's value noise with tri-linear interpolation of the eight
lattice values around the point (LinearNoise.cpp, after Hill and Kelley 2006)."""
from __future__ import annotations

from ..float3 import Float3
from .lattice_noise import VALUE_TABLE, LatticeNoise, lattice_cell, lattice_value


def lerp(f: float, a: float, b: float) -> float:
    return a + f * (b - a)


class LinearNoise(LatticeNoise):
    def value_noise(self, p: Float3) -> float:
        return self.interpolate(p, VALUE_TABLE)

    @staticmethod
    def interpolate(p: Float3, table) -> float:
        """The eight lattice values of ``table`` around p, tri-linearly."""
        ix, fx = lattice_cell(p.x)
        iy, fy = lattice_cell(p.y)
        iz, fz = lattice_cell(p.z)
        # d[k][j][i]: the value at (ix + i, iy + j, iz + k)
        d = [[[lattice_value(ix + i, iy + j, iz + k, table) for i in (0, 1)] for j in (0, 1)] for k in (0, 1)]
        x0 = lerp(fx, d[0][0][0], d[0][0][1])
        x1 = lerp(fx, d[0][1][0], d[0][1][1])
        x2 = lerp(fx, d[1][0][0], d[1][0][1])
        x3 = lerp(fx, d[1][1][0], d[1][1][1])
        y0 = lerp(fy, x0, x1)
        y1 = lerp(fy, x2, x3)
        return lerp(fz, y0, y1)
