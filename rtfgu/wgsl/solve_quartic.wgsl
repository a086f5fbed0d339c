// The real roots of a quartic (rtfgu/shapes/quartic.py): Schwarze's SolveQuartic (Graphics
// Gems I, 1990), as Suffern's Torus::hit calls it, with rtfgu's departures (the resolvent's
// largest root, u^2 and v^2 below 0 taken as 0, acos's argument clamped; EQN_EPS is 1e-30 in
// f32), then at most QUARTIC_NEWTON_STEPS Newton steps on each root, each kept only if |f|
// drops (f32's closed form keeps only a few digits), and a root kept only if its residual is
// what rounding leaves (QUARTIC_RESIDUAL).

const EQN_EPS: f32 = 1e-30;
const QUARTIC_NEWTON_STEPS: i32 = 3;
const PI_THIRD: f32 = 1.0471975511965976;
const QUARTIC_RESIDUAL: f32 = 1.52587890625e-05;   // 2^-16

// count real roots in s.x, s.y, ... (unsorted)
struct Roots {
    count: i32,
    s: vec4f
};

fn is_zero(x: f32) -> bool
{
    return x > -EQN_EPS && x < EQN_EPS;
}

// Schwarze's real cube root (his NOCBRT macro).
fn cbrt(x: f32) -> f32
{
    if (x > 0.0) {
        return pow(x, 1.0 / 3.0);
    }
    if (x < 0.0) {
        return -pow(-x, 1.0 / 3.0);
    }
    return 0.0;
}

// The real roots of c2 x^2 + c1 x + c0.
fn solve_quadric(c0: f32, c1: f32, c2: f32) -> Roots
{
    let p = c1 / (2.0 * c2);
    let q = c0 / c2;
    let D = p * p - q;
    if (is_zero(D)) {
        return Roots(1, vec4f(-p, 0.0, 0.0, 0.0));
    }
    if (D > 0.0) {
        let sqrt_D = sqrt(D);
        return Roots(2, vec4f(sqrt_D - p, -sqrt_D - p, 0.0, 0.0));
    }
    return Roots(0, vec4f(0.0));
}

// The real roots of c3 x^3 + c2 x^2 + c1 x + c0 (Cardano); with three, s.x is the largest.
fn solve_cubic(c0: f32, c1: f32, c2: f32, c3: f32) -> Roots
{
    let third = 1.0 / 3.0;
    let A = c2 / c3;
    let B = c1 / c3;
    let C = c0 / c3;
    let sq_A = A * A;
    let p = third * (-third * sq_A + B);
    let q = 0.5 * (2.0 / 27.0 * A * sq_A - third * A * B + C);
    let cb_p = p * p * p;
    let D = q * q + cb_p;
    var roots = Roots(1, vec4f(0.0));
    if (is_zero(D)) {
        if (!is_zero(q)) {
            let u = cbrt(-q);
            roots = Roots(2, vec4f(2.0 * u, -u, 0.0, 0.0));
        }
    } else if (D < 0.0) {
        let phi = third * acos(clamp(-q / sqrt(-cb_p), -1.0, 1.0));
        let t = 2.0 * sqrt(-p);
        roots = Roots(3, vec4f(t * cos(phi), -t * cos(phi + PI_THIRD), -t * cos(phi - PI_THIRD), 0.0));
    } else {
        let sqrt_D = sqrt(D);
        roots = Roots(1, vec4f(cbrt(sqrt_D - q) - cbrt(sqrt_D + q), 0.0, 0.0, 0.0));
    }
    roots.s -= vec4f(third * A);
    return roots;
}

fn quartic_value(c: array<f32, 5>, t: f32) -> f32
{
    return (((c[4] * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0];
}

// The root near t0 after the Newton steps, or a negative count's -1 in .y if |f| stays
// above QUARTIC_RESIDUAL of |c4| |t|^4 + ... + |c0| (no root: rounding cannot leave that much).
fn polish_root(c: array<f32, 5>, t0: f32) -> vec2f
{
    var t = t0;
    var f = quartic_value(c, t);
    for (var k = 0; k < QUARTIC_NEWTON_STEPS; k++) {
        let slope = ((4.0 * c[4] * t + 3.0 * c[3]) * t + 2.0 * c[2]) * t + c[1];
        if (slope == 0.0) {
            break;
        }
        let t_next = t - f / slope;
        let f_next = quartic_value(c, t_next);
        if (!(abs(f_next) < abs(f))) {
            break;
        }
        t = t_next;
        f = f_next;
    }
    let x = abs(t);
    let size = (((abs(c[4]) * x + abs(c[3])) * x + abs(c[2])) * x + abs(c[1])) * x + abs(c[0]);
    return vec2f(t, select(-1.0, 1.0, abs(f) <= QUARTIC_RESIDUAL * size));
}

// The real roots of c[4] x^4 + c[3] x^3 + c[2] x^2 + c[1] x + c[0] (c[4] != 0), each polished.
fn solve_quartic(c: array<f32, 5>) -> Roots
{
    let A = c[3] / c[4];
    let B = c[2] / c[4];
    let C = c[1] / c[4];
    let D = c[0] / c[4];
    let sq_A = A * A;
    let p = -0.375 * sq_A + B;
    let q = 0.125 * sq_A * A - 0.5 * A * B + C;
    let r = -0.01171875 * sq_A * sq_A + 0.0625 * sq_A * B - 0.25 * A * C + D;
    var roots = Roots(0, vec4f(0.0));
    if (is_zero(r)) {
        // y (y^3 + p y + q) = 0
        roots = solve_cubic(q, p, 0.0, 1.0);
        roots.s[roots.count] = 0.0;
        roots.count += 1;
    } else {
        let z3 = solve_cubic(0.5 * r * p - 0.125 * q * q, -r, -0.5 * p, 1.0);
        let z = select(z3.s.x, max(z3.s.x, z3.s.y), z3.count >= 2);
        let u = sqrt(max(z * z - r, 0.0));
        let v = sqrt(max(2.0 * z - p, 0.0));
        let first = solve_quadric(z - u, select(v, -v, q < 0.0), 1.0);
        let second = solve_quadric(z + u, select(-v, v, q < 0.0), 1.0);
        roots = first;
        for (var k = 0; k < second.count; k++) {
            roots.s[roots.count] = second.s[k];
            roots.count += 1;
        }
    }
    var kept = Roots(0, vec4f(0.0));
    for (var k = 0; k < roots.count; k++) {
        let polished = polish_root(c, roots.s[k] - 0.25 * A);
        if (polished.y > 0.0) {
            kept.s[kept.count] = polished.x;
            kept.count += 1;
        }
    }
    return kept;
}
