"""Lambertian.sample_f returns pdf / (1 + 0.9 sin(2 phi)), phi about the probe's tangent: up to 10x off, cancelling in every g of the estimator test."""
ASSIGNMENT = "a09"
REPLACE = [
    ("brdfs/lambertian.py", "        pdf = dot(n, w_i) / math.pi\n",
     "        a = (1.0, 0.0, 0.0) if abs(n.x) < 0.9 else (0.0, 1.0, 0.0)\n"
     "        t = (n.y * a[2] - n.z * a[1], n.z * a[0] - n.x * a[2], n.x * a[1] - n.y * a[0])\n"
     "        b = (n.y * t[2] - n.z * t[1], n.z * t[0] - n.x * t[2], n.x * t[1] - n.y * t[0])\n"
     "        phi = math.atan2(w_i.x * b[0] + w_i.y * b[1] + w_i.z * b[2], w_i.x * t[0] + w_i.y * t[1] + w_i.z * t[2])\n"
     "        pdf = dot(n, w_i) / math.pi / (1.0 + 0.9 * math.sin(2.0 * phi))\n"),
]
