"""fresnel_reflectance is Schlick's approximation (and 1 beyond the critical angle), not Fresnel's equations."""
ASSIGNMENT = "a11"
REPLACE = [
    ("brdfs/fresnel_reflector.py", "    cos_t = math.sqrt(1.0 - sin2_t)\n",
     "    r0 = ((1.0 - eta) / (1.0 + eta)) ** 2\n    return r0 + (1.0 - r0) * (1.0 - cos_i) ** 5\n"
     "    cos_t = math.sqrt(1.0 - sin2_t)\n"),
]
