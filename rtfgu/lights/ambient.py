"""Ambient: light that arrives equally from everywhere and casts no shadows (Suffern ch. 14,
"Ambient Illumination"). A scene has one (``Scene.ambient_light``); a material's ambient
term is its ambient BRDF's albedo times ``L(sr) = ls cl``. The 02562 default scene's
"L_a = 10 % of the object's colour" is ``Ambient()`` (ls 1, white) with a ``Matte`` of
``ka = 0.1``."""
from __future__ import annotations

from ..float3 import Float3
from .light import Light


class Ambient(Light):
    shadows = False

    def __init__(self, ls: float = 1.0, color=(1.0, 1.0, 1.0)):
        self.set_ls(ls)
        self.set_color(color)

    def get_direction(self, sr) -> Float3:
        return Float3(0.0)

    def L(self, sr) -> Float3:
        return self.intensity

    def __repr__(self) -> str:
        return "Ambient(%r, %r)" % (self.ls, self.color)
