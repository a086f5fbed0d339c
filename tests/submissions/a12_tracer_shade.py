"""AreaLighting.shade calls the material's shade, as Whitted does, instead of area_light_shade."""
ASSIGNMENT = "a12"
REPLACE = [
    ("tracers/area_lighting.py", "        return sr.material.area_light_shade(sr)\n", "        return sr.material.shade(sr)\n"),
]
