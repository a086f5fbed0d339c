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

from ..float3 import Float3, as_float3, cross, normalize
from ..ray import Ray
from .camera import Camera


class PinholeCamera(Camera):
    def __init__(self, eye, lookat, up, d: float = 1.0, aspect: float = 1.0):
        self.eye = as_float3(eye, "PinholeCamera.eye")
        self.lookat = as_float3(lookat, "PinholeCamera.lookat")
        self.up = as_float3(up, "PinholeCamera.up")
        if not (math.isfinite(d) and d > 0):
            raise ValueError("PinholeCamera.d (camera constant) must be finite and > 0, got %r" % (d,))
        if not (math.isfinite(aspect) and aspect > 0):
            raise ValueError("PinholeCamera.aspect must be finite and > 0, got %r" % (aspect,))
        self.d = float(d)
        self.aspect = float(aspect)
        view = self.lookat - self.eye
        if view.length_squared() == 0.0:
            raise ValueError("PinholeCamera.lookat must differ from eye (no view direction)")
        self.v = normalize(view)
        right = cross(self.v, self.up)
        # up parallel to the view leaves no image plane; 1e-12 of |up|^2 is far below any real camera.
        if right.length_squared() <= 1e-12 * self.up.length_squared():
            raise ValueError("PinholeCamera.up must not be parallel to the view direction (lookat - eye)")
        self.b1 = normalize(right)
        self.b2 = cross(self.b1, self.v)

    def gen_ray(self, sx: float, sy: float) -> Ray:
        u = sx * self.aspect * 0.5
        w = sy * 0.5
        q = self.b1 * u + self.b2 * w + self.v * self.d
        # A copy: the C++ Ray holds its origin by value, so moving a ray never moves the eye.
        return Ray(self.eye.copy(), normalize(q))
