from .plane import Plane
from .shape import Shape
from .sphere import Sphere
from .triangle import Triangle

__all__ = ["Shape", "Plane", "Sphere", "Triangle"]
