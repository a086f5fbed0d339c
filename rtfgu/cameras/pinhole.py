"""PinholeCamera: the 02562 week-1 camera (eye, look-at, up, camera constant d).

The image-plane basis (02562 worksheet 1, "get_camera_ray"):
    v  = normalize(lookat - eye)          view direction
    b1 = normalize(cross(v, up))          image-plane right
    b2 = cross(b1, v)                     image-plane up
    q  = b1 * u + b2 * w + v * d,         direction = normalize(q)
where (u, w) = (sx * aspect * 0.5, sy * 0.5): the slide's
``uv = vec2f(coords.x*uniforms.aspect*0.5f, coords.y*0.5f)``.
"""
from __future__ import annotations

import math

from ..float3 import normalize
from ..ray import Ray
from .camera import Camera, look_at_basis


class PinholeCamera(Camera):
    def __init__(self, eye, lookat, up, d: float = 1.0, aspect: float = 1.0):
        self.eye, self.lookat, self.up, self.v, self.b1, self.b2 = look_at_basis(eye, lookat, up, "PinholeCamera")
        if not (math.isfinite(d) and d > 0):
            raise ValueError("PinholeCamera.d (camera constant) must be finite and > 0, got %r" % (d,))
        if not (math.isfinite(aspect) and aspect > 0):
            raise ValueError("PinholeCamera.aspect must be finite and > 0, got %r" % (aspect,))
        self.d = float(d)
        self.aspect = float(aspect)

    def gen_ray(self, sx: float, sy: float) -> Ray:
        ### BEGIN SOLUTION
        u = sx * self.aspect * 0.5
        w = sy * 0.5
        q = self.b1 * u + self.b2 * w + self.v * self.d
        # A copy: the C++ Ray holds its origin by value, so moving a ray never moves the eye.
        return Ray(self.eye.copy(), normalize(q))
        ### END SOLUTION
