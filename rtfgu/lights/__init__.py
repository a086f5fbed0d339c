"""The lights (Suffern ch. 14, 17, 18): one class per file, all with the book's Light
interface (rtfgu/lights/light.py)."""
from .ambient import Ambient
from .ambient_occluder import AmbientOccluder
from .area_light import AreaLight
from .directional import Directional
from .environment_light import EnvironmentLight, read_exr, read_image
from .rgbe import read_hdr
from .light import Light, LightSample
from .point_light import PointLight

__all__ = ["Light", "LightSample", "Ambient", "PointLight", "Directional", "AreaLight", "AmbientOccluder",
           "EnvironmentLight", "read_exr", "read_hdr", "read_image"]
