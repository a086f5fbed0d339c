"""hemisphere_map ignores (x, y) and draws its own random.random(): the right density, but not a function of its sample."""
ASSIGNMENT = "a09"
REPLACE = [
    ("sampling/maps.py", "import math\n", "import math\nimport random\n"),
    ("sampling/maps.py", "    cos_phi = math.cos(2.0 * math.pi * x)\n",
     "    x, y = random.random(), random.random()\n    cos_phi = math.cos(2.0 * math.pi * x)\n"),
]
