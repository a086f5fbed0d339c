"""Lambertian.sample_f draws from the uniform hemisphere with its own pdf 1 / (2 pi): correct, only noisier."""
ASSIGNMENT = "a09"
REPLACE = [
    ("brdfs/lambertian.py", "        w_i = about(n, hemisphere_map(u, v, 1.0))\n        pdf = dot(n, w_i) / math.pi\n",
     "        w_i = about(n, hemisphere_map(u, v, 0.0))\n        pdf = 1.0 / (2.0 * math.pi)\n"),
]
