"""EnvironmentLight: light from every direction, from a latitude-longitude image (Suffern ch. 18,
"Environment Light"; 02562 worksheet 9, "Environment mapping").

Set ``scene.environment = EnvironmentLight(image)``: a ray that leaves the scene sees the
image's radiance in its direction instead of ``scene.background``, under every tracer
(PathTrace's diffuse bounces then gather it). It is not yet drawn as a light of its own
(no importance sampling of the image): bounces find it. The image is linear
radiance, (height, width, 3), row 0 at the top; direction d = (x, y, z) with +y up is
looked up as in worksheet 9:

    u = 1/2 + atan2(x, -z) / (2 pi),   v = acos(y) / pi,

the texel (floor(u W), floor(v H)) (the nearest, clamped to the image): -z is the middle
of the image, +y its top row.

``image`` is an array or the path of an image of linear radiance, read by the reader its
suffix names (in any case):

* ``.exr``: OpenEXR, read with the Academy Software Foundation's OpenEXR bindings (the
  ``OpenEXR`` package: the format's own reference library, which keeps half and float
  radiance as it is, where 8-bit image readers clip it);
* ``.hdr``, ``.pic``: a Radiance RGBE picture, the format of worksheet 9's environment
  maps, read by rtfgu's ``read_hdr`` (rtfgu/lights/rgbe.py says why its own).
"""
from __future__ import annotations

import math
import os
from pathlib import Path

from ..lazy_import import numpy as np

from ..float3 import Float3
from .light import Light
from .rgbe import read_hdr


class EnvironmentLight(Light):
    def __init__(self, image, scale: float = 1.0):
        source = "EnvironmentLight.image"
        if isinstance(image, (str, os.PathLike)):
            source = "EnvironmentLight.image %s" % os.fspath(image)
            image = read_image(image)
        try:
            texels = np.array(image, dtype=np.float64)
        except (TypeError, ValueError):
            raise ValueError("%s must be an array of radiance (height, width, 3), got %r"
                             % (source, type(image).__name__)) from None
        if texels.ndim != 3 or texels.shape[2] != 3 or texels.shape[0] < 1 or texels.shape[1] < 1:
            raise ValueError("%s must be (height, width, 3) radiance, got shape %s" % (source, texels.shape))
        if not np.all(np.isfinite(texels)) or texels.min() < 0.0:
            bad = np.argwhere(~np.isfinite(texels) | (texels < 0.0))[0]
            raise ValueError("%s: texel (row %d, column %d) is %r, radiance must be finite and >= 0"
                             % (source, bad[0], bad[1], float(texels[bad[0], bad[1], bad[2]])))
        if not (math.isfinite(scale) and scale >= 0):
            raise ValueError("EnvironmentLight.scale must be finite and >= 0, got %r" % (scale,))
        self.texels = texels * float(scale)
        self.height, self.width = texels.shape[:2]

    def radiance(self, direction: Float3) -> Float3:
        """The radiance arriving from ``direction`` (a unit vector toward the environment)."""
        u = 0.5 + math.atan2(direction.x, -direction.z) / (2.0 * math.pi)
        v = math.acos(min(1.0, max(-1.0, direction.y))) / math.pi
        column = min(int(u * self.width), self.width - 1)
        row = min(int(v * self.height), self.height - 1)
        return Float3(*(float(c) for c in self.texels[row, column]))


def read_exr(path) -> np.ndarray:
    """The RGB channels of an OpenEXR file as (height, width, 3) float32; a ValueError naming
    the file when it is missing or not an OpenEXR image with R, G and B."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise ValueError("EnvironmentLight.image %s: no such file" % path)
    import OpenEXR

    try:
        with OpenEXR.File(path) as f:
            channels = f.channels()
            if "RGB" in channels:
                rgb = np.asarray(channels["RGB"].pixels)
            elif "RGBA" in channels:
                rgb = np.asarray(channels["RGBA"].pixels)[..., :3]
            elif all(c in channels for c in "RGB"):
                rgb = np.stack([np.asarray(channels[c].pixels) for c in "RGB"], axis=-1)
            else:
                raise ValueError("EnvironmentLight.image %s: an OpenEXR image without R, G and B channels "
                                 "(it has %s)" % (path, ", ".join(sorted(channels))))
    except RuntimeError as error:
        raise ValueError("EnvironmentLight.image %s is not an OpenEXR image (%s)" % (path, error)) from None
    return rgb.astype(np.float32)


# The image readers by suffix (lower case).
READERS = {".exr": read_exr, ".hdr": read_hdr, ".pic": read_hdr}


def read_image(path) -> np.ndarray:
    """The radiance of the image ``path`` (height, width, 3), read by the reader its suffix
    names; a ValueError naming the file and the suffix when there is none."""
    suffix = Path(path).suffix
    reader = READERS.get(suffix.lower())
    if reader is None:
        raise ValueError("EnvironmentLight.image %s: unknown image suffix %r: it reads .exr (OpenEXR) "
                         "and .hdr or .pic (Radiance RGBE)" % (os.fspath(path), suffix))
    return reader(path)
