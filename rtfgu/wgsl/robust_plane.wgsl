// release: solves a03 a06
// Robust ray-plane intersection: t = ((a - o) . n) / (d . n) (lecture 01, "Ray-Plane
// Intersection") with a - o kept exact as the pair of TwoSum and both dot products
// compensated: Dot2 of Ogita, Rump and Oishi, "Accurate Sum and Dot Product", SIAM J. Sci.
// Comput. 26(6), 2005, as accurate as in twice the precision, so the sign of t is right for
// nearly parallel rays and origins close to the plane; the Python and numba versions are
// rtfgu/robust.py and rtfgu/kernels/robust.py. It defines the 02562 intersect_plane, as
// robust_sphere.wgsl defines intersect_sphere. Its inputs are finite (the hard-case program,
// hardcase_main.wgsl, makes non-finite input a miss before calling it).

// 0 at run time, unknown to the compiler: XOR-ing the bits of an intermediate with it
// stops algebraic rewriting such as (a + b) - a -> b, which would erase the rounding error
// these error-free transformations capture. The program's main sets it from a buffer.
var<private> plane_opaque_bits: u32 = 0u;

fn plane_opaque(x: f32) -> f32
{
    return bitcast<f32>(bitcast<u32>(x) ^ plane_opaque_bits);
}

fn plane_two_sum(a: f32, b: f32) -> vec2f
{
    let s = plane_opaque(a + b);
    let bb = plane_opaque(s - a);
    return vec2f(s, (a - (s - bb)) + (b - bb));
}

fn plane_two_product(a: f32, b: f32) -> vec2f
{
    // Dekker's TwoProduct with the halves cut on the bits (12 significant bits each), not by
    // Veltkamp's 4097 a - (4097 a - a), and not by fma: the shader compiler may fuse a
    // multiply and an add into an fma, and llvmpipe's fma is not exact. Products of 12-bit
    // halves are exact, so a fused multiply-add gives the same result as the two operations.
    let p = plane_opaque(a * b);
    let ah = bitcast<f32>(bitcast<u32>(a) & 0xfffff000u);
    let al = a - ah;
    let bh = bitcast<f32>(bitcast<u32>(b) & 0xfffff000u);
    let bl = b - bh;
    return vec2f(p, al * bl - (((p - ah * bh) - al * bh) - ah * bl));
}

// sum of x[i] y[i] for i < count, as if in twice the precision
fn plane_dot2(x: array<f32, 6>, y: array<f32, 6>, count: i32) -> f32
{
    var ps = plane_two_product(x[0], y[0]);
    var p = ps.x;
    var s = ps.y;
    for (var i = 1; i < count; i++) {
        let hr = plane_two_product(x[i], y[i]);
        let pq = plane_two_sum(p, hr.x);
        p = pq.x;
        s = s + (pq.y + hr.y);
    }
    return p + s;
}

fn intersect_plane(r: Ray, hit: ptr<function, HitInfo>, position: vec3f, normal: vec3f) -> bool
{
    let w = r.direction;
    let n = normal;
    let denom = plane_dot2(array<f32, 6>(w.x, w.y, w.z, 0.0, 0.0, 0.0),
                           array<f32, 6>(n.x, n.y, n.z, 0.0, 0.0, 0.0), 3);
    if (denom == 0.0) {
        return false;
    }
    let sx = plane_two_sum(position.x, -r.origin.x);
    let sy = plane_two_sum(position.y, -r.origin.y);
    let sz = plane_two_sum(position.z, -r.origin.z);
    let num = plane_dot2(array<f32, 6>(sx.x, sy.x, sz.x, sx.y, sy.y, sz.y),
                         array<f32, 6>(n.x, n.y, n.z, n.x, n.y, n.z), 6);
    let t = num / denom;
    let in_range = t >= r.tmin && t < r.tmax;
    if (in_range) {
        (*hit).has_hit = true;
        (*hit).dist = t;
        (*hit).position = r.origin + w * t;
        (*hit).normal = normalize(n);
    }
    return in_range;
}
