// release: solves a03 a06
// Watertight ray-triangle intersection after Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2(1), 2013 (non-culling); the Python and numba versions
// are rtfgu/robust.py and rtfgu/kernels/robust.py.
// The vertices go into a frame where the ray starts at the origin and runs along +z; the
// edge functions U, V, W are 2D cross products of vertex pairs, so two triangles sharing an
// edge compute exact negatives for it and a ray through the edge hits at least one of them.
// It takes the vertices themselves (the slide's v: array<vec3f, 3>): e0 = v1 - v0 rounded in
// each triangle would break that. WGSL has no f64, so the paper's double-precision
// recomputation of a zero edge function is left out; watertightness does not depend on it.
// The render does not use it (the flat layout stores v0, e0, e1, n); the hard-case program,
// hardcase_main.wgsl, makes non-finite input a miss before calling it.

fn intersect_triangle_robust(r: Ray, hit: ptr<function, HitInfo>, v: array<vec3f, 3>) -> bool
{
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
