// #if spherical_map
// Suffern ch. 29's SphericalMap (rtfgu/mappings/spherical_map.py): latitude and longitude of
// a unit sphere about the origin.
fn spherical_map(p: vec3f) -> vec2f
{
    let theta = acos(clamp(p.y, -1.0, 1.0));
    var phi = atan2(p.x, p.z);
    if (phi < 0.0) {
        phi += 2.0 * PI;
    }
    return vec2f(phi / (2.0 * PI), 1.0 - theta / PI);
}
// #endif
