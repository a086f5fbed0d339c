"""MultiJittered.generate_samples jitters with Python's random.random() instead of the sampler's stream."""
ASSIGNMENT = "a10"
REPLACE = [
    ("sampling/multi_jittered.py",
     "            self.samples.append(((i * n + j) * subcell + self.rand_float() * subcell,\n",
     "            import random\n"
     "            self.samples.append(((i * n + j) * subcell + random.random() * subcell,\n"),
]
