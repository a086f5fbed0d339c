// release: solves a05
// Perfect reflection: the path continues along w - 2 (w . n) n, its radiance weighted by
// kr cr (1 for the 02562 mirror; Reflective.shade, rtfgu/materials/reflective.py).
fn mirror(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    let d = (*r).direction;
    let n = (*hit).normal;
    continue_path(r, hit, d - n * (2.0 * dot(d, n)), (*hit).reflection);
    return (*hit).emission;
}
