// Sample `index` of `pixel` (Sampler.sample_unit_square, rtfgu/sampling/sampler.py): a
// point of the set the random stream picks for the pixel, in that set's shuffled order,
// from the sampler's arrays; Burley's Sobol pair (sobol.wgsl) for a Sobol sampler; the
// pixel's centre for a scene rendered without a sampler.
const PIXEL_SET = 0u;
const LENS_SET = 1u;

fn pixel_sample(pixel: u32, index: u32, dimension: u32) -> vec2f
{
    // #if sampler
    let jump = (random_u32(pixel, index / NUM_SAMPLES, dimension, uniforms.seed) % NUM_SETS) * NUM_SAMPLES;
    return samples[jump + u32(shuffled[jump + index % NUM_SAMPLES])];
    // #else
    // #if sobol
    return sobol_pair(pixel, index, dimension, uniforms.seed);
    // #else
    return vec2f(0.5);
    // #endif
    // #endif
}
