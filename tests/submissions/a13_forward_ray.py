"""Instance.object_ray takes the ray through the forward matrix instead of the inverse."""
ASSIGNMENT = "a13"
REPLACE = [
    ("shapes/instance.py", "        return Ray(self.inv_matrix * ray.origin, self.inv_matrix.transform_vector(ray.direction),\n",
     "        return Ray(self.forward_matrix * ray.origin, self.forward_matrix.transform_vector(ray.direction),\n"),
]
