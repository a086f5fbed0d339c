"""Emissive: a surface that only emits, L_e = ls ce, and reflects nothing (Suffern ch. 18,
"Emissive"); the shape of an ``AreaLight`` (rtfgu/lights/area_light.py). The ray-cast
tracers show L_e on both sides (as the 02562 ``emissive`` shader); PathTrace counts it from
the front only (the side the normal points to), as the area light emits."""
from __future__ import annotations

from ..float3 import Float3
from ..validation import colour, number
from .material import EMISSIVE, Material, PathVertex


class Emissive(Material):
    shader = EMISSIVE

    def __init__(self, ls: float = 1.0, ce=(1.0, 1.0, 1.0)):
        self.ls, self.ce = number(ls, "Emissive.ls"), colour(ce, "Emissive.ce")

    def set_ls(self, ls: float) -> None:
        self.ls = number(ls, "Emissive.ls")

    def set_ce(self, ce) -> None:
        self.ce = colour(ce, "Emissive.ce")

    @property
    def emission(self) -> Float3:
        """L_e = ls ce."""
        return self.ce * self.ls

    def shade(self, sr) -> Float3:
        return self.get_Le(sr)

    def path_shade(self, sr) -> PathVertex:
        return PathVertex(None)

    def __repr__(self) -> str:
        return "Emissive(%r, %r)" % (self.ls, self.ce)
