// release: solves a05
// Perfect reflection: the path continues along w - 2 (w . n) n (Reflective.shade, rtfgu/materials/reflective.py).
fn mirror(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    let d = (*r).direction;
    let n = (*hit).normal;
    continue_path(r, hit, d - n * (2.0 * dot(d, n)));
    return (*hit).emission;
}
