"""Texture: a colour that varies over a surface (Suffern ch. 29, "Textures").

``color_at(shape, position)`` is the book's ``Texture::get_color(const ShadeRec& sr)``: the
colour at the hit point ``position`` (the book's ``sr.local_hit_point``) on ``shape``. A
texture in texture space (``ImageTexture``, ``Checker``) reads the shape's texture
coordinates there (the book's ``sr.u``, ``sr.v``: ``Shape.texcoord(position)``, after
Suffern's mappings and 02562 worksheet 3), multiplies them by ``scale`` (worksheet 3's plane
uses 0.2) and looks them up with ``get_color(u, v)``; a solid texture (``SolidTexture``:
``Checker3D``, the noise textures, ``Wood``) reads the point itself. A shape whose material
has a texture takes the texture's colour in place of its own ``color``; nothing else in
shading changes. Colours are linear, as every colour in rtfgu.
"""
from __future__ import annotations

import math
from abc import ABC, abstractmethod

from ..float3 import Float3


class Texture(ABC):
    def __init__(self, scale: float = 1.0):
        if isinstance(scale, bool) or not isinstance(scale, (int, float)) or not (
                math.isfinite(scale) and scale > 0):
            raise ValueError("%s.scale must be finite and > 0, got %r" % (type(self).__name__, scale))
        self.scale = float(scale)

    @property
    def uses_texcoord(self) -> bool:
        """Does the colour depend on the shape's (u, v)? (The flat paths compute them only then.)"""
        return True

    def texture_coordinates(self, shape, position: Float3) -> tuple:
        """(u, v) at ``position`` on ``shape``, before ``scale``: the shape's own."""
        return shape.texcoord(position)

    def color_at(self, shape, position: Float3) -> Float3:
        """The book's get_color(sr): get_color of the texture coordinates times ``scale``."""
        u, v = self.texture_coordinates(shape, position)
        return self.get_color(u * self.scale, v * self.scale)

    @abstractmethod
    def get_color(self, u: float, v: float) -> Float3:
        """The linear colour at (u, v); the texture repeats or clamps outside [0, 1)."""
