"""FlatRimmedBowl: a hemispherical bowl with a flat rim, a Compound of three part objects
(Suffern ch. 19, "Part objects"): the outside, a ConvexPartSphere of ``outer_radius``; the
inside, a ConcavePartSphere of ``inner_radius``, both the lower half (polar angles 90 to 180
degrees, every azimuth); and the rim between them, an Annulus facing +y.

The book's bowl sits at the origin (an Instance moves it); this one takes its ``center``.
"""
from __future__ import annotations

from ..float3 import Float3, as_float3
from .annulus import Annulus
from .compound import Compound
from .concave_part_sphere import ConcavePartSphere
from .convex_part_sphere import ConvexPartSphere


class FlatRimmedBowl(Compound):
    def __init__(self, center, inner_radius: float, outer_radius: float, color, material=None):
        super().__init__()
        center = as_float3(center, "FlatRimmedBowl.center")
        # The annulus checks 0 <= inner_radius < outer_radius, under the bowl's names.
        try:
            rim = Annulus(center, Float3(0.0, 1.0, 0.0), inner_radius, outer_radius, color, material)
        except ValueError as error:
            raise ValueError(str(error).replace("Annulus.", "FlatRimmedBowl.")) from None
        if rim.inner_radius == 0.0:
            raise ValueError("FlatRimmedBowl.inner_radius must be finite and > 0, got %r" % (inner_radius,))
        self.add_object(ConvexPartSphere(center, rim.outer_radius, 0.0, 360.0, 90.0, 180.0, color, material))
        self.add_object(ConcavePartSphere(center, rim.inner_radius, 0.0, 360.0, 90.0, 180.0, color, material))
        self.add_object(rim)
