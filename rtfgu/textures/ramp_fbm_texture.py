"""RampFBmTexture: Suffern ch. 31's marble: the height y of the point, perturbed by the
noise's value_fbm, runs through a ramp of colours as u = (1 + sin(y + perturbation fbm)) / 2
(RampFBmTexture::get_color2), the ramp's entry int(u (n - 1)).

The book reads the ramp from the top row of an image file; ``ramp`` here is either such a
file (read as ImageTexture reads one, decoded to linear colour) or a list of colours.
"""
from __future__ import annotations

import math

from ..lazy_import import numpy as np

from ..float3 import Float3, as_float3
from ..validation import number
from .image_texture import read_texture
from .noise_texture import NoiseTexture


class RampFBmTexture(NoiseTexture):
    def __init__(self, noise, ramp, perturbation: float = 3.0, scale: float = 1.0):
        super().__init__(noise, scale)
        if isinstance(ramp, (str, bytes)) or hasattr(ramp, "__fspath__"):
            try:
                texels = read_texture(ramp)
            except ValueError as error:
                raise ValueError(str(error).replace("ImageTexture.path", "RampFBmTexture.ramp")) from None
            colours = [Float3(*map(float, texels[0, i])) for i in range(texels.shape[1])]
        else:
            try:
                colours = [as_float3(c, "RampFBmTexture.ramp[%d]" % i) for i, c in enumerate(ramp)]
            except TypeError:
                raise ValueError("RampFBmTexture.ramp must be an image file or a list of colours, got %r"
                                 % (ramp,)) from None
            if not colours:
                raise ValueError("RampFBmTexture.ramp must hold at least one colour")
        self.ramp = colours
        self.perturbation = number(perturbation, "RampFBmTexture.perturbation")

    @property
    def texels(self) -> np.ndarray:
        """The ramp as a one-row image (1, n, 3), for the flat layout's texels."""
        return np.array([[(c.x, c.y, c.z) for c in self.ramp]], dtype=np.float64)

    def get_color(self, p: Float3) -> Float3:
        noise = self.noise.value_fbm(p)
        y = p.y + self.perturbation * noise
        u = (1.0 + math.sin(y)) / 2.0
        return self.ramp[int(u * (len(self.ramp) - 1))]
