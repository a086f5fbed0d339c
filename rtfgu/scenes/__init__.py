"""Homework scenes, one function per image, and the SCENES registry (name -> function)."""
from .registry import SCENES, get_scene, homework
from . import lecture01, default_scene, suffern, sampling, textures, meshes, environment  # noqa: F401  (registers the scenes)
from . import suffern_textures  # noqa: F401  (registers the scenes)

__all__ = ["SCENES", "get_scene", "homework"]
