"""Wood: Suffern ch. 31's wood, after Larry Gritz's RenderMan wood (Apodaca and Gritz 2000)
with the rings about the y axis (the book's Wood.cpp): the point is perturbed by the noise's
vector_fbm (ring_noise) and the trunk by its vector_noise along y (trunk_wobble); its
distance r from the axis times ring_frequency is perturbed around the rings
(angular_wobble) and along them (ring_uneveness) and run through a smooth pulse train of
period 1 (in_ring); two octaves of value_noise make the grain. The colour mixes light_color
and dark_color by mix(in_ring ringy, 1, grain).

The RenderMan helpers are the book's (Maths.cpp): smooth_step, smooth_pulse,
smooth_pulse_train with the book's mod, and mix. The book squares with pow(x, 2.0); here it
is x * x, the same number on every path.
"""
from __future__ import annotations

import math

from ..float3 import Float3
from ..noise.cubic_noise import CubicNoise
from ..validation import colour, number
from .noise_texture import NoiseTexture

# The book's defaults, in the order of its third constructor.
PARAMETERS = (("ring_frequency", 4.0), ("ring_uneveness", 0.25), ("ring_noise", 0.02),
              ("ring_noise_frequency", 1.0), ("trunk_wobble", 0.15), ("trunk_wobble_frequency", 0.025),
              ("angular_wobble", 0.5), ("angular_wobble_frequency", 1.0), ("grain_frequency", 25.0),
              ("grainy", 0.5), ("ringy", 0.5))


def smooth_step(a: float, b: float, x: float) -> float:
    if x < a:
        return 0.0
    if x >= b:
        return 1.0
    y = (x - a) / (b - a)
    return y * y * (3.0 - 2.0 * y)


def book_mod(a: float, b: float) -> float:
    """The book's mod: a - int(a / b) b, moved into [0, b)."""
    n = int(a / b)
    a -= n * b
    if a < 0.0:
        a += b
    return a


def smooth_pulse_train(e0: float, e1: float, e2: float, e3: float, period: float, x: float) -> float:
    x = book_mod(x, period)
    return smooth_step(e0, e1, x) - smooth_step(e2, e3, x)


def mix(a: float, b: float, f: float) -> float:
    return (1.0 - f) * a + f * b


class Wood(NoiseTexture):
    uses_vector_noise = True

    def __init__(self, light_color=Float3(1.0), dark_color=Float3(0.0), noise=None, scale: float = 1.0,
                 **parameters):
        super().__init__(CubicNoise(2, 4.0, 0.5) if noise is None else noise, scale)
        self.light_color = colour(light_color, "Wood.light_color")
        self.dark_color = colour(dark_color, "Wood.dark_color")
        unknown = set(parameters) - {name for name, _ in PARAMETERS}
        if unknown:
            raise ValueError("Wood has no parameter %s (known: %s)"
                             % (", ".join(sorted(unknown)), ", ".join(name for name, _ in PARAMETERS)))
        for name, default in PARAMETERS:
            setattr(self, name, number(parameters.get(name, default), "Wood." + name))

    def get_color(self, p: Float3) -> Float3:
        noise = self.noise
        # perturb the hit point, then the trunk, so that it is not exactly along the y axis
        offset = noise.vector_fbm(p * self.ring_noise_frequency)
        ring_point = p + offset * self.ring_noise
        wobble = noise.vector_noise(Float3(0.0, 0.0, p.y * self.trunk_wobble_frequency)) * self.trunk_wobble
        rx = ring_point.x + wobble.x
        ry = ring_point.y
        rz = ring_point.z + wobble.z
        r = math.sqrt(rx * rx + rz * rz) * self.ring_frequency
        # rings not quite round, unequally spaced and of different thicknesses
        f = self.angular_wobble_frequency
        r += self.angular_wobble * smooth_step(0.0, 5.0, r) * noise.value_noise(Float3(f * rx, f * ry * 0.1, f * rz))
        r += self.ring_uneveness * noise.value_noise(Float3(r, r, r))
        in_ring = smooth_pulse_train(0.1, 0.55, 0.7, 0.95, 1.0, r)
        # the grain
        gx = p.x * self.grain_frequency
        gy = p.y * self.grain_frequency * 0.05
        gz = p.z * self.grain_frequency
        dpgrain = 0.2
        grain = 0.0
        amplitude = 1.0
        for i in range(2):
            grain_valid = 1.0 - smooth_step(0.2, 0.6, dpgrain)
            if grain_valid > 0.0:
                g = grain_valid * noise.value_noise(Float3(gx, gy, gz))
                g *= 0.3 + 0.7 * in_ring
                g = min(max(0.8 - g, 0.0), 1.0)
                g = self.grainy * smooth_step(0.5, 1.0, g * g)
                if i == 0:
                    in_ring *= 1.0 - 0.4 * grain_valid
                grain = amplitude * max(grain, g)
            gx = 2.0 * gx
            gy = 2.0 * gy
            gz = 2.0 * gz
            dpgrain *= 2.0
            amplitude *= 0.5
        final_value = mix(in_ring * self.ringy, 1.0, grain)
        return self.light_color * (1.0 - final_value) + self.dark_color * final_value
