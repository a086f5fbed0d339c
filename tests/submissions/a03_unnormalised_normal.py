"""Sphere.normal_at returns position - center without normalising it (length = radius)."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/sphere.py", "        return normalize(position - self.center)\n", "        return position - self.center\n"),
]
