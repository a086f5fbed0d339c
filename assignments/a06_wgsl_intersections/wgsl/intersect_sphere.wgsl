// Ray-sphere intersection (lecture 01, "Ray-Sphere Intersection"; 02562):
// a t^2 + b t + c = 0 with a = w . w, b = 2 (o - c) . w, c = (o - c) . (o - c) - r^2.
fn intersect_sphere(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, radius: f32) -> bool
{
    // TODO a06: intersect_sphere
    //   a = w . w, b = 2 (o - c) . w, c = (o - c) . (o - c) - r^2, disc = b^2 - 4ac.
    //   No hit if disc < 0; else the first of (-b - sqrt(disc)) / 2a and (-b + sqrt(disc)) / 2a
    //   in [tmin, tmax): fill *hit, normal = normalize(position - center).
    return TODO_a06_intersect_sphere;  // not written yet: replace this line with your code
}
