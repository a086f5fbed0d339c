// #if cubic_noise
// CubicNoise (rtfgu/noise/cubic_noise.py): the 4 x 4 x 4 lattice values around p through the
// Catmull-Rom four-knot spline along x, then y, then z. As CubicNoise.interpolate, one walk
// serves every table: table -1 is VALUE_TABLE, table 0, 1, 2 a component of VECTOR_TABLE
// (VECTOR_TABLES of rtfgu/noise/lattice_noise.py).
fn four_knot_spline(x: f32, k0: f32, k1: f32, k2: f32, k3: f32) -> f32
{
    let c3 = -0.5 * k0 + 1.5 * k1 - 1.5 * k2 + 0.5 * k3;
    let c2 = k0 - 2.5 * k1 + 2.0 * k2 - 0.5 * k3;
    let c1 = 0.5 * (-k0 + k2);
    return ((c3 * x + c2) * x + c1) * x + k1;
}

// The lattice value of ``table`` at (ix, iy, iz); the vector tables exist only where a
// scene uses vector_noise.
fn cubic_knot(table: i32, ix: i32, iy: i32, iz: i32) -> f32
{
    // #if vector_noise
    if (table >= 0) {
        return lattice_vector(ix, iy, iz)[table];
    }
    // #endif
    return lattice_value(ix, iy, iz);
}

fn cubic_row(table: i32, i: vec3i, fx: f32) -> f32
{
    return four_knot_spline(fx, cubic_knot(table, i.x - 1, i.y, i.z), cubic_knot(table, i.x, i.y, i.z),
                            cubic_knot(table, i.x + 1, i.y, i.z), cubic_knot(table, i.x + 2, i.y, i.z));
}

fn cubic_plane(table: i32, i: vec3i, fx: f32, fy: f32) -> f32
{
    return four_knot_spline(fy, cubic_row(table, i - vec3i(0, 1, 0), fx), cubic_row(table, i, fx),
                            cubic_row(table, i + vec3i(0, 1, 0), fx), cubic_row(table, i + vec3i(0, 2, 0), fx));
}

fn cubic_interpolate(table: i32, p: vec3f) -> f32
{
    let c = floor(p);
    let f = p - c;
    let i = vec3i(c);
    return four_knot_spline(f.z, cubic_plane(table, i - vec3i(0, 0, 1), f.x, f.y), cubic_plane(table, i, f.x, f.y),
                            cubic_plane(table, i + vec3i(0, 0, 1), f.x, f.y),
                            cubic_plane(table, i + vec3i(0, 0, 2), f.x, f.y));
}

// CubicNoise.value_noise: clamped to [-1, 1], the spline may overshoot the knots.
fn cubic_noise(p: vec3f) -> f32
{
    return clamp(cubic_interpolate(-1, p), -1.0, 1.0);
}
// #if vector_noise
// CubicNoise.vector_noise: the three component tables through the same walk, not clamped.
fn cubic_vector_noise(p: vec3f) -> vec3f
{
    return vec3f(cubic_interpolate(0, p), cubic_interpolate(1, p), cubic_interpolate(2, p));
}
// #endif
// #endif
