"""MultiJittered.generate_samples starts y in subcell i n + j, as x, instead of j n + i: the points crowd the grid's diagonal cells."""
ASSIGNMENT = "a10"
REPLACE = [
    ("sampling/multi_jittered.py", "                                 (j * n + i) * subcell + self.rand_float() * subcell))",
     "                                 (i * n + j) * subcell + self.rand_float() * subcell))"),
]
