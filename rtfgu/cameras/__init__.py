from .camera import Camera
from .orthographic import OrthographicCamera
from .pinhole import PinholeCamera

__all__ = ["Camera", "OrthographicCamera", "PinholeCamera"]
