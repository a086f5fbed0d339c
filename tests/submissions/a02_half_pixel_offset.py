"""The orthographic camera adds half a pixel (of a 64-pixel image) to sx and sy, although gen_ray's samples already sit at pixel centres."""
ASSIGNMENT = "a02"
REPLACE = [
    ("cameras/orthographic.py",
     "        sx = 0.5 + sx / 2\n        sy = 0.5 + sy / 2\n",
     "        # shift to the centre of the pixel (half a pixel of a 64-pixel image)\n"
     "        sx = 0.5 + sx / 2 + 0.5 / 64\n        sy = 0.5 + sy / 2 + 0.5 / 64\n"),
]
