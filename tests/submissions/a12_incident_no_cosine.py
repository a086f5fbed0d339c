"""AreaLight.incident leaves out the cosine at the light: the lamp lights what lies behind it."""
ASSIGNMENT = "a12"
REPLACE = [
    ("lights/area_light.py", "        if not cos_l > 0.0:\n            return Float3(0.0)\n        return self.emission * (self.area * cos_l / (dist * dist))\n",
     "        return self.emission * (self.area / (dist * dist))\n"),
]
