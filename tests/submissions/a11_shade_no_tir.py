"""Dielectric.shade traces the refracted ray even under total internal reflection."""
ASSIGNMENT = "a11"
REPLACE = [
    ("materials/dielectric.py", "        if self.fresnel_btdf.tir(sr):\n            return L + L_r\n", ""),
]
