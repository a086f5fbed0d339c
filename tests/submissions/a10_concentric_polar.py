"""concentric_map is the polar map r = sqrt(x), phi = 2 pi y: uniform on the disk, but not the concentric map."""
ASSIGNMENT = "a10"
REPLACE = [
    ("sampling/maps.py", "    sx = 2.0 * x - 1.0\n",
     "    return math.sqrt(x) * math.cos(2.0 * math.pi * y), math.sqrt(x) * math.sin(2.0 * math.pi * y)\n"
     "    sx = 2.0 * x - 1.0\n"),
]
