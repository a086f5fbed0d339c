"""Instance._compose multiplies the inverses in the order of the calls: inverse * inv_matrix."""
ASSIGNMENT = "a13"
REPLACE = [
    ("shapes/instance.py", "        self.inv_matrix = self.inv_matrix * inverse\n",
     "        self.inv_matrix = inverse * self.inv_matrix\n"),
]
