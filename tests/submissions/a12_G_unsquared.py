"""AreaLight.G divides the cosine by the distance, not by its square (and incident with it)."""
ASSIGNMENT = "a12"
REPLACE = [
    ("lights/area_light.py", "        return max(self._cos_l(sr), 0.0) / d2 if d2 > 0.0 else 0.0\n",
     "        return max(self._cos_l(sr), 0.0) / d2 ** 0.5 if d2 > 0.0 else 0.0\n"),
    ("lights/area_light.py", "        return self.emission * (self.area * cos_l / (dist * dist))\n",
     "        return self.emission * (self.area * cos_l / dist)\n"),
]
