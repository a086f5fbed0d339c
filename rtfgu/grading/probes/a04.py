"""Probes of a04's visible tests: diffuse shading with a point light (02562: Kepler's inverse
square law, Lambert's cosine law, "Sampling light in the shader")."""
from __future__ import annotations

import math

from .support import Cases, num, vec


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
        label = "lambertian at (%g, %g, %g), normal (%g, %g, %g), colour (%g, %g, %g), lights %s" % (
            tuple(position) + tuple(normal) + tuple(color) + (lights,))
        cases.run(label, run, color=list(color), emission=list(emission), position=list(position),
                  normal=list(normal), lights=[list(p) for p, _ in lights])
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
