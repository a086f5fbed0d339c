"""Sphere.intersect_p assumes a unit direction: a = 1 in the quadratic."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/sphere.py", "        a = dot(ray.direction, ray.direction)\n", "        a = 1.0\n"),
]
