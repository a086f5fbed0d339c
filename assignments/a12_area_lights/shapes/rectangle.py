"""Rectangle: corner ``p0`` and the perpendicular edge vectors ``a`` and ``b`` (Suffern ch. 19,
"Rectangles"), the points p0 + s a + t b with s, t in [0, 1].

The book's ``Rectangle::hit``: the ray meets the rectangle's plane (normal n = a x b,
normalised) at

    t = ((p0 - o) . n) / (d . n)

(``Plane.intersect_p``, lecture 01, as the disk does), and the hit counts when d' = o + t d - p0 projects onto a and b within the edges:

    0 <= d' . a <= |a|^2   and   0 <= d' . b <= |b|^2

(the edges belong to the rectangle, as the disk's rim belongs to the disk). A ray parallel
to the plane (d . n = 0) misses it, as it misses the plane.

As an area light's shape (Suffern ch. 18.6, "Rectangular lights") it offers ``sample(u, v)``
= p0 + u a + v b, uniform by area for (u, v) uniform in the unit square, ``pdf`` = 1 / area
with area = |a| |b|, and ``get_normal`` = n: it emits from the side n points to.
"""
from __future__ import annotations

from ..float3 import Float3, as_float3, cross, dot, normalize
from .planar_shape import PlanarShape
from .shape import nonzero_vector

# How far from perpendicular a and b may be: |a . b| <= PERPENDICULAR |a| |b|. The
# projection test above is the rectangle's only when they are perpendicular; a rotated
# rectangle's edges rounded to float32 are perpendicular to about 1e-7.
PERPENDICULAR = 1e-5


def perpendicular_edges(a, b) -> tuple:
    """The edge vectors a and b, refused unless nonzero and perpendicular (PERPENDICULAR)."""
    a = nonzero_vector(a, "Rectangle.a")
    b = nonzero_vector(b, "Rectangle.b")
    if abs(dot(a, b)) > PERPENDICULAR * a.length() * b.length():
        raise ValueError("Rectangle.a and Rectangle.b must be perpendicular edge vectors, got a = %r, "
                         "b = %r (a . b = %r)" % (a, b, dot(a, b)))
    return a, b


class Rectangle(PlanarShape):
    def __init__(self, p0, a, b, color, material=None):
        super().__init__(color, material)
        self.p0 = as_float3(p0, "Rectangle.p0")
        self.a, self.b = perpendicular_edges(a, b)
        self.normal = normalize(cross(self.a, self.b))
        self.a_len_squared = dot(self.a, self.a)
        self.b_len_squared = dot(self.b, self.b)
        self.set_plane(self.p0, self.normal)

    def contains(self, position: Float3) -> bool:
        d = position - self.p0
        ddota = dot(d, self.a)
        if ddota < 0.0 or ddota > self.a_len_squared:
            return False
        ddotb = dot(d, self.b)
        return 0.0 <= ddotb <= self.b_len_squared

    def normal_at(self, position: Float3) -> Float3:
        return self.normal

    def bounds(self):
        from ..accelerators.bbox import BBox
        return BBox.of_points((self.p0, self.p0 + self.a, self.p0 + self.b, self.p0 + self.a + self.b))

    def texcoord(self, position: Float3) -> tuple:
        """(u, v) in the unit square: the point's projections onto a and b over |a|^2 and |b|^2."""
        d = position - self.p0
        return dot(d, self.a) / self.a_len_squared, dot(d, self.b) / self.b_len_squared

    # An area light's shape (Suffern ch. 18.6): sample, pdf and get_normal.
    @property
    def area(self) -> float:
        return self.a.length() * self.b.length()

    def sample(self, u: float, v: float) -> Float3:
        """p0 + u a + v b: uniform by area for (u, v) uniform in [0, 1)^2."""
        # TODO a12: Rectangle.sample
        #   A point of the rectangle uniform by area (Suffern ch. 18.6, Rectangle::sample): p0 + u a + v b.
        raise NotImplementedError('a12: Rectangle.sample')

    def pdf(self, sr=None) -> float:
        return 1.0 / self.area

    def get_normal(self, point: Float3 = None) -> Float3:
        return self.normal
