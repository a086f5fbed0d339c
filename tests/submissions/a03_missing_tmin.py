"""Sphere.intersect_p accepts both roots below ray.tmin (it checks only t < ray.tmax)."""
ASSIGNMENT = "a03"
# Both root checks in one text: each line alone occurs twice in sphere.py.
REPLACE = [
    ("shapes/sphere.py",
     "            if t >= ray.tmin and t < ray.tmax:\n                ray.tmax = t\n                return True\n\n"
     "            t = (-b + e) / denom\n            if t >= ray.tmin and t < ray.tmax:\n",
     "            if t < ray.tmax:\n                ray.tmax = t\n                return True\n\n"
     "            t = (-b + e) / denom\n            if t < ray.tmax:\n"),
]
