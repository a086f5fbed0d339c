// Watertight ray-triangle intersection after Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2(1), 2013 (non-culling); the Python and numba versions
// are rtfgu/robust.py and rtfgu/kernels/robust.py.
// The vertices go into a frame where the ray starts at the origin and runs along +z; the
// edge functions U, V, W are 2D cross products of vertex pairs, so two triangles sharing an
// edge compute exact negatives for it and a ray through the edge hits at least one of them.
// It takes the vertices themselves (the slide's v: array<vec3f, 3>): e0 = v1 - v0 rounded in
// each triangle would break that. WGSL has no f64, so the paper's double-precision
// recomputation of a zero edge function is left out; watertightness does not depend on it.

fn triangle_robust_finite(v: vec4f) -> bool
{
    let e = bitcast<vec4u>(v) & vec4u(0x7f800000u);
    return all(e != vec4u(0x7f800000u));
}

fn intersect_triangle_robust(r: Ray, hit: ptr<function, HitInfo>, v: array<vec3f, 3>) -> bool
{
    if (!(triangle_robust_finite(vec4f(r.origin, r.tmin)) && triangle_robust_finite(vec4f(r.direction, 0.0))
          && triangle_robust_finite(vec4f(v[0], v[1].x)) && triangle_robust_finite(vec4f(v[1].yz, v[2].xy))
          && triangle_robust_finite(vec4f(v[2].z, 0.0, 0.0, 0.0)))) {
        return false;
    }
    // A zero-area triangle is a miss: U + V + W of a collinear triangle need not round to 0.
    let n = cross(v[1] - v[0], v[2] - v[0]);
    if (all(n == vec3f(0.0))) {
        return false;
    }
    let w = r.direction;
    let aw = abs(w);
    var kz = 2u;
    if (aw.x > aw.y) {
        if (aw.x > aw.z) { kz = 0u; }
    } else if (aw.y > aw.z) {
        kz = 1u;
    }
    var kx = (kz + 1u) % 3u;
    var ky = (kx + 1u) % 3u;
    if (w[kz] < 0.0) {
        let swap = kx;
        kx = ky;
        ky = swap;
    }
    let Sx = w[kx] / w[kz];
    let Sy = w[ky] / w[kz];
    let Sz = 1.0 / w[kz];
    let A = v[0] - r.origin;
    let B = v[1] - r.origin;
    let C = v[2] - r.origin;
    let Ax = A[kx] - Sx * A[kz];
    let Ay = A[ky] - Sy * A[kz];
    let Bx = B[kx] - Sx * B[kz];
    let By = B[ky] - Sy * B[kz];
    let Cx = C[kx] - Sx * C[kz];
    let Cy = C[ky] - Sy * C[kz];
    let U = Cx * By - Cy * Bx;
    let V = Ax * Cy - Ay * Cx;
    let W = Bx * Ay - By * Ax;
    if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) {
        return false;
    }
    let det = U + V + W;
    if (det == 0.0) {
        return false;
    }
    let T = U * (Sz * A[kz]) + V * (Sz * B[kz]) + W * (Sz * C[kz]);
    let t = T / det;
    if (!(t >= r.tmin && t < r.tmax)) {
        return false;
    }
    (*hit).has_hit = true;
    (*hit).dist = t;
    (*hit).position = r.origin + w * t;
    (*hit).normal = normalize(n);
    return true;
}

// PBRT-v4's triangle bound gamma(7) (|b0 p0| + |b1 p1| + |b2 p2|) (section 6.8.5) at its
// largest over barycentrics in [0, 1].
fn triangle_point_error(v: array<vec3f, 3>) -> vec3f
{
    let u = 0.5 * 1.1920929e-7;
    let g7 = 7.0 * u / (1.0 - 7.0 * u);
    return g7 * (abs(v[0]) + abs(v[1]) + abs(v[2]));
}

// The next f32 away from x in the direction of the sign of s (PBRT's NextFloatUp/Down).
fn next_float_toward(x: f32, s: f32) -> f32
{
    if (s == 0.0) {
        return x;
    }
    if (x == 0.0) {
        return select(bitcast<f32>(0x80000001u), bitcast<f32>(1u), s > 0.0);
    }
    let bits = bitcast<u32>(x);
    // Growing in magnitude is +1 on the bits; toward zero is -1.
    if ((x > 0.0) == (s > 0.0)) {
        return bitcast<f32>(bits + 1u);
    }
    return bitcast<f32>(bits - 1u);
}

// PBRT-v4 section 6.8.6, "Robust Spawned Ray Origins" (OffsetRayOrigin): move p along the
// geometric normal n, to the side w leaves toward, by |n| . p_error, rounded away from p.
// The spawned ray starts there with tmin = 0 and neither re-hits its surface nor skips a
// real hit beyond the tiny offset, which a fixed epsilon does at large or small scales.
fn offset_ray_origin(p: vec3f, p_error: vec3f, n: vec3f, w: vec3f) -> vec3f
{
    let d = dot(abs(n), p_error);
    var offset = d * n;
    if (dot(w, n) < 0.0) {
        offset = -offset;
    }
    let po = p + offset;
    return vec3f(next_float_toward(po.x, offset.x), next_float_toward(po.y, offset.y),
                 next_float_toward(po.z, offset.z));
}
