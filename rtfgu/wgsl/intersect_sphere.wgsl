// Ray-sphere intersection (lecture 01, "Ray-Sphere Intersection"; 02562):
// a t^2 + b t + c = 0 with a = w . w, b = 2 (o - c) . w, c = (o - c) . (o - c) - r^2.
fn intersect_sphere(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, radius: f32) -> bool
{
    // ### BEGIN SOLUTION
    let temp = r.origin - center;
    let a = dot(r.direction, r.direction);
    let b = 2.0 * dot(temp, r.direction);
    let c = dot(temp, temp) - radius * radius;
    let disc = b * b - 4.0 * a * c;
    if (disc < 0.0) {
        return false;
    }
    let e = sqrt(disc);
    let denom = 2.0 * a;
    // The least t in [tmin, tmax): the near root first, then the far one (a ray that
    // starts inside the sphere hits the far root).
    var t = (-b - e) / denom;
    if (!(t >= r.tmin && t < r.tmax)) {
        t = (-b + e) / denom;
        if (!(t >= r.tmin && t < r.tmax)) {
            return false;
        }
    }
    (*hit).has_hit = true;
    (*hit).dist = t;
    (*hit).position = r.origin + r.direction * t;
    (*hit).normal = normalize((*hit).position - center);
    return true;
    // ### END SOLUTION
}
