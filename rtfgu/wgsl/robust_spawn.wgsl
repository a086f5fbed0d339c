// release: solves a03
// Robust spawned rays after PBRT-v4, sections 6.8.5 ("Bounding Intersection Point Error")
// and 6.8.6 ("Robust Spawned Ray Origins"); the Python and numba versions are
// rtfgu/robust.py and rtfgu/kernels/robust.py. The render spawns with the slides'
// SPAWN_EPSILON; the hard-case program (hardcase_main.wgsl, feature "spawn") uses these.

// PBRT's gamma(n) = n u / (1 - n u) in f32 (u = 2^-24, half the ulp of 1).
fn gamma_f32(n: f32) -> f32
{
    let nu = n * (0.5 * 1.1920929e-7);
    return nu / (1.0 - nu);
}

// A computed point on a sphere: gamma(5) |p - c| in the sphere's frame plus
// gamma(3) (|p - c| + |c|) for the translation to world space.
fn sphere_point_error(p: vec3f, center: vec3f) -> vec3f
{
    let q = abs(p - center);
    return gamma_f32(5.0) * q + gamma_f32(3.0) * (q + abs(center));
}

// The triangle's bound gamma(7) (|b0 p0| + |b1 p1| + |b2 p2|) at its largest over
// barycentrics in [0, 1].
fn triangle_point_error(v: array<vec3f, 3>) -> vec3f
{
    return gamma_f32(7.0) * (abs(v[0]) + abs(v[1]) + abs(v[2]));
}

// The triangle's bound with the hit point and the plane's point in the vertices' place
// (PBRT has no infinite plane; rtfgu/robust.py, plane_point_error).
fn plane_point_error(p: vec3f, a: vec3f) -> vec3f
{
    return gamma_f32(7.0) * (abs(p) + abs(a));
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
