// Ray-triangle intersection with barycentric coordinates (02562, "Ray-triangle intersection"):
//   t' = ((v0 - o) . n) / (w . n)
//   beta = ((v0 - o) x w) . e1 / (w . n),  gamma = -((v0 - o) x w) . e0 / (w . n)
// The slide passes v: array<vec3f, 3>; rtfgu.layout stores v0 with e0 = v1 - v0, e1 = v2 - v0
// and n = e0 x e1 already computed, so every path uses the same rounded edges.
fn intersect_triangle(r: Ray, hit: ptr<function, HitInfo>, v0: vec3f, e0: vec3f, e1: vec3f, n: vec3f) -> bool
{
    // TODO a06: intersect_triangle
    //   a = v0 - r.origin, t' = (a . n) / (w . n), beta = ((a x w) . e1) / (w . n),
    //   gamma = -((a x w) . e0) / (w . n). Hit if t' in [tmin, tmax), beta >= 0, gamma >= 0
    //   and beta + gamma <= 1: fill *hit as for the plane (normal = normalize(n)).
    return TODO_a06_intersect_triangle;  // not written yet: replace this line with your code
}
