"""The checks of the lecture layer's arguments. Each returns the value in the type the class
keeps, or raises a ValueError that names the field it checked ("Sphere.radius",
"Matte.kd"), so that bad input is refused where it is given, not found later as NaN pixels.
"""
from __future__ import annotations

import math

from .float3 import Float3, as_float3


def number(value, name: str, positive: bool = False) -> float:
    """``value`` as a float: finite and >= 0 (a coefficient, a radiance scale, an exponent),
    or > 0 with ``positive`` (a radius, an index of refraction)."""
    try:
        ok = not isinstance(value, bool) and math.isfinite(value) and (value > 0 if positive else value >= 0)
    except TypeError:
        ok = False
    if not ok:
        raise ValueError("%s must be finite and %s 0, got %r" % (name, ">" if positive else ">=", value))
    return float(value)


def finite(value, name: str) -> float:
    """``value`` as a float if it is a finite number of either sign (a height, a translation,
    an angle)."""
    try:
        ok = not isinstance(value, bool) and math.isfinite(value)
    except TypeError:
        ok = False
    if not ok:
        raise ValueError("%s must be a finite number, got %r" % (name, value))
    return float(value)


def positive(value, name: str) -> float:
    """``value`` as a float if it is finite and > 0."""
    return number(value, name, positive=True)


def colour(value, name: str, surface: bool = False):
    """``value`` as a Float3 with every component finite and >= 0 (a colour, a radiance, an
    absorption coefficient). With ``surface``, also None (the shape's colour at the hit) or a
    Texture (its colour there), a surface's colour ``cd``."""
    from .textures.texture import Texture

    if surface and (value is None or isinstance(value, Texture)):
        return value
    if isinstance(value, str):
        raise ValueError("%s must be %sthree numbers, got %r"
                         % (name, "a Texture, None or " if surface else "", value))
    c = as_float3(value, name)
    if min(c.x, c.y, c.z) < 0.0:
        raise ValueError("%s must be finite and >= 0 in every component, got %r" % (name, c))
    return c


def nonzero_vector(value, name: str) -> Float3:
    """``value`` as a finite, non-zero Float3 (a normal, a direction)."""
    value = as_float3(value, name)
    if value.length_squared() == 0.0:
        raise ValueError("%s must be non-zero" % name)
    return value
