"""AreaLight.pdf returns the area A, not the density 1 / A."""
ASSIGNMENT = "a12"
REPLACE = [
    ("lights/area_light.py", "        return 1.0 / self.area\n", "        return self.area\n"),
]
