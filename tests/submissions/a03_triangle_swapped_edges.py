"""Triangle.intersect_p swaps the edges in beta and gamma: beta from e0, gamma from e1."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/triangle.py", "beta = dot(c, self.e1) / denom", "beta = dot(c, self.e0) / denom"),
    ("shapes/triangle.py", "gamma = -dot(c, self.e0) / denom", "gamma = -dot(c, self.e1) / denom"),
]
