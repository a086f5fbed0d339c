// release: solves a08
// Ray-torus intersection (Suffern ch. 19, "Tori"; rtfgu.shapes.torus): the ring torus about
// the y axis, sweep radius a, tube radius b. The ray is tested against the torus's box
// (torus_box_entry, BBox.hit), then the book's quartic is written for the ray from where it
// enters the box with a unit direction, o' = o + t_box d, d' = d / |d| (coefficients of size
// (a + b)^4, not |o|^4), solved by solve_quartic (solve_quartic.wgsl), and the least
// t_box + s / |d| in [tmin, tmax) is the hit. The
// normal is the book's compute_normal, the gradient of the implicit function.
fn intersect_torus(r: Ray, hit: ptr<function, HitInfo>, a: f32, b: f32) -> bool
{
    let t_box = torus_box_entry(r, a, b);
    if (t_box < 0.0) {
        return false;
    }
    let o = r.origin + r.direction * t_box;
    let size = length(r.direction);
    let d = r.direction / size;
    let sum_d_sqrd = d.x * d.x + d.y * d.y + d.z * d.z;
    let e = o.x * o.x + o.y * o.y + o.z * o.z - a * a - b * b;
    let f = o.x * d.x + o.y * d.y + o.z * d.z;
    let four_a_sqrd = 4.0 * a * a;
    let roots = solve_quartic(array<f32, 5>(e * e - four_a_sqrd * (b * b - o.y * o.y),
                                            4.0 * f * e + 2.0 * four_a_sqrd * o.y * d.y,
                                            2.0 * sum_d_sqrd * e + 4.0 * f * f + four_a_sqrd * d.y * d.y,
                                            4.0 * sum_d_sqrd * f,
                                            sum_d_sqrd * sum_d_sqrd));
    var found = false;
    var t = 0.0;
    for (var k = 0; k < roots.count; k++) {   // the least root in range; the roots are unsorted
        let t_hit = t_box + roots.s[k] / size;
        if (t_hit >= r.tmin && t_hit < r.tmax && (!found || t_hit < t)) {
            found = true;
            t = t_hit;
        }
    }
    if (!found) {
        return false;
    }
    let position = r.origin + r.direction * t;
    return record_hit(hit, t, position, normal_torus(position, a, b));
}

// BBox.hit for the book's box (-a - b, -b, -a - b)..(a + b, b, a + b), grown by 2^-20 of
// a + b: the t at which the ray enters it within [tmin, tmax], or -1 for a miss.
fn torus_box_entry(r: Ray, a: f32, b: f32) -> f32
{
    let pad = 9.5367431640625e-07 * (a + b);
    let hi = vec3f(a + b + pad, b + pad, a + b + pad);
    var t0 = r.tmin;
    var t1 = r.tmax;
    for (var k = 0u; k < 3u; k++) {
        let o = r.origin[k];
        let w = r.direction[k];
        if (w == 0.0) {
            if (o < -hi[k] || o > hi[k]) {
                return -1.0;
            }
            continue;
        }
        var t_near = (-hi[k] - o) / w;
        var t_far = (hi[k] - o) / w;
        if (t_near > t_far) {
            let swap = t_near;
            t_near = t_far;
            t_far = swap;
        }
        t_far *= 1.0000003576278687;   // 1 + 2 gamma_3 in f32 (PBRT-v4 section 6.1.2)
        t0 = max(t0, t_near);
        t1 = min(t1, t_far);
        if (t0 > t1) {
            return -1.0;
        }
    }
    return t0;
}

fn normal_torus(p: vec3f, a: f32, b: f32) -> vec3f
{
    let param_squared = a * a + b * b;
    let sum_squared = dot(p, p);
    return normalize(vec3f(4.0 * p.x * (sum_squared - param_squared),
                           4.0 * p.y * (sum_squared - param_squared + 2.0 * a * a),
                           4.0 * p.z * (sum_squared - param_squared)));
}
