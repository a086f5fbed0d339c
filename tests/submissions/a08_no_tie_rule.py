"""BVH.intersect tests every shape of a leaf with plain intersect_p, so of equal hits the one met first wins, not the earlier shape."""
ASSIGNMENT = "a08"
REPLACE = [
    ("accelerators/bvh.py",
     "                    if best < 0 or i > best:\n"
     "                        if self.shapes[i].intersect_p(ray):\n"
     "                            best = i\n"
     "                    else:   # an earlier shape also wins at the same t\n"
     "                        tmax = ray.tmax\n"
     "                        ray.tmax = math.nextafter(tmax, math.inf)\n"
     "                        if self.shapes[i].intersect_p(ray):\n"
     "                            best = i\n"
     "                        else:\n"
     "                            ray.tmax = tmax\n",
     "                    if self.shapes[i].intersect_p(ray):\n"
     "                        best = i\n"),
]
