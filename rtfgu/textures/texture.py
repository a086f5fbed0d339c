"""Texture: a colour that varies over a surface (Suffern ch. 29, "Textures").

``get_color(u, v)`` is the colour at texture coordinates (u, v); the shape hit gives them
(``Shape.texcoord(position)``, after Suffern's mappings and 02562 worksheet 3), and
``scale`` multiplies them first (worksheet 3's plane uses 0.2). A shape whose material has a
texture takes the texture's colour in place of its own ``color``; nothing else in shading
changes. Colours are linear, as every colour in rtfgu.
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

    def color_at(self, u: float, v: float) -> Float3:
        """The colour at the shape's texture coordinates (u, v): get_color of (u, v) * scale."""
        return self.get_color(u * self.scale, v * self.scale)

    @abstractmethod
    def get_color(self, u: float, v: float) -> Float3:
        """The linear colour at (u, v); the texture repeats or clamps outside [0, 1)."""
