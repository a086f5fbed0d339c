"""a13: instancing, Suffern's Matrix and Instance (ch. 20, "Affine Transformations"; ch. 21,
"Instancing"). The probes are in rtfgu/grading/probes/a13.py.

The three products are checked on matrices that are not symmetric (a normal through the
matrix instead of its transpose shows) with dyadic entries (every product exact); the
composed matrices along chains of calls whose order matters (a scale then a move is not a
move then a scale); the object-space ray, whose direction must not be normalised; the t and
the normals of hits on an ellipsoid, a turned box and a sheared open cylinder; and Suffern's
chapter-21 figure rendered by the lecture layer.
"""
from __future__ import annotations

from . import Check, register

MATRIX = ("matrix.py",)
INSTANCE = ("matrix.py", "shapes/instance.py")


def _same_way(a, b) -> bool:
    """Whether a and b point the same way (a x b = 0, a . b > 0)."""
    cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    scale = 1e-9 * (1 + sum(x * x for x in a)) * (1 + sum(x * x for x in b))
    return all(abs(c) <= scale for c in cross) and sum(x * y for x, y in zip(a, b)) > 0


def _close(a, b) -> bool:
    return isinstance(a, list) and isinstance(b, list) and len(a) == len(b) and all(
        isinstance(x, float) and abs(x - y) <= 1e-9 * (1 + abs(y)) for x, y in zip(a, b))


def hint_products(inputs, want, got):
    if _close(got.get("vector"), want["point"]) and not _close(want["vector"], want["point"]):
        return "your transform_vector moves the vector by the translation m[i][3]: a direction (w = 0) does not move"
    rows, x = inputs["rows"], inputs["x"]
    plain = [sum(rows[i][j] * x[j] for j in range(3)) for i in range(3)]
    if _close(got.get("normal"), plain) and not _close(want["normal"], plain):
        return ("your transform_normal multiplies by the matrix itself: a normal goes through its transpose, "
                "row i = m[0][i] n.x + m[1][i] n.y + m[2][i] n.z (Suffern ch. 20.5)")
    return None


def hint_compose(inputs, want, got):
    if len(inputs["chain"]) > 1 and isinstance(got.get("inv_matrix"), list):
        return ("with more than one call the order of the products matters: the inverse of a product is the "
                "product of the inverses in the other order, inv_matrix * inverse (forward * forward_matrix)")
    return None


def hint_object_ray(inputs, want, got):
    d = got.get("direction")
    if _close(d, d) and len(d) == 3 and _same_way(d, want["direction"]) and not _close(d, want["direction"]):
        return ("your object ray's direction is normalised: keep it as the inverse matrix makes it, so that the "
                "object's t is the world ray's t (Suffern ch. 21.1)")
    return None


def hint_hits(inputs, want, got):
    if got.get("hit") != want.get("hit"):
        return "the instance is %s here: check object_ray and the matrices" % ("hit" if want.get("hit") else "missed")
    return None


M1 = [[1.0, 2.0, 0.0, 3.0], [0.0, 1.0, 0.5, -1.0], [0.25, 0.0, 2.0, 0.5], [0.0, 0.0, 0.0, 1.0]]
M2 = [[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, -4.0], [0.0, 0.0, 0.0, 1.0]]
PRODUCT_CASES = [[M1, [1.0, 2.0, 3.0]], [M1, [-0.5, 0.0, 4.0]], [M2, [1.0, 0.0, 0.0]], [M2, [0.25, -2.0, 1.0]]]
COMPOSE_CASES = [[["translate", 1.0, 2.0, 3.0]], [["scale", 2.0, 1.0, 0.5]], [["rotate_y", 90.0]],
                 [["scale", 2.0, 2.0, 2.0], ["translate", 1.0, 0.0, 0.0]],
                 [["translate", 1.0, 0.0, 0.0], ["scale", 2.0, 2.0, 2.0]],
                 [["rotate_z", 30.0], ["translate", 0.0, 1.0, 0.0], ["scale", 1.0, 3.0, 1.0]]]
