"""Ray: a half line o + t d with the interval [tmin, tmax) (lecture 01, "Ray" slides).

``tmax`` starts at infinity and is shrunk by ``Shape.intersect_p`` to the nearest hit
found so far, so a ray is used for one closest-hit query: every new ray (camera, shadow,
mirror, refraction) starts with a fresh ``tmax``.
"""
from __future__ import annotations

import math
from math import isfinite

from .float3 import Float3

# The slide's RAY_EPSILON: the orthographic camera's default hither and the tmin of its rays
# ("we use a very small value because we want to avoid the case where the view plane is on
# the surface of something").
RAY_EPSILON = 0.00001


class Ray:
    __slots__ = ("origin", "direction", "tmin", "tmax")

    def __init__(self, origin: Float3 | None = None, direction: Float3 | None = None,
                 tmin: float = 0.0, tmax: float = math.inf):
        self.origin = Float3(0, 0, 0) if origin is None else origin
        self.direction = Float3(0, 0, 1) if direction is None else direction
        self.tmin = float(tmin)
        self.tmax = float(tmax)
        # Every ray of every path is checked, so the checks are written out (no method calls).
        o, d = self.origin, self.direction
        if not (isfinite(o.x) and isfinite(o.y) and isfinite(o.z)):
            raise ValueError("Ray.origin must be finite, got %r" % (o,))
        if not (isfinite(d.x) and isfinite(d.y) and isfinite(d.z)) or d.x * d.x + d.y * d.y + d.z * d.z == 0.0:
            raise ValueError("Ray.direction must be finite and non-zero, got %r" % (d,))
        if self.tmin != self.tmin or self.tmax != self.tmax:
            raise ValueError("Ray.tmin and Ray.tmax must not be NaN")

    def __call__(self, t: float) -> Float3:
        """The point at parameter t: origin + direction * t (the slide's operator())."""
        ### BEGIN SOLUTION
        return self.origin + self.direction * t
        ### END SOLUTION

    def __repr__(self) -> str:
        return "Ray(%r, %r, tmin=%r, tmax=%r)" % (self.origin, self.direction, self.tmin, self.tmax)

# How far along its direction a secondary (shadow, mirror, refracted, path) ray starts, so
# that it does not hit the surface it leaves: the slide's tmin idea, sized for float32 too.
SPAWN_EPSILON = 1e-4
