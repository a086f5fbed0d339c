"""a11: realistic transparency, Fresnel's reflectance, Bouguer's absorption and Whitted's
dielectric (Suffern ch. 28, "Realistic Transparency"; 02562 worksheet 8). The probes are in
rtfgu/grading/probes/a11.py.

The reflectance is checked at angles where Fresnel's equations give known values (head on
((1 - eta) / (1 + eta))^2 = 0.04 for glass, Brewster's angle where r_par = 0, grazing, and
beyond the critical angle, 1), the hints comparing with the known slips of
rtfgu.grading.mistakes (summed instead of averaged, r_perp alone, eta turned over, Schlick's
approximation); Bouguer's law at chosen distances; Dielectric.shade by the rays it sends and
the radiance it makes of them; and a glass sphere rendered by Whitted's tracer.
"""
from __future__ import annotations


from ..probes.a05 import BEYOND
from . import Check, close, known_mistake_hint, register

FRESNEL = ("brdfs/fresnel_reflector.py",)
DIELECTRIC = ("materials/dielectric.py",)
GLASS = 1.0 / 1.5
BREWSTER = (1.0 + 1.5 * 1.5) ** -0.5           # cos(theta_B), tan(theta_B) = n2 / n1 = 1.5


def _same(a, b) -> bool:
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(u, v) for u, v in zip(a, b))
    return isinstance(a, float) and isinstance(b, float) and close(a, b, 1e-6, 1e-9)


FRESNEL_SLIPS = (
    ("summed", "your R is r_perp^2 + r_par^2: unpolarised light reflects their mean, (r_perp^2 + r_par^2) / 2"),
    ("perp_only", "your R is r_perp^2 alone: unpolarised light reflects the mean of r_perp^2 and r_par^2"),
    ("inverted_eta", "your R is the one for eta turned over: eta = n1 / n2 is the index of the side the light "
                     "comes from over the other (entering glass from air 1 / 1.5)"),
    ("schlick", "this is Schlick's approximation R0 + (1 - R0)(1 - cos_i)^5; the test asks for Fresnel's "
                "equations themselves"),
)


def hint_fresnel(inputs, want, got):
    hint = known_mistake_hint(FRESNEL_SLIPS, inputs, want, got, "R", _same)
    if hint:
        return hint
    R = got.get("R")
    sin2_t = inputs["eta"] ** 2 * (1.0 - inputs["cos_i"] ** 2)
    if want["R"] == 1.0 and sin2_t >= 1.0 and R != 1.0:
        return ("here eta^2 (1 - cos_i^2) = %.6g >= 1: the light cannot leave, total internal reflection, so R is 1"
                % sin2_t)
    if isinstance(R, float) and not 0.0 <= R <= 1.0:
        return "a reflectance is a fraction of the light, between 0 and 1"
    return None


BOUGUER_SLIPS = (
    ("plus", "your transmittance grows with the distance: Bouguer's law is exp(-sigma_a s), with the minus sign"),
    ("linear", "this is 1 - sigma_a s, the law's first-order line; Bouguer's law is exp(-sigma_a s)"),
)


def hint_bouguer(inputs, want, got):
    return known_mistake_hint(BOUGUER_SLIPS, inputs, want, got, "T", _same)


def hint_dielectric(inputs, want, got):
    traced, expected = got.get("traced"), want.get("traced")
    if isinstance(traced, list) and isinstance(expected, list) and len(traced) != len(expected):
        if len(expected) == 1:
            return ("here the ray is inside beyond the critical angle (fresnel_btdf.tir(sr) is true): only the "
                    "reflected ray goes on, %d were traced" % len(traced))
        return "shade should trace %d rays here (the reflected and the refracted one), it traced %d" % (
            len(expected), len(traced))
    returned = got.get("returned")
    if isinstance(returned, list) and _same(returned, list(BEYOND)) and not _same(want["returned"], returned):
        return ("your result is the traced rays' radiance unweighted and unattenuated: weigh the reflected one by "
                "R and the refracted one by 1 - R, and attenuate a ray that runs inside (self._through)")
    return None


FRESNEL_CASES = [(1.0, GLASS), (1.0, 1.5), (BREWSTER, GLASS), (0.5, GLASS), (0.2, 1.0 / 1.33), (0.001, GLASS),
                 (0.8, 1.5), (0.7, 1.5), (0.5, 1.5)]
BOUGUER_CASES = [((0.0, 0.0, 0.0), 3.0), ((0.5, 1.0, 2.0), 0.0), ((0.5, 1.0, 2.0), 2.0), ((0.1, 0.2, 0.3), 0.5)]
# (position, normal, origin, ior, absorption, what): the sphere-like hits of a05's refraction tests.
DIELECTRIC_CASES = [
    ((0, 0.8, 0), (0, 1, 0), (1, 1.5, 0), 1.5, (0.3, 0.2, 0.1), "entering glass"),
    ((0, 0.8, 0), (0, 1, 0), (0, 1.5, 0), 1.5, (0.0, 0.0, 0.0), "entering clear glass head on"),
    ((0, 0.2, 0), (0, -1, 0), (0, 0.8, 0.2), 1.5, (0.3, 0.2, 0.1), "leaving glass"),
    ((0.25, 0.5, 0), (0.8333333, 0, 0.5527708), (0, 0.5, 0.2), 1.5, (0.3, 0.2, 0.1),
     "inside glass beyond the critical angle"),
]

register("a11_realistic_transparency", [
    Check("fresnel_reflectance: head on, at Brewster's angle, grazing and beyond the critical angle", 3,
          ("a11", "observe_fresnel", dict(cases=FRESNEL_CASES)), hint=hint_fresnel, known="fresnel", needs=FRESNEL),
    Check("transmittance: Bouguer's law exp(-sigma_a s), per channel", 1,
          ("a11", "observe_transmittance", dict(cases=BOUGUER_CASES)), hint=hint_bouguer, known="bouguer",
          needs=DIELECTRIC),
    Check("Dielectric.shade: the reflected and refracted rays, weighted by R and 1 - R, attenuated inside", 3,
          ("a11", "observe_dielectric", dict(cases=DIELECTRIC_CASES)), hint=hint_dielectric),
    Check("image: a glass sphere in the 02562 default scene, Whitted's tracer", 2,
          ("a11", "render_glass", dict(width=48, height=48)), kind="image", size=(48, 48)),
    # ### BEGIN HIDDEN
    Check("fresnel_reflectance: water and diamond, just below and above the critical angle", 1,
          ("a11", "observe_fresnel", dict(cases=[(0.9, 1.0 / 1.33), (0.3, 1.0 / 2.42), (0.67, 1.33), (0.66, 1.33),
                                                  (0.915, 2.42), (0.91, 2.42)])),
          hint=hint_fresnel, known="fresnel", visibility="hidden", needs=FRESNEL),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("Dielectric.shade in water and diamond", 1,
          ("a11", "observe_dielectric", dict(cases=[
              ((0, 0, 0), (0, 1, 0), (1, 1, 0), 1.33, (0.05, 0.02, 0.01), "entering water"),
              ((0, 0.2, 0), (0, -1, 0), (0.3, 0.8, 0.2), 2.42, (0.0, 0.1, 0.0), "leaving diamond")])),
          hint=hint_dielectric, visibility="hidden"),
    # ### END HIDDEN
])
