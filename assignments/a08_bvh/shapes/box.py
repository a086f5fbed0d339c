"""Box: the axis-aligned box between the corners ``p0`` (least x, y, z) and ``p1`` (greatest)
(Suffern ch. 19, "Axis-aligned boxes").

The book's ``Box::hit`` is the slab test: per axis, with a = 1 / d_x,

    tx_min, tx_max = (x0 - o_x) a, (x1 - o_x) a     (swapped when a < 0)

and so for y and z; the ray is inside the box between t0, the largest entering t, and t1,
the smallest leaving t. It hits when t0 < t1 (a ray that only touches an edge or a corner,
t0 = t1, misses, as in the book): at t0, or at t1 when t0 is behind tmin (a ray from inside
the box leaves by a face). rtfgu departs from the book in one place: an axis along which the
ray does not move (d_x = 0, where the book divides by zero) puts no bound on t when o_x is
within [x0, x1] and misses the box otherwise, so that no path ever computes 0 * inf.

The normal is the outward normal of the face hit (the book's ``get_normal(face)``, faces 0-5
being -x, -y, -z, +x, +y, +z). rtfgu's normals are functions of the hit point
(``normal_at(position)``), so the face is the one the point lies nearest to, the first of
-x, -y, -z, +x, +y, +z on an edge or a corner.
"""
from __future__ import annotations

import math

from ..float3 import Float3, as_float3
from ..ray import Ray
from .shape import Shape

# The book's get_normal(face): faces 0-5.
FACE_NORMALS = (Float3(-1.0, 0.0, 0.0), Float3(0.0, -1.0, 0.0), Float3(0.0, 0.0, -1.0),
                Float3(1.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.0, 0.0, 1.0))


class Box(Shape):
    def __init__(self, p0, p1, color, material=None):
        super().__init__(color, material)
        self.p0 = as_float3(p0, "Box.p0")
        self.p1 = as_float3(p1, "Box.p1")
        for axis in range(3):
            if not self.p0[axis] < self.p1[axis]:
                raise ValueError("Box.p0 must be below Box.p1 in every axis (a box with volume), got p0 = %r, "
                                 "p1 = %r (axis %s)" % (self.p0, self.p1, "xyz"[axis]))

    def intersect_p(self, ray: Ray) -> bool:
        # TODO a08: Box.intersect_p
        #   Suffern's axis-aligned box (ch. 19.5, Box::hit): the slab test again, now for a shape. Start with
        #   t0, t1 = -inf, inf; per axis, a ray parallel to the slab (d == 0) misses if its origin is outside
        #   [p0, p1] on that axis and is not limited by it otherwise; else t_near and t_far are where it crosses
        #   the slab's planes (swapped when the direction is negative); t0 is the largest t_near, t1 the
        #   smallest t_far. The ray meets the box when t0 < t1: at t0, or at t1 if t0 < ray.tmin (it starts
        #   inside). A hit needs tmin <= t < tmax; then set ray.tmax = t and return True.
        raise NotImplementedError('a08: Box.intersect_p')

    def normal_at(self, position: Float3) -> Float3:
        """The outward normal of the face nearest to the point: the first of -x, -y, -z, +x,
        +y, +z at equal distances."""
        face = 0
        best = abs(position.x - self.p0.x)
        for k, distance in ((1, abs(position.y - self.p0.y)), (2, abs(position.z - self.p0.z)),
                            (3, abs(position.x - self.p1.x)), (4, abs(position.y - self.p1.y)),
                            (5, abs(position.z - self.p1.z))):
            if distance < best:
                face, best = k, distance
        return FACE_NORMALS[face]

    def bounds(self):
        from ..accelerators.bbox import BBox
        return BBox(self.p0, self.p1)

    def texcoord(self, position: Float3) -> tuple:
        """(u, v) on the face hit: the point's two other coordinates, from p0, over the box's
        size along them (x -> (y, z), y -> (z, x), z -> (x, y))."""
        n = self.normal_at(position)
        axis = 0 if n.x != 0.0 else (1 if n.y != 0.0 else 2)
        i, j = (axis + 1) % 3, (axis + 2) % 3
        return ((position[i] - self.p0[i]) / (self.p1[i] - self.p0[i]),
                (position[j] - self.p0[j]) / (self.p1[j] - self.p0[j]))
