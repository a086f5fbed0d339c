"""Matrix.transform_vector adds the translation, as for a point: directions move."""
ASSIGNMENT = "a13"
REPLACE = [
    ("matrix.py", "        return Float3(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,\n"
                  "                      m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,\n"
                  "                      m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z)\n",
     "        return Float3(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z + m[0][3],\n"
     "                      m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z + m[1][3],\n"
     "                      m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z + m[2][3])\n"),
]
