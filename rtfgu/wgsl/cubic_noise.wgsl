// #if cubic_noise
// CubicNoise.value_noise (rtfgu/noise/cubic_noise.py): the 4 x 4 x 4 lattice values around p
// through the Catmull-Rom four-knot spline along x, then y, then z, clamped to [-1, 1].
fn four_knot_spline(x: f32, k0: f32, k1: f32, k2: f32, k3: f32) -> f32
{
    let c3 = -0.5 * k0 + 1.5 * k1 - 1.5 * k2 + 0.5 * k3;
    let c2 = k0 - 2.5 * k1 + 2.0 * k2 - 0.5 * k3;
    let c1 = 0.5 * (-k0 + k2);
    return ((c3 * x + c2) * x + c1) * x + k1;
}

fn cubic_row(i: vec3i, fx: f32) -> f32
{
    return four_knot_spline(fx, lattice_value(i.x - 1, i.y, i.z), lattice_value(i.x, i.y, i.z),
                            lattice_value(i.x + 1, i.y, i.z), lattice_value(i.x + 2, i.y, i.z));
}

fn cubic_plane(i: vec3i, fx: f32, fy: f32) -> f32
{
    return four_knot_spline(fy, cubic_row(i - vec3i(0, 1, 0), fx), cubic_row(i, fx),
                            cubic_row(i + vec3i(0, 1, 0), fx), cubic_row(i + vec3i(0, 2, 0), fx));
}

fn cubic_noise(p: vec3f) -> f32
{
    let c = floor(p);
    let f = p - c;
    let i = vec3i(c);
    let value = four_knot_spline(f.z, cubic_plane(i - vec3i(0, 0, 1), f.x, f.y), cubic_plane(i, f.x, f.y),
                                 cubic_plane(i + vec3i(0, 0, 1), f.x, f.y), cubic_plane(i + vec3i(0, 0, 2), f.x, f.y));
    return clamp(value, -1.0, 1.0);
}
// #if vector_noise
// CubicNoise.vector_noise: the lattice's unit vectors through the same splines, not clamped.
fn four_knot_spline3(x: f32, k0: vec3f, k1: vec3f, k2: vec3f, k3: vec3f) -> vec3f
{
    let c3 = -0.5 * k0 + 1.5 * k1 - 1.5 * k2 + 0.5 * k3;
    let c2 = k0 - 2.5 * k1 + 2.0 * k2 - 0.5 * k3;
    let c1 = 0.5 * (-k0 + k2);
    return ((c3 * x + c2) * x + c1) * x + k1;
}

fn cubic_vector_row(i: vec3i, fx: f32) -> vec3f
{
    return four_knot_spline3(fx, lattice_vector(i.x - 1, i.y, i.z), lattice_vector(i.x, i.y, i.z),
                             lattice_vector(i.x + 1, i.y, i.z), lattice_vector(i.x + 2, i.y, i.z));
}

fn cubic_vector_plane(i: vec3i, fx: f32, fy: f32) -> vec3f
{
    return four_knot_spline3(fy, cubic_vector_row(i - vec3i(0, 1, 0), fx), cubic_vector_row(i, fx),
                             cubic_vector_row(i + vec3i(0, 1, 0), fx), cubic_vector_row(i + vec3i(0, 2, 0), fx));
}

fn cubic_vector_noise(p: vec3f) -> vec3f
{
    let c = floor(p);
    let f = p - c;
    let i = vec3i(c);
    return four_knot_spline3(f.z, cubic_vector_plane(i - vec3i(0, 0, 1), f.x, f.y), cubic_vector_plane(i, f.x, f.y),
                             cubic_vector_plane(i + vec3i(0, 0, 1), f.x, f.y),
                             cubic_vector_plane(i + vec3i(0, 0, 2), f.x, f.y));
}
// #endif
// #endif
