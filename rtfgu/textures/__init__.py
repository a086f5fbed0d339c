"""Textures (Suffern ch. 29-30, 02562 worksheet 3): a colour that varies over a surface."""
from .checker import Checker
from .image_texture import ImageTexture
from .texture import Texture

__all__ = ["Texture", "ImageTexture", "Checker"]
