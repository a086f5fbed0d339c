"""transmittance loses the minus sign of Bouguer's law: exp(+sigma_a s)."""
ASSIGNMENT = "a11"
REPLACE = [
    ("materials/dielectric.py", "    return Float3(math.exp(-absorption.x * distance), math.exp(-absorption.y * distance),\n"
                                "                  math.exp(-absorption.z * distance))\n",
     "    return Float3(math.exp(absorption.x * distance), math.exp(absorption.y * distance),\n"
     "                  math.exp(absorption.z * distance))\n"),
]
