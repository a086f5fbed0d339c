"""hemisphere_map takes cos(theta) = (1 - y)^(1 / e) instead of (1 - y)^(1 / (e + 1)): every density is off."""
ASSIGNMENT = "a09"
REPLACE = [
    ("sampling/maps.py", "    cos_theta = (1.0 - y) ** (1.0 / (e + 1.0))\n",
     "    cos_theta = (1.0 - y) ** (1.0 / e) if e > 0.0 else 1.0 - y\n"),
]
