from .camera import Camera
from .orthographic import OrthographicCamera
from .pinhole import PinholeCamera
from .thin_lens import ThinLens

__all__ = ["Camera", "OrthographicCamera", "PinholeCamera", "ThinLens"]
