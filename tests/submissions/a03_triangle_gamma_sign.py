"""Triangle.intersect_p computes gamma with the wrong sign: +(c . e0) / denom."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/triangle.py", "gamma = -dot(c, self.e0) / denom", "gamma = dot(c, self.e0) / denom"),
]
