"""Lambertian.sample_f draws cosine-weighted directions but returns the uniform hemisphere's pdf, 1 / (2 pi): biased."""
ASSIGNMENT = "a09"
REPLACE = [
    ("brdfs/lambertian.py", "        pdf = dot(n, w_i) / math.pi\n", "        pdf = 1.0 / (2.0 * math.pi)\n"),
]
