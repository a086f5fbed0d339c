"""fresnel_reflectance sums the two polarisations' reflectances instead of averaging them."""
ASSIGNMENT = "a11"
REPLACE = [
    ("brdfs/fresnel_reflector.py", "    return 0.5 * (r_perp * r_perp + r_par * r_par)\n",
     "    return r_perp * r_perp + r_par * r_par\n"),
]
