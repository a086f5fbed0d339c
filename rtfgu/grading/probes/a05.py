"""Probes of a05's visible tests: shadow rays, Phong, mirror and refraction (02562 weeks 2-3;
Suffern ch. 15, 24 and 27: Light.in_shadow, GlossySpecular, Reflective, PerfectTransmitter)."""
from __future__ import annotations

import math

from .a04 import _hit, _shading_scene
from .support import Cases, boolean, num, vec

LIGHT = (0.0, 1.0, 0.0)


def _toward(p, light):
    w = [light[i] - p[i] for i in range(3)]
    dist = math.sqrt(sum(v * v for v in w))
    return [v / dist for v in w], dist


def _default_shapes(rt):
    F = rt.Float3
    return [rt.Plane(F(0, 0, 0), F(0, 1, 0), F(0.1, 0.7, 0)),
            rt.Triangle(F(-0.2, 0.1, 0.9), F(0.2, 0.1, 0.9), F(-0.2, 0.1, -0.1), F(0.4, 0.3, 0.2)),
            rt.Sphere(F(0, 0.5, 0), 0.3, F(0, 0, 0))]


def _in_shadow(rt, scene, point, light):
    """A point light at ``light``'s in_shadow for a shadow ray from ``point`` toward it."""
    F = rt.Float3
    source = rt.PointLight(F(*light), F(1, 1, 1))
    sr = rt.HitInfo(scene)
    sr.position = F(*point)
    w, _ = _toward([sr.position.x, sr.position.y, sr.position.z], light)
    return boolean(source.in_shadow(rt.Ray(sr.position, F(*w)), sr), "in_shadow's result")


def _shadow_case(rt, cases, label, shapes, point, light):
    def run():
        scene = rt.Scene(None)
        scene.shapes.extend(shapes())
        return {"in shadow": _in_shadow(rt, scene, point, light)}
    cases.run(label, run, point=list(point), light=list(light))


def observe_occluders(rt):
    cases = Cases()
    shapes = lambda: _default_shapes(rt)
    for point, light, what in [((0, 0.05, 0), LIGHT, "below the sphere"),
                               ((1.0, 0.05, -1.0), LIGHT, "beside the sphere"),
                               ((0, 2, 0), (0, 3, 0), "above everything, light above it"),
                               ((0, 0.05, 0), (0, 0.15, 0), "below the sphere, light between it and the sphere"),
                               ((0, 0.05, 0.5), LIGHT, "under the triangle")]:
        _shadow_case(rt, cases, "in_shadow from (%g, %g, %g) (%s) toward the light at (%g, %g, %g)"
                     % (tuple(point) + (what,) + tuple(light)), shapes, point, light)
    return cases.result()


def observe_self_shadow(rt):
    """Points on the surfaces, found by intersecting eye rays as the renderer does, must not
    shadow themselves: the shadow ray leaves the surface."""
    cases = Cases()
    F = rt.Float3
    eye = (2.0, 1.5, 2.0)
    for target in [(1.0, 0.0, -1.0), (-1.2, 0.0, 0.7), (0.7, 0.0, 0.9), (-0.5, 0.0, -1.3), (1.3, 0.0, 0.2),
                   (0.1, 0.1, 0.6), (-0.1, 0.1, 0.5), (0.12, 0.72, 0.1), (0.0, 0.8, 0.05)]:
        def run(target=target):
            scene = rt.Scene(None)
            scene.shapes.extend(_default_shapes(rt))
            d = rt.float3.normalize(F(*target) - F(*eye))
            hit = rt.HitInfo()
            if not scene.intersect(rt.Ray(F(*eye), d), hit):
                return {"in shadow": "no surface hit"}
            p = [hit.position.x, hit.position.y, hit.position.z]
            return {"in shadow": _in_shadow(rt, scene, p, LIGHT)}
        cases.run("in_shadow from the surface point the eye ray toward (%g, %g, %g) hits, toward the light at (0, 1, 0)"
                  % target, run)
    return cases.result()


def _phong_cases(rt, setups):
    cases = Cases()
    F = rt.Float3
    for position, normal, eye, light, color, specular, shininess in setups:
        def run(position=position, normal=normal, eye=eye, light=light, color=color, specular=specular,
                shininess=shininess):
            scene = _shading_scene(rt, [(light, (math.pi, math.pi, math.pi))])
            material = rt.Phong(cs=F(*specular), exp=shininess)
            r = rt.Ray(F(*eye), rt.float3.normalize(F(*position) - F(*eye)))
            hit = _hit(rt, scene, r, position, normal, color, material=material)
            return {"L_o": vec(hit.material.shade(hit), "Phong.shade's result")}
        cases.run("Phong.shade at (%g, %g, %g), normal (%g, %g, %g), seen from (%g, %g, %g), light at (%g, %g, %g), "
                  "rho_s %g, s %g" % (tuple(position) + tuple(normal) + tuple(eye) + tuple(light)
                                      + (specular[0], shininess)), run)
    return cases.result()


