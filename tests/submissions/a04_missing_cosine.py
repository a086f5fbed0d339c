"""lambertian drops the cosine term: rho_d / pi * L_i, without cos(theta)."""
ASSIGNMENT = "a04"
REPLACE = [
    ("shading.py", "        result += rho_d / math.pi * sample.L_i * cos_theta\n",
     "        result += rho_d / math.pi * sample.L_i\n"),
]
