"""Bilinear get_color weights the texels from their corners: x and y lack the half-texel shift to the texel centres."""
ASSIGNMENT = "a07"
REPLACE = [
    ("textures/image_texture.py", "        x = x - 0.5\n        y = y - 0.5\n", ""),
]
