"""ImageTexture: the colours of an image file on a surface (Suffern ch. 29, "Image
Textures"; 02562 worksheet 3, texture addressing and filtering).

The file is read with Pillow and its 8-bit sRGB values decoded to linear with the sRGB
transfer function (IEC 61966-2-1): c / 12.92 for c <= 0.04045, else ((c + 0.055) / 1.055)^2.4.
(u, v) = (0, 0) is the image's bottom-left corner and (1, 1) its top-right; texel (i, j)
(column i, row j from the top) has its centre at ((i + 0.5) / width, 1 - (j + 0.5) / height).

address  "repeat": u and v wrap around (u - floor(u)); "clamp": they stop at the edge texels.
filter   "nearest": the texel that holds (u, v); "bilinear": the four texels around it,
         weighted by distance (worksheet 3's two filters).
"""
from __future__ import annotations

import math
from pathlib import Path

from ..lazy_import import numpy as np

from ..float3 import Float3
from .texture import Texture

FILTERS = ("nearest", "bilinear")
ADDRESSES = ("repeat", "clamp")


def srgb_to_linear(c: np.ndarray) -> np.ndarray:
    """8-bit sRGB values / 255 to linear (the exact piecewise transfer function). The power is
    taken value by value with math.pow: numpy's vectorised power picks its code by the CPU's
    vector instructions and rounds the last bit differently from one machine to the next, so
    the same texture file would give other texels, and other images, on another machine."""
    c = np.asarray(c, dtype=np.float64)
    values, where = np.unique(c, return_inverse=True)
    linear = np.array([v / 12.92 if v <= 0.04045 else math.pow((v + 0.055) / 1.055, 2.4) for v in values.tolist()],
                      dtype=np.float64)
    return linear[where].reshape(c.shape)


def read_texture(path) -> np.ndarray:
    """The linear RGB texels (height, width, 3) of an image file, row 0 at the top; a
    ValueError naming the file if it is missing, not an image or has no pixels."""
    from PIL import Image, UnidentifiedImageError

    path = Path(path)
    if not path.is_file():
        raise ValueError("ImageTexture.path: no such file %s" % path)
    try:
        with Image.open(path) as image:
            rgb = np.asarray(image.convert("RGB"), dtype=np.float64) / 255.0
    except (UnidentifiedImageError, OSError, ValueError) as error:
        raise ValueError("ImageTexture.path: %s is not an image Pillow can read (%s)" % (path, error)) from None
    if rgb.size == 0:
        raise ValueError("ImageTexture.path: %s has no pixels (size %dx%d)" % (path, rgb.shape[1], rgb.shape[0]))
    return srgb_to_linear(rgb)


class ImageTexture(Texture):
    def __init__(self, path=None, filter: str = "bilinear", address: str = "repeat",
                 scale: float = 1.0, texels=None, mapping=None):
        """From the image file ``path``, or from ``texels`` (height, width, 3), linear.
        ``mapping``: a Mapping (Suffern ch. 29, the book's set_mapping) that gives (u, v)
        from the hit point; None: the shape's own (u, v)."""
        from ..mappings.mapping import Mapping

        super().__init__(scale)
        if mapping is not None and not isinstance(mapping, Mapping):
            raise ValueError("ImageTexture.mapping must be a Mapping (SphericalMap, CylindricalMap, "
                             "RectangularMap, LightProbe) or None, got %r" % (mapping,))
        self.mapping = mapping
        if filter not in FILTERS:
            raise ValueError("ImageTexture.filter must be one of %s, got %r" % (", ".join(FILTERS), filter))
        if address not in ADDRESSES:
            raise ValueError("ImageTexture.address must be one of %s, got %r" % (", ".join(ADDRESSES), address))
        if (path is None) == (texels is None):
            raise ValueError("ImageTexture: give either path or texels")
        if texels is None:
            texels = read_texture(path)
        texels = np.asarray(texels, dtype=np.float64)
        if texels.ndim != 3 or texels.shape[2] != 3 or texels.shape[0] < 1 or texels.shape[1] < 1:
            raise ValueError("ImageTexture.texels must have the shape (height >= 1, width >= 1, 3), got %s"
                             % (texels.shape,))
        if not np.all(np.isfinite(texels)):
            raise ValueError("ImageTexture.texels must be finite")
        self.path = path
        self.filter = filter
        self.address = address
        self.texels = texels
        self.height, self.width = texels.shape[:2]

    @property
    def uses_texcoord(self) -> bool:
        return self.mapping is None

    def texture_coordinates(self, shape, position: Float3) -> tuple:
        """The mapping's (u, v) of the hit point, or the shape's own without a mapping."""
        if self.mapping is None:
            return shape.texcoord(position)
        return self.mapping.get_texel_coordinates(position)

    def texel(self, i: int, j: int) -> Float3:
        """Texel column i, row j (from the top), addressed: wrapped or clamped."""
        # TODO a07: ImageTexture.texel
        #   Address the indices: "repeat" wraps them (i % width, j % height; Python's % by a positive
        #   width is never negative), "clamp" holds them at the edge (min(max(i, 0), width - 1), likewise j).
        #   Return Float3 of self.texels[j, i] (row j first: the array is (height, width, 3)).
        raise NotImplementedError('a07: ImageTexture.texel')

    def get_color(self, u: float, v: float) -> Float3:
        # TODO a07: ImageTexture.get_color
        #   Address (u, v): repeat u = u - floor(u) (likewise v); clamp u, v to [0, 1].
        #   To texel space: x = u * width, y = (1 - v) * height (row 0 is the top, v = 1).
        #   nearest: return texel(floor(x), floor(y)).
        #   bilinear: texel centres sit at whole numbers + 0.5, so x -= 0.5, y -= 0.5; i = floor(x),
        #   j = floor(y), fx = x - i, fy = y - j; mix texel(i, j) and texel(i + 1, j) by fx, likewise
        #   row j + 1, then the two rows by fy. texel does the addressing of i + 1 and j + 1.
        raise NotImplementedError('a07: ImageTexture.get_color')
