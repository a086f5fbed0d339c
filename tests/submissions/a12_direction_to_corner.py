"""AreaLight.get_direction always aims at the shape's first corner instead of the point drawn."""
ASSIGNMENT = "a12"
REPLACE = [
    ("lights/area_light.py", "        to_light = self.sample_point - sr.position\n        dist = to_light.length()\n        if not dist > 0.0:                   # the point lit is the point drawn: no direction\n",
     "        to_light = self.v0 - sr.position\n        dist = to_light.length()\n        if not dist > 0.0:                   # the point lit is the point drawn: no direction\n"),
]
