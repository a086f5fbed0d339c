"""SolidTexture: a texture in space (Suffern ch. 30, "3D textures", and ch. 31, noise): its
colour is a function of the hit point, the book's ``sr.local_hit_point``, not of the shape's
texture coordinates, so it carves the colour out of a block of material whatever the shape.

``get_color(p)`` is the colour at the point p = position * ``scale``: ``scale`` shrinks
(> 1) or stretches (< 1) the pattern, as an instance's scaling does for the book's solid
textures.
"""
from __future__ import annotations

from abc import abstractmethod

from ..float3 import Float3
from .texture import Texture


class SolidTexture(Texture):
    @property
    def uses_texcoord(self) -> bool:
        return False

    def color_at(self, shape, position: Float3) -> Float3:
        return self.get_color(position * self.scale)

    @abstractmethod
    def get_color(self, p: Float3) -> Float3:
        """The linear colour at the point p."""
