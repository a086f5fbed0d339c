// Ray-rectangle intersection (Suffern ch. 19, "Rectangles"; rtfgu.shapes.rectangle): the plane
// through p0 with normal n = a x b, normalised (intersect_plane), then 0 <= d . a <= |a|^2
// and 0 <= d . b <= |b|^2 for d = o + t w - p0.
fn intersect_rectangle(r: Ray, hit: ptr<function, HitInfo>, p0: vec3f, a: vec3f, b: vec3f, normal: vec3f) -> bool
{
    var on_plane = *hit;
    if (!intersect_plane(r, &on_plane, p0, normal)) {
        return false;
    }
    let d = on_plane.position - p0;
    let ddota = dot(d, a);
    let ddotb = dot(d, b);
    if (ddota < 0.0 || ddota > dot(a, a) || ddotb < 0.0 || ddotb > dot(b, b)) {
        return false;
    }
    *hit = on_plane;
    return true;
}
