"""Probes of a04's visible tests: diffuse shading with a point light (02562: Kepler's inverse
square law, Lambert's cosine law, "Sampling light in the shader"; Suffern ch. 13-14: the
PointLight's get_direction and L, the Lambertian BRDF, Matte.shade)."""
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
            sample = light.sample(F(*x))     # (L(sr), get_direction(sr), distance) at x
            return {"L_i": vec(sample.L_i, "L_i"), "w_i": vec(sample.w_i, "w_i"), "dist": num(sample.dist, "dist")}
        cases.run("a point light at (%g, %g, %g) with intensity (%g, %g, %g), sampled at (%g, %g, %g)"
                  % (tuple(p) + tuple(intensity) + tuple(x)), run, p=list(p), intensity=list(intensity), x=list(x))
    return cases.result()


def _shading_scene(rt, lights, shadows=False):
    F = rt.Float3
    scene = rt.Scene(None)
    for position, intensity in lights:
        light = rt.PointLight(F(*position), F(*intensity))
        light.set_shadows(shadows)
        scene.lights.append(light)
    scene.tracer.world = scene
    return scene


def _hit(rt, scene, ray, position, normal, color, emission=(0, 0, 0), material=None):
    """The HitInfo a material's shade reads: the hit point, its normal and colour, the
    material (the course's Matte with ``emission`` by default), the ray and the scene."""
    F = rt.Float3
    hit = rt.HitInfo(scene)
    hit.has_hit = True
    hit.position = F(*position)
    hit.normal = rt.float3.normalize(F(*normal))
    hit.color = F(*color)
    hit.material = material or rt.Matte(emission=F(*emission))
    hit.ray = ray
    return hit


def _lambert_cases(rt, setups):
    cases = Cases()
    F = rt.Float3
    for lights, position, normal, color, emission in setups:
        def run(lights=lights, position=position, normal=normal, color=color, emission=emission):
            scene = _shading_scene(rt, lights)
            r = rt.Ray(F(position[0], position[1] + 1, position[2] + 1), F(0, -0.70710678, -0.70710678))
            hit = _hit(rt, scene, r, position, normal, color, emission)
            return {"L_o": vec(hit.material.shade(hit), "Matte.shade's result")}
        label = "Matte.shade at (%g, %g, %g), normal (%g, %g, %g), colour (%g, %g, %g), lights %s" % (
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
