"""BBox: an axis-aligned bounding box (Suffern ch. 19, "Bounding Boxes"), the box between the
corners p0 (the least x, y, z) and p1 (the greatest).

The slab test (Kay and Kajiya 1986, in the form of Williams et al. 2005, "An Efficient and
Robust Ray-Box Intersection Algorithm"): for each axis the ray is inside the slab
p0[a] <= o[a] + t w[a] <= p1[a] for t between (p0[a] - o[a]) / w[a] and (p1[a] - o[a]) / w[a];
the ray meets the box where the three intervals and [tmin, tmax] overlap. A direction
component of 0 gives no interval: the ray is in that slab for every t, or for none. The far
end is widened by 1 + 2 gamma_3 (PBRT-v4 section 6.1.2, gamma_n = n u / (1 - n u)), so that
rounding never makes the test miss a shape whose own test hits it.
"""
from __future__ import annotations

import math

from ..float3 import Float3
from ..ray import Ray

_U = 2.0 ** -53                     # the unit roundoff of float64
WIDEN = 1.0 + 2.0 * (3 * _U) / (1 - 3 * _U)
_U32 = 2.0 ** -24                   # float32's, for the kernels' twins of hit
WIDEN32 = 1.0 + 2.0 * (3 * _U32) / (1 - 3 * _U32)


class BBox:
    __slots__ = ("p0", "p1")

    def __init__(self, p0: Float3, p1: Float3):
        self.p0 = p0
        self.p1 = p1

    @staticmethod
    def of_points(points) -> "BBox":
        points = list(points)
        return BBox(Float3(min(p.x for p in points), min(p.y for p in points), min(p.z for p in points)),
                    Float3(max(p.x for p in points), max(p.y for p in points), max(p.z for p in points)))

    def union(self, other: "BBox") -> "BBox":
        return BBox(Float3(min(self.p0.x, other.p0.x), min(self.p0.y, other.p0.y), min(self.p0.z, other.p0.z)),
                    Float3(max(self.p1.x, other.p1.x), max(self.p1.y, other.p1.y), max(self.p1.z, other.p1.z)))

    def centroid(self) -> Float3:
        return (self.p0 + self.p1) * 0.5

    def surface_area(self) -> float:
        d = self.p1 - self.p0
        return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)

    def contains(self, other: "BBox") -> bool:
        return all(self.p0[a] <= other.p0[a] and other.p1[a] <= self.p1[a] for a in range(3))

    def hit(self, ray: Ray) -> float:
        """The t at which the ray enters the box within [tmin, tmax], or inf if it misses."""
        # TODO a08: BBox.hit
        #   The slab test. Start with t0, t1 = ray.tmin, ray.tmax. For each axis a in 0, 1, 2 (a Float3
        #   indexes as v[a]), with o = ray.origin[a] and w = ray.direction[a]:
        #   if w == 0 the ray stays in the slab for every t or for none: return math.inf when o < p0[a]
        #   or o > p1[a], else go on with the next axis (no division). Otherwise
        #   t_near = (p0[a] - o) / w, t_far = (p1[a] - o) / w, swapped when t_near > t_far (w < 0);
        #   t_far *= WIDEN; t0 = max(t0, t_near), t1 = min(t1, t_far); return math.inf as soon as t0 > t1.
        #   Return t0, where the ray enters the box. The ray is not changed.
        raise NotImplementedError('a08: BBox.hit')


# How much a curved shape's box grows: a shape's own test may accept, by rounding, a grazing
# hit a little outside its exact outline (a sphere's discriminant rounded up to 0).
PAD = 2.0 ** -32


def padded(center: Float3, reach: Float3) -> BBox:
    """The box center +- reach, grown by PAD times the shape's size and distance from the origin."""
    pad = PAD * (max(abs(center.x), abs(center.y), abs(center.z)) + max(reach.x, reach.y, reach.z))
    grown = Float3(reach.x + pad, reach.y + pad, reach.z + pad)
    return BBox(center - grown, center + grown)
