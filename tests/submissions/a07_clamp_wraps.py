"""ImageTexture.texel wraps the indices under clamp addressing too (i % width), so clamp reaches across to the opposite edge."""
ASSIGNMENT = "a07"
REPLACE = [
    ("textures/image_texture.py",
     "            i = min(max(i, 0), self.width - 1)\n            j = min(max(j, 0), self.height - 1)\n",
     "            i %= self.width\n            j %= self.height\n"),
]
