"""ThickRing: a ring about the y axis between the heights ``bottom`` and ``top`` and the radii
``inner_radius`` and ``outer_radius``, a Compound of two OpenCylinders (the inner and the
outer wall) and two Annuli (the bottom one facing -y, the top one +y) (Suffern ch. 19,
"Compound objects", exercise). The book's walls are a concave and a convex cylinder; rtfgu's
OpenCylinder turns its normal toward the ray, so it serves as either.
"""
from __future__ import annotations

from ..float3 import Float3
from .annulus import Annulus
from .compound import Compound
from .open_cylinder import OpenCylinder


class ThickRing(Compound):
    def __init__(self, bottom: float, top: float, inner_radius: float, outer_radius: float, color, material=None):
        super().__init__()
        try:   # the walls and rims check the numbers, under the ring's names
            inner = OpenCylinder(bottom, top, inner_radius, color, material)
            outer = OpenCylinder(bottom, top, outer_radius, color, material)
            rims = [Annulus(Float3(0.0, y, 0.0), Float3(0.0, sign, 0.0), inner.radius, outer.radius, color, material)
                    for y, sign in ((inner.y0, -1.0), (inner.y1, 1.0))]
        except ValueError as error:
            message = str(error)
            for old, new in (("OpenCylinder.y0", "ThickRing.bottom"), ("OpenCylinder.y1", "ThickRing.top"),
                             ("Annulus.inner_radius", "ThickRing.inner_radius"),
                             ("Annulus.outer_radius", "ThickRing.outer_radius")):
                message = message.replace(old, new)
            if "OpenCylinder.radius" in message:
                message = "ThickRing.inner_radius and ThickRing.outer_radius must be finite and > 0, got %r and %r" \
                    % (inner_radius, outer_radius)
            raise ValueError(message) from None
        self.add_object(inner)
        self.add_object(outer)
        for rim in rims:
            self.add_object(rim)
