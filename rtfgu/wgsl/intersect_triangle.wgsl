// Ray-triangle intersection with barycentric coordinates (02562, "Ray-triangle intersection"):
//   t' = ((v0 - o) . n) / (w . n)
//   beta = ((v0 - o) x w) . e1 / (w . n),  gamma = -((v0 - o) x w) . e0 / (w . n)
// The slide passes v: array<vec3f, 3>; rtfgu.layout stores v0 with e0 = v1 - v0, e1 = v2 - v0
// and n = e0 x e1 already computed, so every path uses the same rounded edges.
fn intersect_triangle(r: Ray, hit: ptr<function, HitInfo>, v0: vec3f, e0: vec3f, e1: vec3f, n: vec3f) -> bool
{
    // ### BEGIN SOLUTION
    let denom = dot(r.direction, n);
    if (denom == 0.0) {
        return false;  // the ray is parallel to the triangle's plane
    }
    let a = v0 - r.origin;
    let t = dot(a, n) / denom;
    if (!(t >= r.tmin && t < r.tmax)) {
        return false;
    }
    let c = cross(a, r.direction);
    let beta = dot(c, e1) / denom;
    let gamma = -dot(c, e0) / denom;
    if (beta >= 0.0 && gamma >= 0.0 && beta + gamma <= 1.0) {
        (*hit).has_hit = true;
        (*hit).dist = t;
        (*hit).position = r.origin + r.direction * t;
        (*hit).normal = normalize(n);
        return true;
    }
    return false;
    // ### END SOLUTION
}
