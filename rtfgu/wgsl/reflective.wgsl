// Reflective with a Phong part (Suffern ch. 24; rtfgu/materials/reflective.py): Phong at
// the surface, then the path continues along the mirror direction weighted by kr cr.
// The emission is counted once, by the light loop.
fn reflective(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    let result = direct_light(r, hit);
    mirror(r, hit);
    return result;
}
