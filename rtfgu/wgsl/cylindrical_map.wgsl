// #if cylindrical_map
// Suffern ch. 29's CylindricalMap (rtfgu/mappings/cylindrical_map.py): a cylinder of radius 1
// about the y axis from y = -1 to 1.
fn cylindrical_map(p: vec3f) -> vec2f
{
    var phi = atan2(p.x, p.z);
    if (phi < 0.0) {
        phi += 2.0 * PI;
    }
    return vec2f(phi / (2.0 * PI), (p.y + 1.0) / 2.0);
}
// #endif