RAY_CASES = [[[["scale", 2.0, 1.0, 1.0], ["translate", 0.0, 1.0, 0.0]], [0.0, 1.0, 5.0], [0.0, 0.0, -1.0]],
             [[["scale", 2.0, 1.0, 1.0]], [5.0, 0.0, 0.0], [-1.0, 0.0, 0.0]],
             [[["rotate_x", 90.0], ["translate", 0.0, 0.0, -2.0]], [0.0, 3.0, -2.0], [0.0, -0.6, 0.8]]]
ELLIPSOID = [["scale", 2.0, 1.0, 1.0], ["translate", 0.0, 1.0, 0.0]]
HIT_CASES = [[("sphere", (0, 0, 0), 1.0), ELLIPSOID, [5.0, 1.0, 0.0], [-1.0, 0.0, 0.0]],
             [("sphere", (0, 0, 0), 1.0), ELLIPSOID, [1.0, 6.0, 0.0], [0.0, -1.0, 0.0]],
             [("sphere", (0, 0, 0), 1.0), ELLIPSOID, [0.0, 3.0, 0.0], [0.0, 0.0, 1.0]],
             [("box", (-0.5, -0.5, -0.5), (0.5, 0.5, 0.5)), [["rotate_y", 45.0], ["translate", 0.0, 0.5, 0.0]],
              [3.0, 0.5, 0.1], [-1.0, 0.0, 0.0]],
             [("cylinder", 0.0, 1.0, 1.0), [["shear", 0.0, 0.0, 0.5, 0.0, 0.0, 0.0]],
              [0.25, 0.5, 0.0], [0.0, 0.0, 1.0]]]

register("a13_instancing", [
    Check("Matrix.transform_point, transform_vector and transform_normal", 3,
          ("a13", "observe_products", dict(cases=PRODUCT_CASES)), hint=hint_products, needs=MATRIX),
    Check("Instance: the inverse and forward matrices a chain of calls composes", 3,
          ("a13", "observe_compose", dict(cases=COMPOSE_CASES)), hint=hint_compose, needs=INSTANCE),
    Check("Instance.object_ray: the ray in the object's space, its direction not normalised", 2,
          ("a13", "observe_object_ray", dict(cases=RAY_CASES)), hint=hint_object_ray, needs=INSTANCE),
    Check("Instance hits: t, normal_at and hit_normal on an ellipsoid, a turned box and a sheared cylinder", 3,
          ("a13", "observe_hits", dict(cases=HIT_CASES)), hint=hint_hits),
    Check("image: Suffern's chapter-21 instances (ellipsoids, turned boxes, a leaning cylinder)", 2,
          ("a13", "render_instances", dict(width=32, height=32)), kind="image", size=(32, 32)),
    # ### BEGIN HIDDEN
    Check("Instance: shears and rotations about every axis, composed", 1,
          ("a13", "observe_compose", dict(cases=[[["shear", 0.5, 0.0, 0.0, 0.25, 0.0, 0.0]],
                                                 [["rotate_x", 30.0], ["rotate_y", -60.0], ["rotate_z", 45.0]],
                                                 [["shear", 0.0, 0.5, 0.0, 0.0, 0.25, 0.0], ["scale", 3.0],
                                                  ["translate", -1.0, 2.0, 0.5]]])),
          hint=hint_compose, visibility="hidden", needs=INSTANCE),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("Instance hits from inside and through a sheared ellipsoid", 1,
          ("a13", "observe_hits", dict(cases=[
              [("sphere", (0, 0, 0), 1.0), [["scale", 1.0, 3.0, 1.0], ["rotate_z", 30.0]], [0.0, 0.0, 0.0],
               [0.6, 0.8, 0.0]],
              [("sphere", (0, 0, 0), 1.0), [["shear", 0.5, 0.0, 0.0, 0.0, 0.0, 0.0]], [0.1, 4.0, 0.2],
               [0.0, -1.0, 0.0]]])),
          hint=hint_hits, visibility="hidden"),
    # ### END HIDDEN
])
