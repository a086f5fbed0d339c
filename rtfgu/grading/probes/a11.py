"""Probes of a11's visible tests: Fresnel's reflectance (``fresnel_reflectance``), Bouguer's
law (``transmittance``) and Whitted's dielectric (``Dielectric.shade``) (Suffern ch. 28;
02562 worksheet 8).

``Dielectric.shade`` runs at a chosen hit in a scene whose tracer (a05's) records the rays it
is asked to trace, says each ray ran RUN units before it hit something, and returns a05's
BEYOND for it: the answer is the rays and the radiance shade makes of them."""
from __future__ import annotations

import importlib

from .a04 import _hit
from .a05 import _Traced
from .support import Cases, image, num, vec

RUN = 2.0             # the distance every traced ray runs before it hits


def _fresnel(rt):
    return importlib.import_module(rt.__name__ + ".brdfs.fresnel_reflector")


def _dielectric(rt):
    return importlib.import_module(rt.__name__ + ".materials.dielectric")


def observe_fresnel(rt, cases):
    """fresnel_reflectance(cos_i, eta) for each (cos_i, eta)."""
    out = Cases()
    for cos_i, eta in cases:
        out.run("fresnel_reflectance(cos_i = %r, eta = %r)" % (cos_i, eta),
                lambda c=cos_i, e=eta: {"R": num(_fresnel(rt).fresnel_reflectance(c, e), "fresnel_reflectance's result")},
                cos_i=cos_i, eta=eta)
    return out.result()


def observe_transmittance(rt, cases):
    """transmittance(Float3(absorption), distance) for each (absorption, distance)."""
    out = Cases()
    for absorption, distance in cases:
        out.run("transmittance(absorption %s, distance %r)" % (tuple(absorption), distance),
                lambda a=absorption, s=distance: {"T": vec(_dielectric(rt).transmittance(rt.Float3(*a), s),
                                                           "transmittance's result")},
                absorption=list(absorption), distance=distance)
    return out.result()


def observe_dielectric(rt, cases):
    """Dielectric(ior, absorption).shade at (position, normal) hit by a ray from origin, depth 1."""
    out = Cases()
    F = rt.Float3
    for position, normal, origin, ior, absorption, what in cases:
        def run(position=position, normal=normal, origin=origin, ior=ior, absorption=absorption):
            scene = rt.Scene(None)
            tracer = _Traced(rt, RUN)
            scene.tracer = tracer
            r = rt.Ray(F(*origin), rt.float3.normalize(F(*position) - F(*origin)), 1e-5, 7.0)
            material = _dielectric(rt).Dielectric(ior=ior, absorption=absorption)
            hit = _hit(rt, scene, r, position, normal, (0, 0, 0), material=material)
            hit.depth = 1
            return {"returned": vec(material.shade(hit), "shade's result"), "traced": tracer.rays}
        out.run("Dielectric.shade (%s, ior %g, absorption %s) at %s with normal %s, ray from %s"
                % (what, ior, tuple(absorption), tuple(position), tuple(normal), tuple(origin)), run)
    return out.result()


def render_glass(rt, width: int, height: int):
    """The 02562 default scene with a tinted glass sphere (Dielectric, ior 1.5) seen close
    up, rendered by the lecture layer's pixel loop with Whitted's tracer."""
    scenes = importlib.import_module(rt.__name__ + ".scenes.default_scene")
    scene = scenes.default_scene(rt.LAMBERTIAN, rt.LAMBERTIAN, shadows=False)
    sphere = next(s for s in scene.shapes if type(s).__name__ == "Sphere")
    sphere.material = _dielectric(rt).Dielectric(ior=1.5, absorption=(0.9, 0.3, 0.05))
    scene.camera.d = 4.0          # the camera constant: the sphere fills the middle of the image
    return image(rt.renderer.render_reference(scene, width, height))
