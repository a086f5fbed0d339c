"""What a ray that leaves the scene sees, on the numba path: rtfgu.Scene.background_radiance,
the EnvironmentLight's lat-long lookup (rtfgu/lights/environment_light.py) or the background."""
from __future__ import annotations

import math

from numba import njit, types
from numba.extending import overload

from ..registry import TEXTURES
from .dispatch_support import as_python
from .float3 import lit, load3

# The places of the environment and of each shape's material row in the kernels' ``scene``
# tuple (rtfgu.kernels.render.scene_tuple).
ENVIRONMENT = 4 + len(TEXTURES)
MATERIAL_OF = ENVIRONMENT + 1


@njit(cache=True, error_model="numpy")
def environment_radiance(image, direction):
    """EnvironmentLight.radiance: the nearest texel at u = 1/2 + atan2(x, -z) / (2 pi),
    v = acos(y) / pi."""
    x, y, z = direction
    one = lit(1.0, x)
    u = lit(0.5, x) + math.atan2(x, -z) / lit(2.0 * math.pi, x)
    v = math.acos(min(one, max(-one, y))) / lit(math.pi, x)
    height, width = image.shape[0], image.shape[1]
    column = min(int(u * lit(width, x)), width - 1)
    row = min(int(v * lit(height, x)), height - 1)
    return image[row, column, 0], image[row, column, 1], image[row, column, 2]


def background_radiance(environment, background, direction):
    """The environment's radiance along ``direction``, or the background without one: None
    (typed by the overload below, so a scene without an environment compiles none of it),
    or an empty image (the pixel debugger's, rtfgu.kernels.render.scene_tuple)."""
    return as_python(_typed_background_radiance, environment, background, direction)


@overload(background_radiance, inline="always")
def _typed_background_radiance(environment, background, direction):
    if isinstance(environment, types.NoneType):
        return lambda environment, background, direction: load3(background, 0)

    def lookup(environment, background, direction):
        if environment.shape[0] == 0:
            return load3(background, 0)
        return environment_radiance(environment, direction)
    return lookup
