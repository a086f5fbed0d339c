"""Camera: maps a point (sx, sy) of the image plane [-1, 1]^2 to a ray (lecture 01, "Camera")."""
from __future__ import annotations

import math
from abc import ABC, abstractmethod

from ..float3 import Float3, as_float3, cross, normalize
from ..ray import Ray

# The interval of a blank ray (blank_ray): empty, so the ray hits nothing on any path.
BLANK_TMIN = 0.0
BLANK_TMAX = -1.0


class Camera(ABC):
    # True for a camera whose gen_ray also takes a point of the lens (ThinLens).
    uses_lens = False

    @abstractmethod
    def gen_ray(self, sx: float, sy: float) -> Ray:
        """The ray through (sx, sy), with -1 <= sx, sy <= 1; (-1, -1) is the bottom left."""


def blank_ray(origin: Float3, direction: Float3) -> Ray:
    """The ray of an image point a camera sees nothing through (outside a FishEye's circle,
    in a StereoCamera's gap): its interval [0, -1) is empty, so on every path it hits
    nothing and the tracer returns what a ray that leaves the scene sees, Scene.background
    (with an EnvironmentLight, the environment along ``direction``). Suffern leaves such
    pixels black (FishEye::render_scene traces no ray where r^2 > 1)."""
    return Ray(origin.copy(), direction, BLANK_TMIN, BLANK_TMAX)


def look_at_basis(eye, lookat, up, owner: str):
    """(eye, lookat, up, v, b1, b2) of a camera at ``eye`` looking at ``lookat``, the first
    three checked Float3s (02562 worksheet 1):
    v = normalize(lookat - eye) the view direction, b1 = normalize(v x up) the image
    plane's right, b2 = b1 x v its up. Suffern's (u, v, w) (ch. 9, compute_uvw) are
    (b1, b2, -v). Errors name ``owner``'s field."""
    eye = as_float3(eye, owner + ".eye")
    lookat = as_float3(lookat, owner + ".lookat")
    up = as_float3(up, owner + ".up")
    view = lookat - eye
    if view.length_squared() == 0.0:
        raise ValueError("%s.lookat must differ from eye (no view direction)" % owner)
    v = normalize(view)
    right = cross(v, up)
    # up parallel to the view leaves no image plane; 1e-12 of |up|^2 is far below any real camera.
    if right.length_squared() <= 1e-12 * up.length_squared():
        raise ValueError("%s.up must not be parallel to the view direction (lookat - eye)" % owner)
    b1 = normalize(right)
    return eye, lookat, up, v, b1, cross(b1, v)


def check_angle(value, owner: str, name: str, largest: float) -> float:
    """``value`` in degrees, checked to lie in (0, largest]."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not 0.0 < value <= largest:
        raise ValueError("%s.%s must be an angle in degrees in (0, %g], got %r" % (owner, name, largest, value))
    return float(value)
