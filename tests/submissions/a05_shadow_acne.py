"""in_shadow starts the shadow ray at the surface (tmin 0, tmax dist): no SPAWN_EPSILON offset, so shadow acne."""
ASSIGNMENT = "a05"
REPLACE = [
    ("shading.py", "    shadow_ray = Ray(position, w_i, SPAWN_EPSILON, dist - SPAWN_EPSILON)\n",
     "    shadow_ray = Ray(position, w_i, 0.0, dist)\n"),
]
