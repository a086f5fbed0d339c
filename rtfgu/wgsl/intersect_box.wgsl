// release: solves a08
// Ray-box intersection (Suffern ch. 19, "Axis-aligned boxes"; rtfgu.shapes.box): the slab
// test. t0 is the largest entering t, t1 the smallest leaving t; a hit when t0 < t1, at t0,
// or at t1 for a ray from inside. An axis the ray does not move along bounds nothing when
// the origin is within that slab (WGSL has no infinity: FAR stands for it).
fn intersect_box(r: Ray, hit: ptr<function, HitInfo>, p0: vec3f, p1: vec3f) -> bool
{
    var t0 = -FAR;
    var t1 = FAR;
    for (var axis = 0u; axis < 3u; axis++) {
        let o = r.origin[axis];
        let d = r.direction[axis];
        let lo = p0[axis];
        let hi = p1[axis];
        if (d == 0.0) {
            if (o < lo || o > hi) {
                return false;
            }
            continue;
        }
        let a = 1.0 / d;
        var t_near = (lo - o) * a;
        var t_far = (hi - o) * a;
        if (a < 0.0) {
            t_near = (hi - o) * a;
            t_far = (lo - o) * a;
        }
        t0 = max(t0, t_near);
        t1 = min(t1, t_far);
    }
    if (!(t0 < t1)) {
        return false;
    }
    var t = t1;
    if (t0 >= r.tmin) {
        t = t0;
    }
    if (!(t >= r.tmin && t < r.tmax)) {
        return false;
    }
    let position = r.origin + r.direction * t;
    return record_hit(hit, t, position, normal_box(position, p0, p1));
}

// The face (0-5: -x, -y, -z, +x, +y, +z) nearest to the point, the first at equal distances.
fn box_face(p: vec3f, p0: vec3f, p1: vec3f) -> u32
{
    var face = 0u;
    var best = abs(p.x - p0.x);
    for (var k = 1u; k < 6u; k++) {
        var bound = p1[k % 3u];
        if (k < 3u) {
            bound = p0[k];
        }
        let distance = abs(p[k % 3u] - bound);
        if (distance < best) {
            face = k;
            best = distance;
        }
    }
    return face;
}

// Box.normal_at: the outward normal of the face nearest to the point.
fn normal_box(p: vec3f, p0: vec3f, p1: vec3f) -> vec3f
{
    let face = box_face(p, p0, p1);
    var n = vec3f(0.0);
    n[face % 3u] = select(1.0, -1.0, face < 3u);
    return n;
}
