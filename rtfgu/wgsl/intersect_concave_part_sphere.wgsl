// A part sphere seen from inside (Suffern ch. 19, "Part objects";
// rtfgu.shapes.concave_part_sphere): hit where the convex part is
// (intersect_convex_part_sphere), with the normal turned inward.
fn intersect_concave_part_sphere(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, radius: f32, phi_min: f32,
                                 phi_max: f32, cos_theta_min: f32, cos_theta_max: f32) -> bool
{
    if (!intersect_convex_part_sphere(r, hit, center, radius, phi_min, phi_max, cos_theta_min, cos_theta_max)) {
        return false;
    }
    (*hit).normal = -(*hit).normal;
    return true;
}
