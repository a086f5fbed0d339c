"""a04: diffuse shading with a point light (02562: Kepler's inverse square law, Lambert's cosine
law, "Sampling light in the shader"). The probes are in rtfgu/grading/probes/a04.py (visible)
and a04_hidden.py; the hints compare with the known mistakes of rtfgu.grading.mistakes."""
from __future__ import annotations

import math

from . import Check, image_check, register


def hint_kepler(inputs, want, got):
    dist = (inputs.get("known") or {}).get("dist")
    if dist is None:
        return None
    if isinstance(got.get("w_i"), list) and all(abs(g + w) < 1e-9 for g, w in zip(got["w_i"], want["w_i"])):
        return "w_i points away from the light: it is (p - x) / |p - x|, from the surface toward the light"
    if isinstance(got.get("L_i"), list) and abs(got["L_i"][0] - want["L_i"][0] * dist) < 1e-9 * max(1, abs(got["L_i"][0])):
        return "L_i falls off with the distance, not its square: Kepler's law is L_i = I / |p - x|^2"
    if isinstance(got.get("w_i"), list) and abs(math.hypot(*got["w_i"]) - 1.0) > 1e-6:
        return "w_i must have unit length: divide p - x by the distance"
    return None


def hint_lambert(inputs, want, got):
    L = got.get("L_o")
    if not isinstance(L, list):
        return None
    color, emission = inputs["color"], inputs["emission"]
    cos = (inputs.get("known") or {}).get("cos")
    if cos is None:
        return None
    base = [emission[i] + 0.1 * color[i] for i in range(3)]
    d_want = [want["L_o"][i] - base[i] for i in range(3)]
    d_got = [L[i] - base[i] for i in range(3)]
    lit = [c for c in cos if c > 0]
    if len(lit) == 1 and lit[0] < 0.999 and all(abs(g * lit[0] - w) < 1e-6 * max(1e-3, abs(w)) for g, w in zip(d_got, d_want)) \
            and any(abs(w) > 1e-9 for w in d_want):
        return ("your diffuse term is the expected one divided by cos(theta) = n . w_i = %.4g: "
                "the cosine term of Lambert's law is missing (f_r L_i (n . w_i), f_r = kd cd / pi)" % lit[0])
    if all(abs(g - w - 0.1 * c) < 1e-9 for g, w, c in zip(L, want["L_o"], color)):
        return "you added the ambient term twice"
    if all(abs(g + 0.1 * c - w) < 1e-9 for g, w, c in zip(L, want["L_o"], color)):
        return "the ambient term L_a = 0.1 * colour is missing"
    if any(abs(w) > 1e-9 for w in d_want) and all(abs(g - w * math.pi) < 1e-6 * max(1e-3, abs(g)) for g, w in zip(d_got, d_want)):
        return "divide kd cd by pi (the Lambertian BRDF is f_r = kd cd / pi)"
    if not lit and any(abs(g) > 1e-9 for g in d_got):
        return "a light below the surface (n . w_i <= 0) must add nothing"
    return None


register("a04_diffuse", [
    Check("PointLight.L and get_direction: Kepler's inverse square law and the direction to the light", 2,
          ("a04", "observe_kepler"), hint=hint_kepler, known="kepler"),
    Check("Matte.shade: one point light, Lambert's cosine law and ambient", 3, ("a04", "observe_lambert"),
          hint=hint_lambert, known="lambert"),
    Check("Matte.shade: a light below the surface adds nothing", 1, ("a04", "observe_lambert_below"),
          hint=hint_lambert, known="lambert"),
    image_check("image: 02562 default scene, Lambertian, no shadows", 2, "default_scene",
                shaders=("LAMBERTIAN", "LAMBERTIAN"), shadows=False),
    # ### BEGIN HIDDEN
    Check("Matte.shade: several lights and emission", 2, ("a04_hidden", "observe_lambert_more"), visibility="hidden",
          hint=hint_lambert, known="lambert"),
    # ### END HIDDEN
])
