"""Dielectric.shade weighs the reflected ray by 1 - R and the refracted one by R."""
ASSIGNMENT = "a11"
REPLACE = [
    ("materials/dielectric.py", "        return L + fr * L_r + ft * L_t\n", "        return L + ft * L_r + fr * L_t\n"),
]
