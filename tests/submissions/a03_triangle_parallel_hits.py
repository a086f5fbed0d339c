"""Triangle.intersect_p reports a hit for a ray parallel to the triangle's plane."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/triangle.py", "            return False  # the ray is parallel to the triangle's plane\n",
     "            return True  # the ray is parallel to the triangle's plane\n"),
]
