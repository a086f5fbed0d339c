// release: solves a05
// Phong at the surface, then the path continues by refraction (02562 worksheet 3).
// The emission is counted once, by the light loop.
fn glossy(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    let result = direct_light(r, hit);
    transparent(r, hit);
    return result;
}
