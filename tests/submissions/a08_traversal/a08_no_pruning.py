"""BVH.intersect visits every node without testing a box (BBox.hit is never called): the right hits, every shape tested."""
ASSIGNMENT = "a08"
REPLACE = [
    ("accelerators/bvh.py", "            node = stack.pop()\n            t_enter = node.bbox.hit(ray)\n"
     "            if t_enter == math.inf or t_enter > ray.tmax:\n                continue\n",
     "            node = stack.pop()\n"),
    ("accelerators/bvh.py", "            if far.bbox.hit(ray) < near.bbox.hit(ray):\n                near, far = far, near\n", ""),
]
