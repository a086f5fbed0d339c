"""Triangle.intersect_p accepts a hit at t = tmax: tmin <= t <= tmax instead of t < tmax."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/triangle.py", "if not (t >= ray.tmin and t < ray.tmax):", "if not (t >= ray.tmin and t <= ray.tmax):"),
]
