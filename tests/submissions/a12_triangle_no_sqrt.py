"""Triangle.sample leaves out the square root of u: the points crowd toward v0."""
ASSIGNMENT = "a12"
REPLACE = [
    ("shapes/triangle.py", "        su = math.sqrt(u)\n", "        su = u\n"),
]
