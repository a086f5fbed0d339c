"""a04: diffuse shading with a point light (02562: Kepler's inverse square law, Lambert's
cosine law, "Sampling light in the shader")."""
from __future__ import annotations

import math

from . import Check, image_check, register
from .child import Cases, num, vec


def observe_kepler(rt):
    cases = Cases()
    F = rt.Float3
    for p, intensity, x in [((0, 1, 0), (math.pi,) * 3, (0.5, 0, 0.5)), ((2, 3, -1), (10, 5, 1), (0, 0, 0)),
                            ((0, 1, 0), (1, 1, 1), (0, 0.75, 0))]:
        def run(p=p, intensity=intensity, x=x):
            light = rt.PointLight(F(*p), F(*intensity))
            sample = rt.lights.sample_point_light(light, F(*x))
            return {"L_i": vec(sample.L_i, "L_i"), "w_i": vec(sample.w_i, "w_i"), "dist": num(sample.dist, "dist")}
        cases.run("a point light at (%g, %g, %g) with intensity (%g, %g, %g), sampled at (%g, %g, %g)"
                  % (tuple(p) + tuple(intensity) + tuple(x)), run, p=list(p), intensity=list(intensity), x=list(x))
    return cases.result()


def hint_kepler(inputs, want, got):
    p, x = inputs["p"], inputs["x"]
    dist = math.dist(p, x)
    if isinstance(got.get("w_i"), list) and all(abs(g + w) < 1e-9 for g, w in zip(got["w_i"], want["w_i"])):
        return "w_i points away from the light: it is (p - x) / |p - x|, from the surface toward the light"
    if isinstance(got.get("L_i"), list) and abs(got["L_i"][0] - want["L_i"][0] * dist) < 1e-9 * max(1, abs(got["L_i"][0])):
        return "L_i falls off with the distance, not its square: Kepler's law is L_i = I / |p - x|^2"
    if isinstance(got.get("w_i"), list) and abs(math.hypot(*got["w_i"]) - 1.0) > 1e-6:
        return "w_i must have unit length: divide p - x by the distance"
    return None


def _shading_scene(rt, lights, shadows=False):
    F = rt.Float3
    scene = rt.Scene(None)
    scene.shadows = shadows
    for position, intensity in lights:
        scene.lights.append(rt.PointLight(F(*position), F(*intensity)))
    return scene


def _hit(rt, position, normal, color, emission=(0, 0, 0), material=None):
    F = rt.Float3
    hit = rt.HitInfo()
    hit.has_hit = True
    hit.position = F(*position)
    hit.normal = rt.float3.normalize(F(*normal))
    m = material or rt.Material(rt.LAMBERTIAN, emission=F(*emission))
    hit.set_material(F(*color), m)
    return hit


def _lambert_cases(rt, setups):
    cases = Cases()
    F = rt.Float3
    for lights, position, normal, color, emission in setups:
        def run(lights=lights, position=position, normal=normal, color=color, emission=emission):
            scene = _shading_scene(rt, lights)
            hit = _hit(rt, position, normal, color, emission)
            r = rt.Ray(F(position[0], position[1] + 1, position[2] + 1), F(0, -0.70710678, -0.70710678))
            return {"L_o": vec(rt.shading.lambertian(scene, r, hit), "lambertian's result")}
        n = [c / math.sqrt(sum(v * v for v in normal)) for c in normal]
        cos = []
        for lp, _ in lights:
            w = [lp[i] - position[i] for i in range(3)]
            length = math.sqrt(sum(v * v for v in w))
            cos.append(sum(n[i] * w[i] / length for i in range(3)))
        label = "lambertian at (%g, %g, %g), normal (%g, %g, %g), colour (%g, %g, %g), lights %s" % (
            tuple(position) + tuple(normal) + tuple(color) + (lights,))
        cases.run(label, run, color=list(color), emission=list(emission), cos=cos)
    return cases.result()


PI3 = (math.pi,) * 3


