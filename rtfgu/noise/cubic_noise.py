"""CubicNoise: Suffern ch. 31's value noise with tri-cubic interpolation: the 4 x 4 x 4
lattice values around the point through the Catmull-Rom four-knot spline, along x, then y,
then z, clamped to [-1, 1] (CubicNoise.cpp, after Peachey 2003)."""
from __future__ import annotations

from ..float3 import Float3
from .lattice_noise import VALUE_TABLE, LatticeNoise, lattice_cell, lattice_value


def four_knot_spline(x: float, knots) -> float:
    """The Catmull-Rom spline through knots[1] (x = 0) and knots[2] (x = 1)."""
    c3 = -0.5 * knots[0] + 1.5 * knots[1] - 1.5 * knots[2] + 0.5 * knots[3]
    c2 = knots[0] - 2.5 * knots[1] + 2.0 * knots[2] - 0.5 * knots[3]
    c1 = 0.5 * (-knots[0] + knots[2])
    c0 = knots[1]
    return ((c3 * x + c2) * x + c1) * x + c0


class CubicNoise(LatticeNoise):
    def value_noise(self, p: Float3) -> float:
        # Clamped: the spline may overshoot the knots.
        return min(max(self.interpolate(p, VALUE_TABLE), -1.0), 1.0)

    @staticmethod
    def interpolate(p: Float3, table) -> float:
        """The 4 x 4 x 4 lattice values of ``table`` around p, tri-cubically."""
        ix, fx = lattice_cell(p.x)
        iy, fy = lattice_cell(p.y)
        iz, fz = lattice_cell(p.z)
        zknots = []
        for k in (-1, 0, 1, 2):
            yknots = []
            for j in (-1, 0, 1, 2):
                xknots = [lattice_value(ix + i, iy + j, iz + k, table) for i in (-1, 0, 1, 2)]
                yknots.append(four_knot_spline(fx, xknots))
            zknots.append(four_knot_spline(fy, yknots))
        return four_knot_spline(fz, zknots)
