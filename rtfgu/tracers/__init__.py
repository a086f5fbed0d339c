"""The tracers (Suffern ch. 3, 14, 18, 24, 26): how a ray becomes a colour."""
from .area_lighting import AreaLighting
from .global_trace import GlobalTrace
from .path_trace import MAX_AREA_LIGHTS, MAX_PATH_DEPTH, PathTrace
from .ray_cast import RayCast
from .tracer import Tracer
from .whitted import MAX_DEPTH, Whitted

__all__ = ["Tracer", "RayCast", "Whitted", "AreaLighting", "PathTrace", "GlobalTrace", "MAX_DEPTH",
           "MAX_PATH_DEPTH", "MAX_AREA_LIGHTS"]
