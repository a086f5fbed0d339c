"""Matte's light loop drops the cosine term: f_r L_i, without n . w_i."""
ASSIGNMENT = "a04"
REPLACE = [
    ("materials/matte.py", "            L += self.f(sr, wo, wi) * L_i * ndotwi\n",
     "            L += self.f(sr, wo, wi) * L_i\n"),
]
