"""Textures (Suffern ch. 29-31, 02562 worksheet 3): a colour that varies over a surface."""
from .checker import Checker
from .checker3d import Checker3D
from .image_texture import ImageTexture
from .solid_texture import SolidTexture
from .texture import Texture

__all__ = ["Texture", "SolidTexture", "ImageTexture", "Checker", "Checker3D"]
