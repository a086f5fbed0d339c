"""Float3: the three-component vector of lecture 01 ("Float3 Structure" slides).

The C++ struct keeps ``float d[3]`` in a union with the named views ``x, y, z``,
``r, g, b``, ``s, t, u`` and ``alpha, beta, gamma``. Python has no unions, so the
aliases are properties over the same three slots: writing ``v.r`` writes ``v.x``.

``*`` is componentwise (or by a scalar on either side), exactly as on the slide;
the dot and cross products are the named functions ``dot`` and ``cross``.
"""
from __future__ import annotations

import math


class Float3:
    __slots__ = ("x", "y", "z")

    def __init__(self, x: float = 0.0, y: float | None = None, z: float | None = None):
        # Float3() is zero, Float3(c) repeats c, Float3(x, y, z) sets each component
        # (the slide's constructors Float3(), Float3(float c), Float3(x, y, z)).
        if z is not None and y is not None:
            self.x = float(x)
            self.y = float(y)
            self.z = float(z)
        elif y is None and z is None:
            self.x = self.y = self.z = float(x)
        else:
            raise TypeError("Float3 takes no argument, one (c) or three (x, y, z)")

    # --- the union's aliases -------------------------------------------------
    r = property(lambda v: v.x, lambda v, c: setattr(v, "x", float(c)))
    g = property(lambda v: v.y, lambda v, c: setattr(v, "y", float(c)))
    b = property(lambda v: v.z, lambda v, c: setattr(v, "z", float(c)))
    s = property(lambda v: v.x, lambda v, c: setattr(v, "x", float(c)))
    t = property(lambda v: v.y, lambda v, c: setattr(v, "y", float(c)))
    u = property(lambda v: v.z, lambda v, c: setattr(v, "z", float(c)))
    alpha = property(lambda v: v.x, lambda v, c: setattr(v, "x", float(c)))
    beta = property(lambda v: v.y, lambda v, c: setattr(v, "y", float(c)))
    gamma = property(lambda v: v.z, lambda v, c: setattr(v, "z", float(c)))

    # --- operator[] ------------------------------------------------------------
    def __getitem__(self, i: int) -> float:
        if i == 0 or i == -3:
            return self.x
        if i == 1 or i == -2:
            return self.y
        if i == 2 or i == -1:
            return self.z
        raise IndexError("Float3 index out of range: %r" % (i,))

    def __setitem__(self, i: int, c: float) -> None:
        name = ("x", "y", "z")[i]
        setattr(self, name, float(c))

    def __iter__(self):
        yield self.x
        yield self.y
        yield self.z

    def __len__(self) -> int:
        return 3

    # --- compound assignment: += -= *= /= with a Float3 or a scalar -------------
    def __iadd__(self, o):
        o = _as_float3(o)
        self.x += o.x; self.y += o.y; self.z += o.z
        return self

    def __isub__(self, o):
        o = _as_float3(o)
        self.x -= o.x; self.y -= o.y; self.z -= o.z
        return self

    def __imul__(self, o):
        o = _as_float3(o)
        self.x *= o.x; self.y *= o.y; self.z *= o.z
        return self

    def __itruediv__(self, o):
        o = _as_float3(o)
        self.x /= o.x; self.y /= o.y; self.z /= o.z
        return self

    # --- arithmetic -------------------------------------------------------------
    def __add__(self, o: Float3) -> Float3:
        ### BEGIN SOLUTION
        return Float3(self.x + o.x, self.y + o.y, self.z + o.z)
        ### END SOLUTION

    def __neg__(self) -> Float3:
        ### BEGIN SOLUTION
        return Float3(-self.x, -self.y, -self.z)
        ### END SOLUTION

    def __sub__(self, o: Float3) -> Float3:
        ### BEGIN SOLUTION
        return Float3(self.x - o.x, self.y - o.y, self.z - o.z)
        ### END SOLUTION

    def __mul__(self, o) -> Float3:
        ### BEGIN SOLUTION
        if isinstance(o, Float3):
            return Float3(self.x * o.x, self.y * o.y, self.z * o.z)
        return Float3(self.x * o, self.y * o, self.z * o)
        ### END SOLUTION

    # "inline Float3 operator*(float f, const Float3 &v) { return v*f; }"
    def __rmul__(self, f) -> Float3:
        return self * f

    def __truediv__(self, o) -> Float3:
        ### BEGIN SOLUTION
        if isinstance(o, Float3):
            return Float3(self.x / o.x, self.y / o.y, self.z / o.z)
        # The slide divides by a scalar through its reciprocal: inv = 1.0f / x.
        inv = 1.0 / o
        return Float3(self.x * inv, self.y * inv, self.z * inv)
        ### END SOLUTION

    def length_squared(self) -> float:
        ### BEGIN SOLUTION
        return self.x * self.x + self.y * self.y + self.z * self.z
        ### END SOLUTION

    def length(self) -> float:
        ### BEGIN SOLUTION
        return math.sqrt(self.length_squared())
        ### END SOLUTION

    # --- conveniences a Python user expects --------------------------------------
    def __eq__(self, o) -> bool:
        return isinstance(o, Float3) and self.x == o.x and self.y == o.y and self.z == o.z

    __hash__ = None  # mutable, like the C++ struct

    def __repr__(self) -> str:
        return "Float3(%r, %r, %r)" % (self.x, self.y, self.z)

    def copy(self) -> Float3:
        return Float3(self.x, self.y, self.z)

    def is_finite(self) -> bool:
        return math.isfinite(self.x) and math.isfinite(self.y) and math.isfinite(self.z)


def _as_float3(o) -> Float3:
    return o if isinstance(o, Float3) else Float3(o)


def normalize(v: Float3) -> Float3:
    ### BEGIN SOLUTION
    return v / v.length()
    ### END SOLUTION


def dot(v1: Float3, v2: Float3) -> float:
    ### BEGIN SOLUTION
    return v1.x * v2.x + v1.y * v2.y + v1.z * v2.z
    ### END SOLUTION


def cross(v1: Float3, v2: Float3) -> Float3:
    ### BEGIN SOLUTION
    return Float3((v1.y * v2.z) - (v1.z * v2.y),
                  (v1.z * v2.x) - (v1.x * v2.z),
                  (v1.x * v2.y) - (v1.y * v2.x))
    ### END SOLUTION


def as_float3(value, name: str) -> Float3:
    """Accept a Float3 or three numbers; raise a ValueError naming ``name`` if not finite."""
    if not isinstance(value, Float3):
        try:
            x, y, z = value
        except (TypeError, ValueError):
            raise ValueError("%s must be a Float3 or three numbers, got %r" % (name, value)) from None
        value = Float3(x, y, z)
    if not value.is_finite():
        raise ValueError("%s must be finite, got %r" % (name, value))
    return value
