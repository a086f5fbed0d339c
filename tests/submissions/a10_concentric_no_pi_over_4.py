"""concentric_map forgets to turn phi from eighths of a turn into radians (no pi / 4)."""
ASSIGNMENT = "a10"
REPLACE = [
    ("sampling/maps.py", "    phi *= math.pi / 4.0\n", "    phi *= 1.0\n"),
]
