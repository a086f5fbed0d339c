"""Box.intersect_p always takes t0: a ray that starts inside the box misses it."""
ASSIGNMENT = "a08"
REPLACE = [
    ("shapes/box.py", "        t_hit = t0 if t0 >= ray.tmin else t1   # from inside the box: where it leaves\n",
     "        t_hit = t0\n"),
]
