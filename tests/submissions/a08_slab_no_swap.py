"""BBox.hit never swaps t_near and t_far, so along a negative direction component t_near > t_far and the box is always missed."""
ASSIGNMENT = "a08"
REPLACE = [
    ("accelerators/bbox.py", "            if t_near > t_far:\n                t_near, t_far = t_far, t_near\n", ""),
]
