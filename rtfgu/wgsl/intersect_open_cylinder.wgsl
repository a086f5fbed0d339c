// Ray-open-cylinder intersection (Suffern ch. 19, "Open cylinders"; rtfgu.shapes.open_cylinder):
// a t^2 + b t + c = 0 with a = w_x^2 + w_z^2, b = 2 (o_x w_x + o_z w_z), c = o_x^2 + o_z^2 - r^2,
// the near root then the far one, each when its height is within [y0, y1]. The normal
// (x, 0, z) / r is turned toward the ray, as the book's: the inside is seen too.
fn intersect_open_cylinder(r: Ray, hit: ptr<function, HitInfo>, y0: f32, y1: f32, radius: f32) -> bool
{
    let a = r.direction.x * r.direction.x + r.direction.z * r.direction.z;
    if (a == 0.0) {
        return false;  // parallel to the axis
    }
    let b = 2.0 * (r.origin.x * r.direction.x + r.origin.z * r.direction.z);
    let c = r.origin.x * r.origin.x + r.origin.z * r.origin.z - radius * radius;
    let disc = b * b - 4.0 * a * c;
    if (disc < 0.0) {
        return false;
    }
    // The near root, then the far one (the inside, seen through an open end).
    let roots = vec2f(-b - sqrt(disc), -b + sqrt(disc)) / (2.0 * a);
    var k = 0u;
    for (; k < 2u; k++) {
        let y_hit = r.origin.y + roots[k] * r.direction.y;
        if (roots[k] >= r.tmin && roots[k] < r.tmax && y_hit >= y0 && y_hit <= y1) {
            break;
        }
    }
    if (k == 2u) {
        return false;
    }
    let t = roots[k];
    (*hit).has_hit = true;
    (*hit).dist = t;
    (*hit).position = r.origin + r.direction * t;
    var n = normalize(vec3f((*hit).position.x, 0.0, (*hit).position.z));
    if (dot(r.direction, n) > 0.0) {
        n = -n;
    }
    (*hit).normal = n;
    return true;
}
