// Ray-open-cylinder intersection (Suffern ch. 19, "Open cylinders"; rtfgu.shapes.open_cylinder):
// the ray projected onto the xz plane meets the sphere of radius r about the origin
// (intersect_sphere: the same quadratic) where the ray meets the infinite cylinder; the near
// root, then the far one, counts when its height is within [y0, y1]. The normal (x, 0, z) / r
// is turned toward the ray, as the book's: the inside is seen too.
fn intersect_open_cylinder(r: Ray, hit: ptr<function, HitInfo>, y0: f32, y1: f32, radius: f32) -> bool
{
    if (r.direction.x == 0.0 && r.direction.z == 0.0) {
        return false;  // parallel to the axis
    }
    var flat = Ray(vec3f(r.origin.x, 0.0, r.origin.z), vec3f(r.direction.x, 0.0, r.direction.z), r.tmin, r.tmax);
    for (var k = 0; k < 2; k++) {
        var on_circle = *hit;
        if (!intersect_sphere(flat, &on_circle, vec3f(0.0), radius)) {
            return false;
        }
        let y_hit = r.origin.y + on_circle.dist * r.direction.y;
        if (y_hit >= y0 && y_hit <= y1) {
            on_circle.position = r.origin + r.direction * on_circle.dist;
            var n = normalize(vec3f(on_circle.position.x, 0.0, on_circle.position.z));
            if (dot(r.direction, n) > 0.0) {
                n = -n;
            }
            on_circle.normal = n;
            *hit = on_circle;
            return true;
        }
        flat.tmin = next_after(on_circle.dist);
    }
    return false;
}
