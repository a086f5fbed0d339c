"""Instance.object_ray normalises the object-space direction, so the object's t is not the world ray's."""
ASSIGNMENT = "a13"
REPLACE = [
    ("shapes/instance.py", "        return Ray(self.inv_matrix * ray.origin, self.inv_matrix.transform_vector(ray.direction),\n",
     "        return Ray(self.inv_matrix * ray.origin, normalize(self.inv_matrix.transform_vector(ray.direction)),\n"),
]
