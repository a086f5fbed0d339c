// Ray-annulus intersection (Suffern ch. 19; rtfgu.shapes.annulus): the plane of the annulus
// (intersect_plane), then the hit counts when r_i^2 <= (p - c) . (p - c) <= r_o^2.
fn intersect_annulus(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, normal: vec3f, inner_radius: f32,
                     outer_radius: f32) -> bool
{
    var on_plane = *hit;
    if (!intersect_plane(r, &on_plane, center, normal)) {
        return false;
    }
    let to_hit = on_plane.position - center;
    let d2 = dot(to_hit, to_hit);
    if (d2 >= inner_radius * inner_radius && d2 <= outer_radius * outer_radius) {
        *hit = on_plane;
        return true;
    }
    return false;
}
