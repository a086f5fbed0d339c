// Burley's shuffled, Owen-scrambled Sobol pair (rtfgu/sampling/sobol.py; Burley, "Practical
// Hash-based Owen Scrambling", JCGT 9(4), 2020): assembled only for a render whose sampler is
// a Sobol. u32 arithmetic wraps mod 2^32, as the lecture layer's masks do.

// Laine and Karras's hash (Burley, listing 3): bit j depends only on bits 0..j of x.
fn laine_karras_permutation(x_in: u32, seed: u32) -> u32
{
    var x = x_in + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// The base-2 Owen scramble of the fraction x (Burley, listing 4).
fn nested_uniform_scramble(x: u32, seed: u32) -> u32
{
    return reverseBits(laine_karras_permutation(reverseBits(x), seed));
}

// Sobol's second dimension: index bit j adds v_j, v_0 = 2^31, v_(j+1) = v_j ^ (v_j >> 1).
fn sobol_1(index: u32) -> u32
{
    var x = 0u;
    var v = 0x80000000u;
    for (var i = index; i != 0u; i >>= 1u) {
        if ((i & 1u) != 0u) {
            x ^= v;
        }
        v ^= v >> 1u;
    }
    return x;
}

// The pair's 32-bit fractions: the index shuffled, then each Sobol coordinate scrambled, all
// seeded from pcg(seed + pcg(dimension + pcg(pixel))).
fn sobol_pair_u32(pixel: u32, index: u32, dimension: u32, seed: u32) -> vec2u
{
    let key = pcg(seed + pcg(dimension + pcg(pixel)));
    let shuffled = nested_uniform_scramble(index, key);
    return vec2u(nested_uniform_scramble(reverseBits(shuffled), pcg(key + 1u)),
                 nested_uniform_scramble(sobol_1(shuffled), pcg(key + 2u)));
}

// (u, v) in [0, 1)^2 with 24 bits each: the same numbers as in float64.
fn sobol_pair(pixel: u32, index: u32, dimension: u32, seed: u32) -> vec2f
{
    let x = sobol_pair_u32(pixel, index, dimension, seed);
    return vec2f(f32(x.x >> 8u), f32(x.y >> 8u)) * (1.0 / 16777216.0);
}
