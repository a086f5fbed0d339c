"""Torus: the ring torus about the y axis through the origin, with sweep radius ``a`` (from
the axis to the centre of the tube) and tube radius ``b`` < a (Suffern ch. 19, "Tori").

Its implicit equation is (x^2 + y^2 + z^2 + a^2 - b^2)^2 = 4 a^2 (x^2 + z^2), and a ray
o + t d meets it where (the book's ``Torus::hit``, with e = o.o - a^2 - b^2 and f = o.d)

    c4 t^4 + c3 t^3 + c2 t^2 + c1 t + c0 = 0,
    c4 = (d.d)^2,  c3 = 4 (d.d) f,  c2 = 2 (d.d) e + 4 f^2 + 4 a^2 d_y^2,
    c1 = 4 f e + 8 a^2 o_y d_y,  c0 = e^2 - 4 a^2 (b^2 - o_y^2).

The book first tests the ray against the torus's bounding box (BBox.hit, Suffern ch. 19, which
is assignment a08's: a student's torus works once a08 is solved), then
solves the quartic with Schwarze's ``SolveQuartic`` (rtfgu.shapes.quartic, which also polishes
each root with Newton's method) and takes the least root in range. rtfgu departs from the book
in one place, for the digits: the quartic is written for the ray from where it enters the box
with a unit direction, o' = o + t_box d and d' = d / |d|, and the hit is at t = t_box + s / |d|
for its root s. A far origin gives coefficients of size |o|^4 whose leading digits cancel; from
the box they are of size (a + b)^4, and with |d'| = 1 the roots are distances of the size of
the torus (in float32, a direction of length 1e3 left the closed form no correct digit).

The normal is the gradient of the implicit function, the book's ``compute_normal``:
(4 x (|p|^2 - a^2 - b^2), 4 y (|p|^2 - a^2 - b^2 + 2 a^2), 4 z (|p|^2 - a^2 - b^2)), normalised.
"""
from __future__ import annotations

import math

from ..float3 import Float3, normalize
from ..ray import Ray
from .quartic import solve_quartic
from .shape import Shape, positive


class Torus(Shape):
    def __init__(self, a: float, b: float, color, material=None):
        super().__init__(color, material)
        self.a = positive(a, "Torus.a")
        self.b = positive(b, "Torus.b")
        if not self.b < self.a:
            raise ValueError("Torus.b, the tube radius, must be below Torus.a, the sweep radius, got a = %r, "
                             "b = %r (b >= a is a horn or spindle torus, which is not a ring)" % (self.a, self.b))
        self._box = self.bounds()

    def intersect_p(self, ray: Ray) -> bool:
        t_box = self._box.hit(ray)
        if t_box == math.inf:
            return False
        o = ray.origin + ray.direction * t_box
        length = ray.direction.length()
        d = ray.direction / length
        a, b = self.a, self.b
        sum_d_sqrd = d.x * d.x + d.y * d.y + d.z * d.z
        e = o.x * o.x + o.y * o.y + o.z * o.z - a * a - b * b
        f = o.x * d.x + o.y * d.y + o.z * d.z
        four_a_sqrd = 4.0 * a * a
        count, roots = solve_quartic(e * e - four_a_sqrd * (b * b - o.y * o.y),
                                     4.0 * f * e + 2.0 * four_a_sqrd * o.y * d.y,
                                     2.0 * sum_d_sqrd * e + 4.0 * f * f + four_a_sqrd * d.y * d.y,
                                     4.0 * sum_d_sqrd * f,
                                     sum_d_sqrd * sum_d_sqrd)
        t = math.inf
        for k in range(count):   # the least root in range; the roots are unsorted
            t_hit = t_box + roots[k] / length
            if ray.tmin <= t_hit < ray.tmax and t_hit < t:
                t = t_hit
        if t == math.inf:
            return False
        ray.tmax = t
        return True

    def normal_at(self, position: Float3) -> Float3:
        a, b = self.a, self.b
        param_squared = a * a + b * b
        x, y, z = position.x, position.y, position.z
        sum_squared = x * x + y * y + z * z
        return normalize(Float3(4.0 * x * (sum_squared - param_squared),
                                4.0 * y * (sum_squared - param_squared + 2.0 * a * a),
                                4.0 * z * (sum_squared - param_squared)))

    def bounds(self):
        """The book's box, (-a - b, -b, -a - b) to (a + b, b, a + b), grown as BBox.padded grows
        a curved shape's."""
        from ..accelerators.bbox import padded
        return padded(Float3(0.0, 0.0, 0.0), Float3(self.a + self.b, self.b, self.a + self.b))

    def texcoord(self, position: Float3) -> tuple:
        """u = phi / (2 pi) about the y axis, phi = atan2(x, z) in [0, 2 pi) (as Suffern's
        CylindricalMap); v = theta / (2 pi) about the tube, theta = atan2(y, rho - a) in
        [0, 2 pi) with rho = sqrt(x^2 + z^2): 0 on the outer equator, 1/4 on top, 1/2 on the
        inner equator."""
        x, y, z = position.x, position.y, position.z
        two_pi = 2.0 * math.pi
        phi = math.atan2(x, z)
        if phi < 0.0:
            phi += two_pi
        theta = math.atan2(y, math.sqrt(x * x + z * z) - self.a)
        if theta < 0.0:
            theta += two_pi
        return phi / two_pi, theta / two_pi