def observe_lambert(rt):
    return _lambert_cases(rt, [
        ([((0, 1, 0), PI3)], (0, 0, 0), (0, 1, 0), (0.1, 0.7, 0), (0, 0, 0)),
        ([((0, 1, 0), PI3)], (0.5, 0, 0.5), (0, 1, 0), (0.1, 0.7, 0), (0, 0, 0)),
        ([((0, 1, 0), PI3)], (1, 0, 0), (0, 1, 0), (0.4, 0.3, 0.2), (0, 0, 0)),
        ([((2, 2, 0), (4, 4, 4))], (0, 0, 0), (0, 1, 0), (1, 1, 1), (0, 0, 0)),
        ([((0, 1, 0), PI3)], (0.2, 0.1, 0.4), (0, 2, 0), (0.4, 0.3, 0.2), (0, 0, 0)),
    ])


def observe_lambert_below(rt):
    return _lambert_cases(rt, [
        ([((0, -1, 0), PI3)], (0, 0, 0), (0, 1, 0), (0.1, 0.7, 0), (0, 0, 0)),
        ([((3, -0.5, 0), (5, 5, 5))], (0, 0, 0), (0, 1, 0), (0.5, 0.5, 0.5), (0, 0, 0)),
    ])


# ### BEGIN HIDDEN
def observe_lambert_more(rt):
    return _lambert_cases(rt, [
        ([((0, 1, 0), PI3), ((2, 1, 0), (1, 2, 3))], (0.5, 0, 0), (0, 1, 0), (0.8, 0.6, 0.4), (0, 0, 0)),
        ([((0, 1, 0), PI3)], (0, 0, 0), (0, 1, 0), (0.2, 0.2, 0.2), (0.5, 0.25, 0)),
        ([((1, 1, 1), (2, 2, 2)), ((-1, 1, 1), (2, 0, 2)), ((0, -1, 0), (9, 9, 9))], (0, 0, 0),
         (0, 1, 1), (0.3, 0.6, 0.9), (0, 0, 0)),
    ])
# ### END HIDDEN


def hint_lambert(inputs, want, got):
    L = got.get("L_o")
    if not isinstance(L, list):
        return None
    color, emission, cos = inputs["color"], inputs["emission"], inputs["cos"]
    base = [emission[i] + 0.1 * color[i] for i in range(3)]
    d_want = [want["L_o"][i] - base[i] for i in range(3)]
    d_got = [L[i] - base[i] for i in range(3)]
    lit = [c for c in cos if c > 0]
    if len(lit) == 1 and lit[0] < 0.999 and all(abs(g * lit[0] - w) < 1e-6 * max(1e-3, abs(w)) for g, w in zip(d_got, d_want)) \
            and any(abs(w) > 1e-9 for w in d_want):
        return ("your diffuse term is the expected one divided by cos(theta) = n . w_i = %.4g: "
                "the cosine term of Lambert's law is missing (rho_d / pi * L_i * (n . w_i))" % lit[0])
    if all(abs(g - w - 0.1 * c) < 1e-9 for g, w, c in zip(L, want["L_o"], color)):
        return "you added the ambient term twice"
    if all(abs(g + 0.1 * c - w) < 1e-9 for g, w, c in zip(L, want["L_o"], color)):
        return "the ambient term L_a = 0.1 * colour is missing"
    if any(abs(w) > 1e-9 for w in d_want) and all(abs(g - w * math.pi) < 1e-6 * max(1e-3, abs(g)) for g, w in zip(d_got, d_want)):
        return "divide rho_d by pi (the Lambertian BRDF is rho_d / pi)"
    if not lit and any(abs(g) > 1e-9 for g in d_got):
        return "a light below the surface (n . w_i <= 0) must add nothing"
    return None


register("a04_diffuse", [
    Check("sample_point_light: Kepler's inverse square law and the direction to the light", 2,
          observe_kepler, hint=hint_kepler),
    Check("lambertian: one point light, Lambert's cosine law and ambient", 3, observe_lambert, hint=hint_lambert),
    Check("lambertian: a light below the surface adds nothing", 1, observe_lambert_below, hint=hint_lambert),
    image_check("image: 02562 default scene, Lambertian, no shadows", 2,
                lambda rt: rt.scenes.default_scene.default_scene(rt.LAMBERTIAN, rt.LAMBERTIAN, shadows=False)),
    # ### BEGIN HIDDEN
    Check("lambertian: several lights and emission", 2, observe_lambert_more, visibility="hidden",
          hint=hint_lambert),
    # ### END HIDDEN
])
