"""OrthographicCamera: parallel rays along -z (lecture 01, "Orthographic Camera")."""
from __future__ import annotations

import math

from ..float3 import Float3
from ..ray import RAY_EPSILON, Ray
from .camera import Camera


class OrthographicCamera(Camera):
    """The prism left..right x bottom..top x hither..yon, looked at along -z."""

    def __init__(self, left: float, right: float, bottom: float, top: float,
                 hither: float = RAY_EPSILON, yon: float = math.inf):
        for name, value in (("left", left), ("right", right), ("bottom", bottom), ("top", top),
                            ("hither", hither)):
            if not math.isfinite(value):
                raise ValueError("OrthographicCamera.%s must be finite, got %r" % (name, value))
        if math.isnan(yon):
            raise ValueError("OrthographicCamera.yon must not be NaN")
        if right == left:
            raise ValueError("OrthographicCamera.right must differ from left")
        if top == bottom:
            raise ValueError("OrthographicCamera.top must differ from bottom")
        self.left = float(left)
        self.right = float(right)
        self.bottom = float(bottom)
        self.top = float(top)
        self.hither = float(hither)
        self.yon = float(yon)

    def gen_ray(self, sx: float, sy: float) -> Ray:
        # OrthographicCamera::gen_ray, line for line.
        # shift to the centre of the pixel (half a pixel of a 64-pixel image)
        sx = 0.5 + sx / 2 + 0.5 / 64
        sy = 0.5 + sy / 2 + 0.5 / 64

        x = self.left + (self.right - self.left) * sx
        y = self.bottom + (self.top - self.bottom) * sy

        return Ray(Float3(x, y, self.hither), Float3(0, 0, -1), 0.00001, self.yon - self.hither)
