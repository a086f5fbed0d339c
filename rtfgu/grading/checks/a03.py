"""a03: ray-plane, ray-sphere, ray-triangle intersection and the closest hit (lecture 01,
"Ray-Plane Intersection", "Ray-Sphere Intersection"; 02562 week 2). The probes are in
rtfgu/grading/probes/a03.py (visible) and a03_hidden.py; the sphere's hints compare with the
known mistakes of rtfgu.grading.mistakes."""
from __future__ import annotations

from . import Check, image_check, register


def _interval_hint(inputs, want, got):
    """Hints every shape shares: the interval and what a miss leaves alone."""
    if got.get("returned") is True and want["returned"] is False:
        t = got.get("ray.tmax")
        if isinstance(t, float) and t < inputs["tmin"]:
            return ("you accepted t = %.6g, which is less than ray.tmin = %g (behind the ray's start): "
                    "a hit needs tmin <= t < tmax" % (t, inputs["tmin"]))
        if isinstance(t, float) and t >= inputs["tmax"]:
            return "you accepted t = %.6g, which is not less than ray.tmax = %g: a hit needs tmin <= t < tmax" % (
                t, inputs["tmax"])
    if got.get("returned") is want["returned"] is False and got.get("ray.tmax") != want["ray.tmax"]:
        return "on a miss, intersect_p must leave ray.tmax as it was"
    if got.get("returned") is True and want["returned"] is True and got.get("ray.tmax") == inputs["tmax"]:
        return "on a hit, intersect_p must set ray.tmax to the hit distance t"
    return None


def _near(t, values) -> bool:
    return any(abs(t - w) < 1e-6 * max(1.0, abs(w)) for w in values)


def hint_sphere(inputs, want, got):
    """Compares the student's t with the known mistakes (rtfgu.grading.mistakes.sphere)."""
    t = got.get("ray.tmax")
    known = inputs.get("known") or {}
    roots, a = known.get("roots", []), known.get("a")
    if isinstance(t, float) and got.get("returned") is True and _near(t, known.get("roots_plus_4ac", [])) \
            and not _near(t, roots):
        return ("your t is a root of b^2 + 4ac instead of the discriminant b^2 - 4ac: "
                "check the sign in the discriminant")
    disc = known.get("disc")
    if want["returned"] is False and got.get("returned") is True and isinstance(disc, float) and disc < 0:
        return ("this ray misses the sphere (b^2 - 4ac = %.6g < 0) but your code reports a hit: "
                "check the discriminant, b^2 - 4ac, and its sign" % disc)
    interval = _interval_hint(inputs, want, got)
    if interval:
        return interval
    if isinstance(t, float) and len(roots) == 2 and _near(t, roots[1:]) and want["ray.tmax"] != t:
        return "you returned the far root; the near one, (-b - sqrt(b^2 - 4ac)) / 2a, comes first when it is in range"
    if isinstance(t, float) and isinstance(a, float) and a != 1.0:
        if _near(t, [w * a for w in roots]):
            return ("your t is off by the factor d . d: keep a = d . d in the quadratic (the direction need "
                    "not be a unit vector)")
        if _near(t, known.get("roots_a_is_one", [])):
            return ("your t solves t^2 + b t + c = 0, as if a = d . d were 1; here d . d = %.6g: keep a in "
                    "the quadratic, the direction need not be a unit vector" % a)
    return None


# The slips that decide inside or outside wrongly (rtfgu.grading.mistakes.triangle), in the
# order a hint names them.
TRIANGLE_SLIPS = (("gamma_sign", "a flipped sign of gamma"), ("beta_sign", "a flipped sign of beta"),
                  ("swapped_edges", "e0 and e1 swapped"), ("open_edge", "the edge v1 v2 left out (beta + gamma < 1)"))


def hint_triangle(inputs, want, got):
    """Names where the ray meets the plane (the exact beta and gamma of the known mistakes)
    and the slips that give the student's answer there."""
    known = inputs.get("known") or {}
    returned = got.get("returned")
    t = got.get("ray.tmax")
    if "beta" in known and isinstance(returned, bool) and returned != want["returned"] \
            and (not returned or (isinstance(t, float) and inputs["tmin"] <= t < inputs["tmax"])):
        where = "beta = %.6g, gamma = %.6g, beta + gamma = %.6g" % (
            known["beta"], known["gamma"], known["beta"] + known["gamma"])
        slips = [text for key, text in TRIANGLE_SLIPS if known.get(key) == returned != known["inside"]]
        if known.get("open_edge") == returned != known["inside"]:
            slips = [TRIANGLE_SLIPS[-1][1]]   # on the edge itself: that slip, not the signs
        if known["inside"] and not returned and not inputs["tmin"] <= known["t"] < inputs["tmax"]:
            slips = []        # outside the interval: the interval's hint below
        if slips or known["inside"] != returned:
            text = ("the ray meets the triangle's plane %s the triangle (%s), but your code %s" % (
                "inside" if known["inside"] else "outside", where,
                "reports no hit" if known["inside"] else "reports a hit"))
            if slips:
                text += "; %s gives that here" % (slips[0] if len(slips) == 1 else
                                                   ", ".join(slips[:-1]) + " or " + slips[-1])
            return text + (". beta weighs v1 (e0 = v1 - v0) and gamma weighs v2 (e1 = v2 - v0); a point is "
                           "inside when beta >= 0, gamma >= 0 and beta + gamma <= 1")
    return _interval_hint(inputs, want, got)


def hint_normals(inputs, want, got):
    length = got.get("its length")
    if isinstance(length, float) and abs(length - 1.0) > 1e-6:
        return ("your normal has length %.6g, not 1: normal_at must return a unit vector "
                "(normalize it; for a sphere, divide position - center by the radius)" % length)
    return None


register("a03_intersections", [
    Check("Plane.intersect_p: hits, misses and the ray interval", 2, ("a03", "observe_plane"), hint=_interval_hint,
          needs=("shapes/plane.py",)),
    Check("Sphere.intersect_p: rays that hit", 2, ("a03", "observe_sphere_hits"), hint=hint_sphere, known="sphere",
          needs=("shapes/sphere.py",)),
    Check("Sphere.intersect_p: rays that miss", 1, ("a03", "observe_sphere_misses"), hint=hint_sphere,
          known="sphere", needs=("shapes/sphere.py",)),
    Check("Sphere.intersect_p: only t in [tmin, tmax) counts", 2, ("a03", "observe_sphere_interval"),
          hint=hint_sphere, known="sphere", needs=("shapes/sphere.py",)),
    Check("Triangle.intersect_p: inside, outside and the ray interval", 2, ("a03", "observe_triangle"),
          hint=hint_triangle, known="triangle", needs=("shapes/triangle.py",)),
    Check("normal_at: unit normals of sphere, plane and triangle", 1, ("a03", "observe_normals"), hint=hint_normals),
    image_check("image: lecture 01 scene, the closest hit in flat colours", 2, "lecture01_flat_colors"),
    image_check("image: 02562 default scene in flat colours", 2, "default_flat_colors"),
    # ### BEGIN HIDDEN
    Check("the closest hit among five shapes", 2, ("a03_hidden", "observe_closest"), visibility="hidden",
          hint=_interval_hint),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("Sphere.intersect_p with directions that are not unit vectors", 1,
          ("a03_hidden", "observe_sphere_long_directions"), visibility="hidden", hint=hint_sphere, known="sphere",
          needs=("shapes/sphere.py",)),
    # ### END HIDDEN
])
