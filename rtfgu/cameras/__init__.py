from .camera import Camera
from .fish_eye import FishEye
from .orthographic import OrthographicCamera
from .pinhole import PinholeCamera
from .spherical import Spherical
from .stereo_camera import StereoCamera
from .thin_lens import ThinLens

__all__ = ["Camera", "FishEye", "OrthographicCamera", "PinholeCamera", "Spherical", "StereoCamera", "ThinLens"]
