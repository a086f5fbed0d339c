"""StereoCamera: two pinhole cameras side by side, their images side by side with a gap
(Suffern ch. 12, "Stereoscopy"; StereoCamera::setup_cameras and render_stereo).

The two eyes sit at eye -/+ x b1, x = r tan(beta / 2) half their separation, r the distance
from eye to lookat: beta is the angle between the two eyes as seen from lookat. Both look
along the stereo camera's v, with its basis (b1, b2, v), camera constant d and aspect
hres / vres. Each view's image-plane window is shifted toward the other eye, by
+/- d tan(beta / 2), so that the two views' centre rays meet at lookat: the book's
pp.x = s (c - hres / 2 + sp.x) + x2 with the shift measured on rtfgu's image plane (height
1 at distance d); the book's views meet at distance d, the same point when d = r.

The image is hres + pixel_gap + hres pixels wide and vres high (``image_size``): the
parallel viewing type puts the left eye's view on the left, the transverse (cross-eyed)
type the right eye's. Rendered at another size the same layout is scaled: the column of an
image point is c = (sx + 1) / 2 (2 hres + pixel_gap) in pixels of the stereo image. A point
in the gap gets a blank ray (rtfgu.cameras.camera.blank_ray): Scene.background, where the
book leaves the window's pixels black.
"""
from __future__ import annotations

import math

from ..float3 import normalize
from ..ray import Ray
from .camera import Camera, blank_ray, look_at_basis

VIEWING_TYPES = ("parallel", "transverse")


def _check_count(value, name: str, least: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < least:
        raise ValueError("StereoCamera.%s must be an integer >= %d (pixels), got %r" % (name, least, value))
    return value


class StereoCamera(Camera):
    def __init__(self, eye, lookat, up, d: float = 1.0, hres: int = 200, vres: int = 200,
                 pixel_gap: int = 5, beta: float = 5.0, viewing: str = "parallel"):
        self.eye, self.lookat, self.up, self.v, self.b1, self.b2 = look_at_basis(eye, lookat, up, "StereoCamera")
        if not (math.isfinite(d) and d > 0):
            raise ValueError("StereoCamera.d (camera constant) must be finite and > 0, got %r" % (d,))
        self.d = float(d)
        self.hres = _check_count(hres, "hres", 1)
        self.vres = _check_count(vres, "vres", 1)
        self.pixel_gap = _check_count(pixel_gap, "pixel_gap", 0)
        if isinstance(beta, bool) or not isinstance(beta, (int, float)) or not (math.isfinite(beta)
                                                                                and 0.0 <= beta < 180.0):
            raise ValueError("StereoCamera.beta (stereo separation angle) must be in degrees in [0, 180), got %r"
                             % (beta,))
        self.beta = float(beta)
        if viewing not in VIEWING_TYPES:
            raise ValueError("StereoCamera.viewing must be one of %s, got %r" % (", ".join(VIEWING_TYPES), viewing))
        self.viewing = viewing
        self.aspect = self.hres / self.vres
        half = math.tan(0.5 * self.beta * (math.pi / 180.0))
        x = (self.lookat - self.eye).length() * half
        shift = self.d * half
        # The eye offset along b1 and the window shift of the view on the left of the image;
        # the view on the right has the opposite ones.
        self.offset, self.shift = (-x, shift) if viewing == "parallel" else (x, -shift)

    @property
    def image_size(self) -> tuple:
        """(width, height) in pixels of the stereo pair at the views' own size."""
        return 2 * self.hres + self.pixel_gap, self.vres

    def gen_ray(self, sx: float, sy: float) -> Ray:
        hres = float(self.hres)
        c = (sx + 1.0) * 0.5 * (hres + hres + self.pixel_gap)
        if c < hres:
            offset, shift = self.offset, self.shift
        elif c >= hres + self.pixel_gap:
            offset, shift = -self.offset, -self.shift
            c = c - (hres + self.pixel_gap)
        else:
            return blank_ray(self.eye, self.v)
        # The pinhole's u = sx' aspect / 2 for the view's own sx' = 2 c / hres - 1, plus the shift.
        u = (c / hres - 0.5) * self.aspect + shift
        w = sy * 0.5
        q = self.b1 * u + self.b2 * w + self.v * self.d
        return Ray(self.eye + self.b1 * offset, normalize(q))
