"""Shape: something a ray can hit (lecture 01, "Class Shape").

``intersect_p(ray)`` returns True if the ray hits the shape within [ray.tmin, ray.tmax)
and then shrinks ``ray.tmax`` to the hit distance; it changes nothing else. Calling it on
every shape in turn therefore leaves ``ray.tmax`` at the nearest hit (the slide's render
loop). Because of that side effect a ray serves one closest-hit query: start every new
ray with a fresh ``tmax``.
"""
from __future__ import annotations

from abc import ABC, abstractmethod

from ..float3 import Float3, as_float3, cross, dot, normalize
from ..materials.material import Material
from ..ray import Ray
from ..validation import nonzero_vector, positive  # noqa: F401  (the shapes' checks)


class Shape(ABC):
    def __init__(self, color, material: Material | None = None):
        self.color = as_float3(color, type(self).__name__ + ".color")
        self.material = Material() if material is None else material
        if not isinstance(self.material, Material):
            raise ValueError("%s.material must be a Material, got %r" % (type(self).__name__, material))

    @abstractmethod
    def intersect_p(self, ray: Ray) -> bool:
        """True on a hit in [ray.tmin, ray.tmax); then ray.tmax is the hit distance."""

    @abstractmethod
    def normal_at(self, position: Float3) -> Float3:
        """The unit geometric normal at a point on the surface."""

    def hit_normal(self, position: Float3, direction: Float3) -> Float3:
        """The normal a hit by a ray along ``direction`` records (Scene.intersect): the
        geometric ``normal_at``. A shape whose book's ``hit`` turns the normal toward the
        ray (Suffern's OpenCylinder, seen from inside and out) overrides it."""
        return self.normal_at(position)

    def bounds(self):
        """The shape's axis-aligned bounding box (rtfgu.accelerators.BBox), or None for a
        shape without one (a plane): what a BVH holds."""
        return None

    def sample_with_normal(self, u: float, v: float) -> tuple:
        """(point, unit normal) of an area light's shape: ``sample(u, v)`` and
        ``get_normal`` there (Suffern ch. 18: a shape that offers ``sample``, ``pdf`` and
        ``get_normal`` can be an AreaLight's)."""
        point = self.sample(u, v)
        return point, self.get_normal(point)

    def texcoord(self, position: Float3) -> tuple:
        """The texture coordinates (u, v) of a point on the surface (textures, Suffern ch. 29)."""
        raise NotImplementedError("%s has no texture coordinates" % type(self).__name__)


def plane_texcoord(position: Float3, point: Float3, normal: Float3) -> tuple:
    """(u, v) on a plane: (p - point) . tangent and (p - point) . binormal, with the binormal
    the plane's direction closest to +z (+x for a plane facing z) and tangent =
    binormal x n. A floor (n = +y) gets worksheet 3's tangent (-1, 0, 0), binormal (0, 0, 1)."""
    n = normalize(normal)
    binormal = Float3(0.0, 0.0, 1.0) - n * n.z
    if binormal.length_squared() < 1e-12:
        binormal = Float3(1.0, 0.0, 0.0) - n * n.x
    binormal = normalize(binormal)
    tangent = cross(binormal, n)
    d = position - point
    return dot(d, tangent), dot(d, binormal)


def meets_plane(plane, ray):
    """The t at which ``ray`` meets ``plane`` within [tmin, tmax), by the plane's own
    intersect_p on a copy of the ray (the ray is not changed), or None: the first step of the
    shapes that lie in a plane, the Disk and the Rectangle (Suffern ch. 19)."""
    probe = Ray(ray.origin, ray.direction, ray.tmin, ray.tmax)
    return probe.tmax if plane.intersect_p(probe) else None
