"""Mappings (Suffern ch. 29): texture coordinates computed from the hit point."""
from .cylindrical_map import CylindricalMap
from .light_probe import LightProbe
from .mapping import Mapping
from .rectangular_map import RectangularMap
from .spherical_map import SphericalMap

__all__ = ["Mapping", "SphericalMap", "CylindricalMap", "RectangularMap", "LightProbe"]
