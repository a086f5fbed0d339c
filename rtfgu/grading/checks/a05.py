"""a05: shadow rays, Phong, mirror and refraction (02562 weeks 2-3). The probes are in
rtfgu/grading/probes/a05.py (visible) and a05_hidden.py."""
from __future__ import annotations

from . import Check, image_check, register


def hint_shadow(inputs, want, got):
    if want.get("in shadow") is False and got.get("in shadow") is True:
        if "point" not in inputs:
            return ("this point on a surface is lit, but your shadow ray hits the surface it starts on "
                    "(shadow acne): start the shadow ray a little off the surface, ray.tmin = SPAWN_EPSILON, "
                    "and end it before the light, ray.tmax = self.distance(sr) - SPAWN_EPSILON")
        return "nothing lies between this point and the light: only hits with tmin <= t < dist - epsilon shadow it"
    if want.get("in shadow") is True and got.get("in shadow") is False:
        return "a shape lies between the point and the light: any hit along the shadow ray puts the point in shadow"
    return None


def hint_path(inputs, want, got):
    """Hints on the ray a material sends on ("traced": what the probe's tracer was asked)."""
    traced, expected = got.get("traced"), want.get("traced")
    if not isinstance(traced, list) or not isinstance(expected, list):
        return None
    if not traced and expected:
        return "shade must trace the next ray: sr.scene.tracer.trace_ray(ray, sr.depth + 1), and add what it sees"
    if not traced or not expected or not isinstance(traced[0], dict):
        return None
    g, w = traced[0], expected[0]
    if g.get("depth") != w.get("depth"):
        return "trace the next ray one level deeper than the hit: depth sr.depth + 1"
    if g.get("tmax") != w.get("tmax"):
        return "a new ray starts with a fresh interval: Ray(sr.position, w, SPAWN_EPSILON), whose tmax is infinity"
    if g.get("tmin") != w.get("tmin"):
        return "start the new ray SPAWN_EPSILON off the surface: Ray(sr.position, w, SPAWN_EPSILON)"
    if isinstance(g.get("direction"), list) and isinstance(w.get("direction"), list):
        if all(abs(a + b) < 1e-6 for a, b in zip(g["direction"], w["direction"])):
            return "your direction is reversed"
    if g.get("direction") == w.get("direction") and got.get("returned") != want.get("returned"):
        return "the ray is right; add the light it brings back: L + fr * L_r * specular_scale(|n . w|, pdf)"
    return None


def hint_refraction(inputs, want, got):
    return hint_path(inputs, want, got) or (
        "check PerfectTransmitter.transmitted_direction's eta: entering (d . n < 0) eta = 1 / ior; leaving, "
        "eta = ior with the normal flipped; and mirror the ray when eta^2 (1 - cos_i^2) > 1 (total internal "
        "reflection)")


def _shaded(name, weight, sphere_shader, shadows, **options):
    """An image test of the 02562 default scene with ``sphere_shader`` on the sphere."""
    return image_check(name, weight, "default_scene", shaders=(sphere_shader, "LAMBERTIAN"), shadows=shadows,
                       **options)


register("a05_shadows_phong_mirror_refraction", [
    Check("Light.in_shadow: occluders between the point and the light", 2, ("a05", "observe_occluders"),
          hint=hint_shadow),
    Check("Light.in_shadow: a lit surface point does not shadow itself (no shadow acne)", 2,
          ("a05", "observe_self_shadow"), hint=hint_shadow),
    Check("Phong: the normalised glossy lobe (GlossySpecular.f) plus the diffuse term", 2, ("a05", "observe_phong"),
          rtol=1e-5),
    Check("Reflective.shade: the mirror traces its reflected ray one level deeper", 1, ("a05", "observe_mirror"),
          hint=hint_path),
    Check("Transparent: refraction by Snell's law and total internal reflection", 2, ("a05", "observe_refraction"),
          hint=hint_refraction),
    _shaded("image: 02562 default scene with shadows", 2, "LAMBERTIAN", True),
    _shaded("image: Phong sphere (no shadows)", 1, "PHONG", False),
    _shaded("image: mirror sphere (no shadows)", 1, "MIRROR", False),
    _shaded("image: refractive sphere (no shadows)", 1, "TRANSPARENT", False),
    # ### BEGIN HIDDEN
    _shaded("image: glossy sphere (no shadows)", 1, "GLOSSY", False, visibility="hidden"),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("Light.in_shadow among several shapes", 1, ("a05_hidden", "observe_occluders_more"), visibility="hidden",
          hint=hint_shadow),
    # ### END HIDDEN
])
