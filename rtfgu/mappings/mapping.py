"""Mapping: Suffern ch. 29's texture mapping, the texture coordinates of a point of the
object's own space (the book's local hit point) computed from the point alone, in place of
the shape's own (u, v) (``ImageTexture(..., mapping=...)``, the book's
``ImageTexture::set_mapping``).

The book's ``get_texel_coordinates(p, hres, vres, row, column)`` returns the texel
(int((vres - 1) v), int((hres - 1) u)); rtfgu's returns (u, v) in [0, 1]^2, and the image
texture's filter and address mode pick the texels from them as they do from a shape's
(u, v), so a mapped lookup is filtered like any other. The book's mappings take the object
to be about the origin with radius 1 (a unit sphere, a cylinder from y = -1 to 1, a square
from -1 to 1): a shape elsewhere or of another size is mapped through its position relative
to that, as the book's instances do.
"""
from __future__ import annotations

from abc import ABC, abstractmethod

from ..float3 import Float3


class Mapping(ABC):
    # The flat layout's name of the mapping (rtfgu.registry.MAPPING_IDS).
    name = ""

    @abstractmethod
    def get_texel_coordinates(self, p: Float3) -> tuple:
        """(u, v) of the point p; (0, 0) is the image's bottom-left corner."""
