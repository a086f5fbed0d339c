"""a01: Float3 and Ray (lecture 01, "Float3 Structure" and "Ray"). The probes are in
rtfgu/grading/probes/a01.py (visible) and a01_hidden.py."""
from __future__ import annotations

from . import Check, register


def hint_dot_cross(inputs, want, got):
    if "cross" in want and got.get("cross") and all(abs(g + w) < 1e-9 for g, w in zip(got["cross"], want["cross"])):
        return "your cross product has the opposite sign: the order is a x b = (a.y b.z - a.z b.y, ...)"
    return None


def hint_length(inputs, want, got):
    if "length" in want and isinstance(got.get("length"), float) and abs(got["length"] - want["length"] ** 2) < 1e-9:
        return "length() returned the squared length: take the square root"
    return None


register("a01_float3_ray", [
    Check("Float3: addition, subtraction and negation", 2, ("a01", "observe_add_sub")),
    Check("Float3: products and quotients, componentwise and by a number", 2, ("a01", "observe_mul_div")),
    Check("dot and cross products", 2, ("a01", "observe_dot_cross"), hint=hint_dot_cross),
    Check("length_squared, length and normalize", 2, ("a01", "observe_length"), hint=hint_length),
    Check("Ray: the point at parameter t, r(t) = o + t d", 1, ("a01", "observe_ray")),
    # ### BEGIN HIDDEN
    Check("operators return new vectors and leave their operands unchanged", 1,
          ("a01_hidden", "observe_unchanged"), visibility="hidden"),
    # ### END HIDDEN
])
