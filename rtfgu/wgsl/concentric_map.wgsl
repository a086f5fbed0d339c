// release: solves a10
// Shirley and Chiu's concentric map of [0, 1]^2 onto the unit disk, as Suffern's
// Sampler::map_samples_to_unit_disk (rtfgu/sampling/maps.py).
fn concentric_map(p: vec2f) -> vec2f
{
    let sx = 2.0 * p.x - 1.0;
    let sy = 2.0 * p.y - 1.0;
    var r: f32;
    var phi: f32;
    if (sx > -sy) {
        if (sx > sy) {
            r = sx;
            phi = sy / sx;
        } else {
            r = sy;
            phi = 2.0 - sx / sy;
        }
    } else {
        if (sx < sy) {
            r = -sx;
            phi = 4.0 + sy / sx;
        } else {
            r = -sy;
            if (sy != 0.0) {
                phi = 6.0 - sx / sy;
            } else {
                phi = 0.0;
            }
        }
    }
    phi *= PI / 4.0;
    return vec2f(r * cos(phi), r * sin(phi));
}
