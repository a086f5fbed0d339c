"""What Suffern's part objects share (ch. 19, "Part objects"): the range of angles a part
keeps of its whole shape, given in degrees and kept in radians as the book's constructors
do (``phi_min = azimuth_min * PI_ON_180``), and the azimuth of a point about the y axis.

The azimuth is the book's phi = atan2(x, z), moved into [0, 2 pi): 0 on +z, 90 degrees on
+x. The polar angle theta is measured from +y (0 at the top, 180 at the bottom).
"""
from __future__ import annotations

import math

from ..float3 import Float3

TWO_PI = 2.0 * math.pi
PI_ON_180 = math.pi / 180.0


def angle_range(low, high, top: float, low_name: str, high_name: str) -> tuple:
    """(low, high) in radians, for angles in degrees with 0 <= low < high <= top: a
    ValueError naming the field otherwise."""
    values = []
    for value, name in ((low, low_name), (high, high_name)):
        try:
            ok = not isinstance(value, bool) and math.isfinite(value) and 0.0 <= value <= top
        except TypeError:
            ok = False
        if not ok:
            raise ValueError("%s must be an angle in degrees within [0, %g], got %r" % (name, top, value))
        values.append(float(value))
    if not values[0] < values[1]:
        raise ValueError("%s must be below %s, got %r and %r" % (low_name, high_name, low, high))
    return values[0] * PI_ON_180, values[1] * PI_ON_180


def azimuth(p: Float3) -> float:
    """The book's phi of a point p relative to the axis: atan2(x, z) in [0, 2 pi)."""
    phi = math.atan2(p.x, p.z)
    if phi < 0.0:
        phi += TWO_PI
    return phi
