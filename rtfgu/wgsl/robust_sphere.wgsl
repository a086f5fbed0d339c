// release: solves a03 a06
// Robust ray-sphere intersection after Haines, Guenther and Akenine-Moeller, "Precision
// Improvements for Ray/Sphere Intersection", Ray Tracing Gems, chapter 7 (2019); the Python
// and numba versions are rtfgu/robust.py and rtfgu/kernels/intersect.py.
// With f = o - c, a = w . w and b' = -f . w:
//   disc = a (r^2 - |f + (b'/a) w|^2)   the squared distance from the centre to the line,
//                                       instead of b^2 - 4ac, which cancels for a far or
//                                       small sphere in f32;
//   t0 = c / q, t1 = q / a with q = b' + sign(b') sqrt(disc), never a difference of two
//   nearly equal numbers.
// The assembler (rtfgu/wgsl/assemble.py) takes intersect_sphere from this file instead of
// intersect_sphere.wgsl when the formula is "robust"; both have the 02562 signature. Its
// inputs are finite (compile_scene refuses anything else; the hard-case program,
// hardcase_main.wgsl, makes non-finite input a miss before calling it). The direction is
// scaled by the power of two that brings its largest component into [0.5, 1), and the roots
// back (rtfgu.robust.direction_scale): exact, so the roots are those of the direction
// itself, but w . w cannot overflow or underflow.

fn intersect_sphere(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, radius: f32) -> bool
{
    let f = r.origin - center;
    let w = abs(r.direction);
    let s = ldexp(1.0, -frexp(max(max(w.x, w.y), w.z)).exp);
    let d = r.direction * s;
    let a = dot(d, d);
    let b = -dot(f, d);
    let c = dot(f, f) - radius * radius;
    let l = f + (b / a) * d;
    let disc = a * (radius * radius - dot(l, l));
    if (!(disc >= 0.0)) {
        return false;
    }
    let root = sqrt(disc);
    var q = b - root;
    if (b >= 0.0) {
        q = b + root;
    }
    // q = 0 only for b' = 0 and disc = 0: the origin is the tangent point, both roots are 0.
    var t0 = 0.0;
    var t1 = 0.0;
    if (q != 0.0) {
        t0 = c / q * s;
        t1 = q / a * s;
    }
    // The least t in [tmin, tmax): the near root if it is in range, else the far one.
    let near = min(t0, t1);
    let t = select(max(t0, t1), near, near >= r.tmin && near < r.tmax);
    if (!(t >= r.tmin && t < r.tmax)) {
        return false;
    }
    let p = r.origin + r.direction * t;
    (*hit).has_hit = true;
    (*hit).dist = t;
    (*hit).position = p;
    (*hit).normal = normalize(p - center);
    return true;
}
