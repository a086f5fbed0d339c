"""FBmTexture: Suffern ch. 31's fractional Brownian motion texture: the noise's value_fbm at
the point, mapped from [0, 1] to [min_value, max_value], times ``color``; a value outside
[0, 1] shows red, as the book's FBmTexture::get_color does, so a bad range is seen."""
from __future__ import annotations

from ..float3 import Float3
from ..validation import colour, number
from .noise_texture import NoiseTexture

OUT_OF_RANGE = Float3(1.0, 0.0, 0.0)


class FBmTexture(NoiseTexture):
    def __init__(self, noise, color=Float3(1.0), min_value: float = 0.0, max_value: float = 1.0,
                 scale: float = 1.0):
        super().__init__(noise, scale)
        self.color = colour(color, "FBmTexture.color")
        self.min_value = number(min_value, "FBmTexture.min_value")
        self.max_value = number(max_value, "FBmTexture.max_value")

    def get_color(self, p: Float3) -> Float3:
        value = self.noise.value_fbm(p)
        value = self.min_value + (self.max_value - self.min_value) * value
        if value < 0.0 or value > 1.0:
            return OUT_OF_RANGE
        return self.color * value
