// #if rectangular_map
// Suffern ch. 29's RectangularMap (rtfgu/mappings/rectangular_map.py): the square
// -1 <= x, z <= 1 of the plane y = 0.
fn rectangular_map(p: vec3f) -> vec2f
{
    return vec2f((p.z + 1.0) / 2.0, (p.x + 1.0) / 2.0);
}
// #endif