def observe_phong(rt):
    top = (0.0, 0.8, 0.0)
    return _phong_cases(rt, [
        (top, (0, 1, 0), (0.0, 1.5, 0.3), LIGHT, (0, 0, 0), (0.1, 0.1, 0.1), 42.0),
        ((0.1, 0.78, 0.1), (0.1, 0.28, 0.1), (2.0, 1.5, 2.0), LIGHT, (0, 0, 0), (0.1, 0.1, 0.1), 42.0),
        ((0.5, 0.0, 0.5), (0, 1, 0), (-0.5, 1.0, -0.5), LIGHT, (0.1, 0.7, 0), (0.5, 0.5, 0.5), 10.0),
        ((0.5, 0.0, 0.5), (0, 1, 0), (2.0, 1.5, 2.0), LIGHT, (0.1, 0.7, 0), (0.3, 0.3, 0.3), 5.0),
    ])


# What the next ray sees, in the probes: a radiance no surface's own shading gives.
BEYOND = (0.25, 0.5, 0.75)


class _Traced:
    """A tracer that records the rays a material sends on (their origin, direction, interval and
    depth) and returns BEYOND for each; with ``run``, it ends each at that distance (its tmax,
    as a trace that found a hit there leaves it)."""

    def __init__(self, rt, run=None):
        self.rt, self.rays, self.run = rt, [], run
        self.samples_area_lights = False

    def trace_ray(self, ray, depth=0):
        self.rays.append({"origin": vec(ray.origin, "the traced ray's origin"),
                          "direction": vec(ray.direction, "the traced ray's direction"),
                          "tmin": num(ray.tmin, "the traced ray's tmin"), "tmax": num(ray.tmax, "the traced ray's tmax"),
                          "depth": depth})
        if self.run is not None:
            ray.tmax = self.run
        return self.rt.Float3(*BEYOND)


def _sends_on(rt, position, normal, origin, material):
    """shade of ``material`` hit at ``position`` by a ray from ``origin`` (depth 2), in a scene
    without lights whose tracer records the rays it is asked to trace."""
    F = rt.Float3
    scene = rt.Scene(None)
    tracer = _Traced(rt)
    scene.tracer = tracer
    r = rt.Ray(F(*origin), rt.float3.normalize(F(*position) - F(*origin)), 1e-5, 7.0)
    hit = _hit(rt, scene, r, position, normal, (0, 0, 0), material=material)
    hit.depth = 2
    result = vec(material.shade(hit), "shade's result")
    return {"returned": result, "traced": tracer.rays}


def observe_mirror(rt):
    cases = Cases()
    for position, normal, origin in [((0, 0, 0), (0, 1, 0), (1, 1, 0)), ((0, 0.8, 0), (0, 1, 0), (2, 1.5, 2)),
                                     ((0.3, 0.5, 0), (1, 0, 0), (2, 1.5, 2))]:
        def run(position=position, normal=normal, origin=origin):
            return _sends_on(rt, position, normal, origin, rt.Reflective())
        cases.run("Reflective.shade (a perfect mirror) at (%g, %g, %g) with normal (%g, %g, %g), ray from (%g, %g, %g)"
                  % (tuple(position) + tuple(normal) + tuple(origin)), run)
    return cases.result()


def observe_refraction(rt):
    cases = Cases()
    F = rt.Float3
    for position, normal, origin, ior, what in [
            ((0, 0.8, 0), (0, 1, 0), (1, 1.5, 0), 1.5, "entering glass"),
            ((0, 0.2, 0), (0, -1, 0), (0, 0.8, 0.2), 1.5, "leaving glass"),
            ((0.25, 0.5, 0), (0.8333333, 0, 0.5527708), (0, 0.5, 0.2), 1.5, "leaving glass beyond the critical angle: total internal reflection"),
            ((0, 0, 0), (0, 1, 0), (1, 1, 0), 1.33, "entering water")]:
        def run(position=position, normal=normal, origin=origin, ior=ior):
            return _sends_on(rt, position, normal, origin, rt.Transparent(ior=ior))
        cases.run("Transparent.shade (%s, ior %g) at (%g, %g, %g) with normal (%g, %g, %g), ray from (%g, %g, %g)"
                  % ((what, ior) + tuple(position) + tuple(normal) + tuple(origin)), run)
    return cases.result()
