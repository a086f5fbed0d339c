"""BVH.intersect takes the farther child first and never skips a node whose box the ray enters beyond ray.tmax."""
ASSIGNMENT = "a08"
REPLACE = [
    ("accelerators/bvh.py", "            node = stack.pop()\n            t_enter = node.bbox.hit(ray)\n"
     "            if t_enter == math.inf or t_enter > ray.tmax:\n                continue\n",
     "            node = stack.pop()\n"),
    ("accelerators/bvh.py", "            stack.append(far)\n            stack.append(near)\n",
     "            stack.append(near)\n            stack.append(far)\n"),
]
