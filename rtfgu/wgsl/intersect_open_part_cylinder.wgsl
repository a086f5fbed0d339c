// Ray-part-cylinder intersection (Suffern ch. 19, "Part objects"; rtfgu.shapes.open_part_cylinder):
// the open cylinder's hit (intersect_open_cylinder, its normal turned toward the ray), kept
// when its azimuth atan2(x, z) is in [phi_min, phi_max]; else the next one, beyond it.
fn intersect_open_part_cylinder(r: Ray, hit: ptr<function, HitInfo>, y0: f32, y1: f32, radius: f32, phi_min: f32,
                                phi_max: f32) -> bool
{
    var probe = r;
    for (var k = 0; k < 2; k++) {
        var on_cylinder = *hit;
        if (!intersect_open_cylinder(probe, &on_cylinder, y0, y1, radius)) {
            return false;
        }
        var phi = atan2(on_cylinder.position.x, on_cylinder.position.z);
        if (phi < 0.0) {
            phi += 2.0 * PI;
        }
        if (phi >= phi_min && phi <= phi_max) {
            *hit = on_cylinder;
            return true;
        }
        probe.tmin = next_after(on_cylinder.dist);
    }
    return false;
}
