// The random stream (rtfgu/sampling/random.py): PCG's output permutation as a hash
// (Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 2020), once per counter,
// so every path draws the same numbers for the same (pixel, index, dimension, seed).
fn pcg(v: u32) -> u32
{
    let state = v * 747796405u + 2891336453u;
    let word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

fn random_u32(pixel: u32, index: u32, dimension: u32, seed: u32) -> u32
{
    var h = pcg(pixel);
    h = pcg(index + h);
    h = pcg(dimension + h);
    return pcg(seed + h);
}

// In [0, 1) with 24 random bits: the same number as in float64.
fn random_float(pixel: u32, index: u32, dimension: u32, seed: u32) -> f32
{
    return f32(random_u32(pixel, index, dimension, seed) >> 8u) * (1.0 / 16777216.0);
}
