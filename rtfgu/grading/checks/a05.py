"""a05: shadow rays, Phong, mirror and refraction (02562 weeks 2-3). The probes are in
rtfgu/grading/probes/a05.py (visible) and a05_hidden.py."""
from __future__ import annotations

from . import Check, image_check, register


def hint_shadow(inputs, want, got):
    if want.get("in shadow") is False and got.get("in shadow") is True:
        if "point" not in inputs:
            return ("this point on a surface is lit, but your shadow ray hits the surface it starts on "
                    "(shadow acne): start the shadow ray a little off the surface, tmin = SPAWN_EPSILON, "
                    "and end it before the light, tmax = dist - SPAWN_EPSILON")
        return "nothing lies between this point and the light: only hits with tmin <= t < dist - epsilon shadow it"
    if want.get("in shadow") is True and got.get("in shadow") is False:
        return "a shape lies between the point and the light: any hit along the shadow ray puts the point in shadow"
    return None


def hint_path(inputs, want, got):
    if got.get("r.tmax") is not None and got.get("r.tmax") != want.get("r.tmax"):
        return "the next ray of the path starts with a fresh interval: tmax = infinity (use _continue_path)"
    if got.get("hit.has_hit") is True and want.get("hit.has_hit") is False:
        return "clear hit.has_hit so that the path loop traces the next ray (use _continue_path)"
    if isinstance(got.get("r.direction"), list) and isinstance(want.get("r.direction"), list):
        g, w = got["r.direction"], want["r.direction"]
        if all(abs(a + b) < 1e-6 for a, b in zip(g, w)):
            return "your direction is reversed"
    return None


def hint_refraction(inputs, want, got):
    return hint_path(inputs, want, got) or (
        "check eta: entering (d . n < 0) eta = 1 / ior; leaving, eta = ior with the normal flipped; "
        "and mirror the ray when eta^2 (1 - cos_i^2) > 1 (total internal reflection)")


def _shaded(name, weight, sphere_shader, shadows, **options):
    """An image test of the 02562 default scene with ``sphere_shader`` on the sphere."""
    return image_check(name, weight, "default_scene", shaders=(sphere_shader, "LAMBERTIAN"), shadows=shadows,
                       **options)


register("a05_shadows_phong_mirror_refraction", [
    Check("in_shadow: occluders between the point and the light", 2, ("a05", "observe_occluders"), hint=hint_shadow),
    Check("in_shadow: a lit surface point does not shadow itself (no shadow acne)", 2,
          ("a05", "observe_self_shadow"), hint=hint_shadow),
    Check("phong: the normalised Phong lobe plus the diffuse term", 2, ("a05", "observe_phong"), rtol=1e-5),
    Check("mirror: the reflected ray continues the path", 1, ("a05", "observe_mirror"), hint=hint_path),
    Check("transparent: refraction by Snell's law and total internal reflection", 2, ("a05", "observe_refraction"),
          hint=hint_refraction),
    _shaded("image: 02562 default scene with shadows", 2, "LAMBERTIAN", True),
    _shaded("image: Phong sphere (no shadows)", 1, "PHONG", False),
    _shaded("image: mirror sphere (no shadows)", 1, "MIRROR", False),
    _shaded("image: refractive sphere (no shadows)", 1, "TRANSPARENT", False),
    # ### BEGIN HIDDEN
    _shaded("image: glossy sphere (no shadows)", 1, "GLOSSY", False, visibility="hidden"),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("in_shadow among several shapes", 1, ("a05_hidden", "observe_occluders_more"), visibility="hidden",
          hint=hint_shadow),
    # ### END HIDDEN
])
