// Ray-plane intersection (02562; lecture 01, "Ray-Plane Intersection"):
// t' = ((p0 - o) . n) / (w . n), written with A = o . n, B = w . n, C = p0 . n.
fn intersect_plane(r: Ray, hit: ptr<function, HitInfo>, position: vec3f, normal: vec3f) -> bool
{
    // ### BEGIN SOLUTION
    let A = dot(r.origin, normal);
    let B = dot(r.direction, normal);
    let C = dot(position, normal);
    if (B == 0.0) {
        return false;  // a ray parallel to the plane never meets it
    }
    let t = (C - A) / B;
    if (t >= r.tmin && t < r.tmax) {
        (*hit).has_hit = true;
        (*hit).dist = t;
        (*hit).position = r.origin + r.direction * t;
        (*hit).normal = normalize(normal);
        return true;
    }
    return false;
    // ### END SOLUTION
}
