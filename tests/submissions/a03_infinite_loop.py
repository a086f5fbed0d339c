"""Triangle.normal_at never returns (an endless loop in place of its body)."""
ASSIGNMENT = "a03"
REPLACE = [
    ("shapes/triangle.py", "        return normalize(self.n)\n", "        while True:  # never ends\n            pass\n"),
]
