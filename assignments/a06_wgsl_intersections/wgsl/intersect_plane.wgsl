// Ray-plane intersection (02562; lecture 01, "Ray-Plane Intersection"):
// t' = ((p0 - o) . n) / (w . n), written with A = o . n, B = w . n, C = p0 . n.
fn intersect_plane(r: Ray, hit: ptr<function, HitInfo>, position: vec3f, normal: vec3f) -> bool
{
    // TODO a06: intersect_plane
    //   t' = ((position - r.origin) . normal) / (r.direction . normal); a ray parallel to the
    //   plane misses. On a hit with r.tmin <= t' < r.tmax set (*hit).has_hit = true,
    //   dist = t', position = r.origin + r.direction * t', normal = normalize(normal);
    //   return true. Otherwise return false and leave *hit alone.
    return TODO_a06_intersect_plane;  // not written yet: replace this line with your code
}
