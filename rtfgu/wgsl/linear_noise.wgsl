// #if linear_noise
// LinearNoise.value_noise (rtfgu/noise/linear_noise.py): the eight lattice values around p,
// interpolated along x, then y, then z.
fn noise_lerp(f: f32, a: f32, b: f32) -> f32
{
    return a + f * (b - a);
}

fn linear_noise(p: vec3f) -> f32
{
    let c = floor(p);
    let f = p - c;
    let i = vec3i(c);
    let x0 = noise_lerp(f.x, lattice_value(i.x, i.y, i.z), lattice_value(i.x + 1, i.y, i.z));
    let x1 = noise_lerp(f.x, lattice_value(i.x, i.y + 1, i.z), lattice_value(i.x + 1, i.y + 1, i.z));
    let x2 = noise_lerp(f.x, lattice_value(i.x, i.y, i.z + 1), lattice_value(i.x + 1, i.y, i.z + 1));
    let x3 = noise_lerp(f.x, lattice_value(i.x, i.y + 1, i.z + 1), lattice_value(i.x + 1, i.y + 1, i.z + 1));
    let y0 = noise_lerp(f.y, x0, x1);
    let y1 = noise_lerp(f.y, x2, x3);
    return noise_lerp(f.z, y0, y1);
}
// #if vector_noise
// LinearNoise.vector_noise: the lattice's unit vectors, interpolated the same way.
fn linear_vector_noise(p: vec3f) -> vec3f
{
    let c = floor(p);
    let f = p - c;
    let i = vec3i(c);
    let x0 = mix(lattice_vector(i.x, i.y, i.z), lattice_vector(i.x + 1, i.y, i.z), f.x);
    let x1 = mix(lattice_vector(i.x, i.y + 1, i.z), lattice_vector(i.x + 1, i.y + 1, i.z), f.x);
    let x2 = mix(lattice_vector(i.x, i.y, i.z + 1), lattice_vector(i.x + 1, i.y, i.z + 1), f.x);
    let x3 = mix(lattice_vector(i.x, i.y + 1, i.z + 1), lattice_vector(i.x + 1, i.y + 1, i.z + 1), f.x);
    return mix(mix(x0, x1, f.y), mix(x2, x3, f.y), f.z);
}
// #endif
// #endif
