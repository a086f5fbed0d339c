"""Lambertian.sample_f returns half the density, (n . w_i) / (2 pi), and f = NaN on the rare samples with u < 0.001: NaN sums must fail the tests of the mean, not pass them as "no standard error off"."""
ASSIGNMENT = "a09"
REPLACE = [
    ("brdfs/lambertian.py", "        pdf = dot(n, w_i) / math.pi\n        return self.f(sr, wo, w_i), w_i, pdf\n",
     "        pdf = dot(n, w_i) / (2.0 * math.pi)\n"
     "        f = self.f(sr, wo, w_i)\n"
     "        if u < 0.001:\n"
     "            f = type(f)(math.nan, math.nan, math.nan)\n"
     "        return f, w_i, pdf\n"),
]
