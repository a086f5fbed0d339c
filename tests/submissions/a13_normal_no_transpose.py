"""Matrix.transform_normal multiplies by the matrix itself, not by its transpose."""
ASSIGNMENT = "a13"
REPLACE = [
    ("matrix.py", "        return Float3(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z,\n"
                  "                      m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,\n"
                  "                      m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z)\n",
     "        return Float3(m[0][0] * n.x + m[0][1] * n.y + m[0][2] * n.z,\n"
     "                      m[1][0] * n.x + m[1][1] * n.y + m[1][2] * n.z,\n"
     "                      m[2][0] * n.x + m[2][1] * n.y + m[2][2] * n.z)\n"),
]
