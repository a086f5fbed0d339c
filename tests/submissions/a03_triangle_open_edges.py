"""Triangle.intersect_p leaves out its edge v1 v2: beta + gamma < 1 instead of <= 1."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/triangle.py", "beta + gamma <= 1.0:", "beta + gamma < 1.0:"),
]
