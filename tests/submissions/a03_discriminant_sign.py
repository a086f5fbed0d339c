"""Sphere.intersect_p computes the discriminant as b^2 + 4ac instead of b^2 - 4ac."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/sphere.py", "disc = b * b - 4 * a * c", "disc = b * b + 4 * a * c"),
]
