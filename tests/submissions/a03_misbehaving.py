"""Plane.intersect_p allocates 64 GB, Triangle.intersect_p prints megabytes, Sphere.intersect_p returns 0 and Sphere.normal_at a tuple."""
ASSIGNMENT = "a03"
DEF = "    def intersect_p(self, ray: Ray) -> bool:\n"
REPLACE = [
    ("shapes/plane.py", DEF, DEF + "        hoard = [bytearray(64 * 1024 * 1024) for _ in range(1000)]  # 64 GB\n"),
    ("shapes/triangle.py", DEF,
     DEF + "        for _ in range(200000):\n            print('debugging the triangle ' * 10)\n"),
    ("shapes/sphere.py", "        if disc < 0.0:\n            return False\n", "        if disc < 0.0:\n            return 0\n"),
    ("shapes/sphere.py", "        return normalize(position - self.center)\n",
     "        n = normalize(position - self.center)\n        return (n.x, n.y, n.z)\n"),
]
