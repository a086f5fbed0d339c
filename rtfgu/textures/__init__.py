"""Textures (Suffern ch. 29-31, 02562 worksheet 3): a colour that varies over a surface."""
from .checker import Checker
from .checker3d import Checker3D
from .fbm_texture import FBmTexture
from .image_texture import ImageTexture
from .noise_texture import NoiseTexture
from .ramp_fbm_texture import RampFBmTexture
from .solid_texture import SolidTexture
from .texture import Texture
from .wood import Wood
from .wrapped_fbm_texture import WrappedFBmTexture

__all__ = ["Texture", "SolidTexture", "NoiseTexture", "ImageTexture", "Checker", "Checker3D", "FBmTexture",
           "WrappedFBmTexture", "RampFBmTexture", "Wood"]
