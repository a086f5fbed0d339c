"""Light: where light comes from (Suffern ch. 14, "Lights"; 02562, "Sampling light in the
shader").

The book's interface, which a material's light loop asks at a hit ``sr``:

* ``get_direction(sr)``: the unit direction w_i from the hit toward the light (a point of
  an area light is drawn here, as in the book);
* ``L(sr)``: the incident radiance arriving along it (the 02562 point light's Kepler law,
  I / d^2, is here);
* ``G(sr)`` and ``pdf(sr)``: an area light's geometry factor and the density of the point
  drawn (1 for every other light), so that ``L G / pdf`` is the estimate of the light;
* ``distance(sr)``: how far the shadow ray toward it may go (infinite for light from far
  away);
* ``in_shadow(ray, sr)``: whether a shape blocks the shadow ray before the light;
* ``casts_shadows()``: whether the light is tested for shadows at all (``set_shadows``;
  02562 week 2 renders the default scene without, then with them).

The slide's record ``struct Light { L_i, w_i, dist }`` is ``LightSample``: the three
numbers the WGSL and numba light functions return for one light at one point.
"""
from __future__ import annotations

from typing import NamedTuple

from ..float3 import Float3
from ..ray import SPAWN_EPSILON
from ..validation import colour, number


class LightSample(NamedTuple):
    """The slide's ``struct Light``: incident radiance, unit direction toward the light, and
    the distance to it."""
    L_i: Float3
    w_i: Float3
    dist: float


class Light:
    shadows = True
    sampler = None
    # The book's radiance scale and colour; their product ls cl is the light's ``intensity``
    # (its radiance, for Ambient and AmbientOccluder), kept up to date by the setters.
    ls = 1.0
    color = intensity = Float3(1.0)

    def set_ls(self, ls: float) -> None:
        self.ls = number(ls, type(self).__name__ + ".ls")
        self.intensity = self.color * self.ls

    def set_color(self, color) -> None:
        self.color = colour(color, type(self).__name__ + ".color")
        self.intensity = self.color * self.ls

    drawn_by_ray_casting = True     # RayCast, Whitted and AreaLighting can ask it
    def set_sampler(self, sampler) -> None:
        """The book's ``set_sampler``, for a light that draws points or directions (an
        AreaLight, an AmbientOccluder): they come from this sampler's sets instead of the
        random stream."""
        from ..sampling.sobol import check_own_sampler

        self.sampler = check_own_sampler(type(self).__name__, sampler)

    def set_shadows(self, shadows: bool) -> None:
        self.shadows = bool(shadows)

    def flat_limit(self):
        """None if the numba and WGSL paths take this light as the lecture layer does; else
        why not."""
        return None

    def casts_shadows(self) -> bool:
        return self.shadows

    def get_direction(self, sr) -> Float3:
        raise NotImplementedError

    def L(self, sr) -> Float3:
        raise NotImplementedError

    def G(self, sr) -> float:
        return 1.0

    def pdf(self, sr) -> float:
        return 1.0

    def distance(self, sr) -> float:
        """How far the light is: infinitely far unless the light says otherwise."""
        return float("inf")

    def incident(self, sr) -> Float3:
        """L G / pdf, the light's estimate of the radiance arriving along the direction
        ``get_direction`` gave."""
        return self.L(sr) * (self.G(sr) / self.pdf(sr))

    def in_shadow(self, ray, sr) -> bool:
        """The shadow ray ``ray`` (from the hit toward the light): is any shape of the scene hit
        between the surface and the light? The ray's interval is set here: it starts
        SPAWN_EPSILON off the surface and ends SPAWN_EPSILON before the light."""
        # TODO a05: Light.in_shadow
        #   Set ray.tmin = SPAWN_EPSILON and ray.tmax = self.distance(sr) - SPAWN_EPSILON, then return True if
        #   any shape of sr.scene.shapes hits the ray. The offsets keep the ray from hitting the surface it
        #   leaves (shadow acne) and from hitting the light's own position.
        raise NotImplementedError('a05: Light.in_shadow')

    def sample(self, pos: Float3) -> LightSample:
        """The slide's light sample at ``pos`` (the flat paths' ``sample_<light>``): for the
        lights that need no hit but its position."""
        from ..hit_info import HitInfo

        sr = HitInfo()
        sr.position = pos
        w_i = self.get_direction(sr)
        return LightSample(self.L(sr), w_i, self.distance(sr))
