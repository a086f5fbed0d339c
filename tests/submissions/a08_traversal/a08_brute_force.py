"""BVH.intersect ignores the tree and tests every shape in turn: the right hits, at the cost of no BVH at all."""
ASSIGNMENT = "a08"
REPLACE = [
    ("accelerators/bvh.py", "        if self.root is None:\n            return best\n        stack = [self.root]\n",
     "        for i, shape in enumerate(self.shapes):\n"
     "            if shape.intersect_p(ray):\n"
     "                best = i\n"
     "        return best\n"
     "        stack = [self.root]\n"),
]
