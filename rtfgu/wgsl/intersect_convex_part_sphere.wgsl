// Ray-part-sphere intersection (Suffern ch. 19, "Part objects"; rtfgu.shapes.convex_part_sphere):
// the sphere's root (intersect_sphere), kept when the point p - c has
// r cos(theta_max) <= y <= r cos(theta_min) and phi = atan2(x, z) in [phi_min, phi_max];
// else the far root, looked for beyond the near one. The normal is the sphere's, outward.
fn intersect_convex_part_sphere(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, radius: f32, phi_min: f32,
                                phi_max: f32, cos_theta_min: f32, cos_theta_max: f32) -> bool
{
    var probe = r;
    for (var k = 0; k < 2; k++) {
        var on_sphere = *hit;
        if (!intersect_sphere(probe, &on_sphere, center, radius)) {
            return false;
        }
        let p = r.origin + r.direction * on_sphere.dist - center;
        var phi = atan2(p.x, p.z);
        if (phi < 0.0) {
            phi += 2.0 * PI;
        }
        if (p.y >= radius * cos_theta_max && p.y <= radius * cos_theta_min && phi >= phi_min && phi <= phi_max) {
            *hit = on_sphere;
            return true;
        }
        probe.tmin = next_after(on_sphere.dist);
    }
    return false;
}
