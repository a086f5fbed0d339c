"""WrappedFBmTexture: Suffern ch. 31's wrapped noise: expansion_number times the noise's
value_fbm, its fractional part mapped to [min_value, max_value], times ``color``
(WrappedFBmTexture::get_color); the wrap turns the smooth noise into bands."""
from __future__ import annotations

import math

from ..float3 import Float3
from ..validation import colour, number, positive
from .noise_texture import NoiseTexture


class WrappedFBmTexture(NoiseTexture):
    def __init__(self, noise, color=Float3(1.0), min_value: float = 0.0, max_value: float = 1.0,
                 expansion_number: float = 2.0, scale: float = 1.0):
        super().__init__(noise, scale)
        self.color = colour(color, "WrappedFBmTexture.color")
        self.min_value = number(min_value, "WrappedFBmTexture.min_value")
        self.max_value = number(max_value, "WrappedFBmTexture.max_value")
        self.expansion_number = positive(expansion_number, "WrappedFBmTexture.expansion_number")

    def get_color(self, p: Float3) -> Float3:
        noise = self.expansion_number * self.noise.value_fbm(p)
        value = noise - math.floor(noise)
        value = self.min_value + (self.max_value - self.min_value) * value
        return self.color * value
