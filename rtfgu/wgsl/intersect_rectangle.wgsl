// Ray-rectangle intersection (Suffern ch. 19, "Rectangles"; rtfgu.shapes.rectangle): the plane
// through p0 with normal n = a x b (normalised), then 0 <= d . a <= |a|^2 and
// 0 <= d . b <= |b|^2 for d = o + t w - p0.
fn intersect_rectangle(r: Ray, hit: ptr<function, HitInfo>, p0: vec3f, a: vec3f, b: vec3f, normal: vec3f) -> bool
{
    let denom = dot(r.direction, normal);
    if (denom == 0.0) {
        return false;  // parallel to the rectangle's plane
    }
    let t = dot(p0 - r.origin, normal) / denom;
    if (!(t >= r.tmin && t < r.tmax)) {
        return false;
    }
    let position = r.origin + r.direction * t;
    let d = position - p0;
    let ddota = dot(d, a);
    if (ddota < 0.0 || ddota > dot(a, a)) {
        return false;
    }
    let ddotb = dot(d, b);
    if (ddotb < 0.0 || ddotb > dot(b, b)) {
        return false;
    }
    (*hit).has_hit = true;
    (*hit).dist = t;
    (*hit).position = position;
    (*hit).normal = normal;
    return true;
}
