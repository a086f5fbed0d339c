"""Sphere.intersect_p overwrites the file named by RTFGU_ATTACK_PATH (a grader reference file in the test)."""
ASSIGNMENT = "a03"
DEF = "    def intersect_p(self, ray: Ray) -> bool:\n"
REPLACE = [
    ("shapes/sphere.py", DEF,
     DEF + "        import os\n        target = os.environ.get('RTFGU_ATTACK_PATH')\n        if target:\n"
           "            with open(target, 'w') as f:\n                f.write('{}')\n"),
]
