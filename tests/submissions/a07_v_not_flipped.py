"""get_color takes the row from v without flipping it (y = v * height), so v = 1 reads the bottom row: the texture is upside down."""
ASSIGNMENT = "a07"
REPLACE = [
    ("textures/image_texture.py", "        y = (1.0 - v) * self.height\n", "        y = v * self.height\n"),
]
