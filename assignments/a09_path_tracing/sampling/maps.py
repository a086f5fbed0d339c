"""Maps of unit-square samples to the unit disk and the hemisphere (Suffern ch. 6-7).

Each map is a function of one point, so the lecture layer, the numba kernels
(rtfgu/kernels/sampling.py) and WGSL (rtfgu/wgsl/sampling.wgsl) apply the same map to the
same sample; tests/test_sampling.py checks each against its density (chi-square).
"""
from __future__ import annotations

import math

from ..float3 import Float3


def concentric_map(x: float, y: float) -> tuple:
    """Shirley and Chiu's concentric map of [0, 1]^2 onto the unit disk, as Suffern's
    Sampler::map_samples_to_unit_disk: squares about the centre go to circles, so
    stratification survives and area is preserved (density 1 / pi)."""
    # TODO a10: concentric_map
    #   Shirley and Chiu's concentric map (Suffern ch. 6, "Mapping Samples to a Unit Disk"): with
    #   (sx, sy) = (2x - 1, 2y - 1) in [-1, 1]^2, find the region (of four, split by the diagonals)
    #   the point is in; r is the coordinate of largest magnitude and phi/(pi/4) runs from 0 to 8
    #   around the square (region 1: r = sx, phi = sy/sx; region 2: r = sy, phi = 2 - sx/sy;
    #   region 3: r = -sx, phi = 4 + sy/sx; region 4: r = -sy, phi = 6 - sx/sy, and 0 at the centre).
    #   Return (r cos(phi pi/4), r sin(phi pi/4)).
    raise NotImplementedError('a10: concentric_map')


def hemisphere_map(x: float, y: float, e: float) -> Float3:
    """A direction about +z with density (e + 1) / (2 pi) cos^e(theta), as Suffern's
    Sampler::map_samples_to_hemisphere: phi = 2 pi x, cos(theta) = (1 - y)^(1 / (e + 1)).
    e = 1 is the cosine-weighted hemisphere."""
    # TODO a09: hemisphere_map
    #   Suffern's map of (x, y) in [0, 1)^2 to a direction about +z with density
    #   (e + 1) / (2 pi) cos^e(theta): phi = 2 pi x, cos(theta) = (1 - y)^(1 / (e + 1)),
    #   sin(theta) = sqrt(1 - cos^2(theta)); return Float3(sin(theta) cos(phi), sin(theta) sin(phi), cos(theta)).
    raise NotImplementedError('a09: hemisphere_map')


def orthonormal_basis(n: Float3) -> tuple:
    """Two unit vectors t, b with (t, b, n) orthonormal, for a unit n (Duff et al., "Building
    an Orthonormal Basis, Revisited", JCGT 6(1), 2017), without a branch on n but its sign."""
    sign = 1.0 if n.z >= 0.0 else -1.0
    a = -1.0 / (sign + n.z)
    b = n.x * n.y * a
    return Float3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), Float3(b, sign + n.y * n.y * a, -n.y)


def about(axis: Float3, local: Float3) -> Float3:
    """``local`` (x, y, z) in the frame whose z is the unit ``axis``: a hemisphere_map sample
    turned about a normal or a mirror direction."""
    t, b = orthonormal_basis(axis)
    return t * local.x + b * local.y + axis * local.z
