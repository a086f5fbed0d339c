// #if lattice_noise
// LatticeNoise's sums (rtfgu/noise/lattice_noise.py, Suffern ch. 31): noise is the row's
// noise id (0 LinearNoise, 1 CubicNoise); each sum is mapped into [0, 1] with fbm_max.
fn value_noise(noise: f32, p: vec3f) -> f32
{
    // #if linear_noise
    if (noise == 0.0) {
        return linear_noise(p);
    }
    // #endif
    // #if cubic_noise
    return cubic_noise(p);
    // #else
    return 0.0;
    // #endif
}

fn value_fractal_sum(noise: f32, num_octaves: f32, fbm_max: f32, p: vec3f) -> f32
{
    var amplitude = 1.0;
    var frequency = 1.0;
    var sum = 0.0;
    for (var j = 0; j < i32(num_octaves); j++) {
        sum += amplitude * value_noise(noise, p * frequency);
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    return (sum + fbm_max) / (fbm_max + fbm_max);
}

fn value_turbulence(noise: f32, num_octaves: f32, fbm_max: f32, p: vec3f) -> f32
{
    var amplitude = 1.0;
    var frequency = 1.0;
    var turbulence = 0.0;
    for (var j = 0; j < i32(num_octaves); j++) {
        turbulence += amplitude * abs(value_noise(noise, p * frequency));
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    return turbulence / fbm_max;
}

fn value_fbm(noise: f32, num_octaves: f32, lacunarity: f32, gain: f32, fbm_max: f32, p: vec3f) -> f32
{
    var amplitude = 1.0;
    var frequency = 1.0;
    var fbm = 0.0;
    for (var j = 0; j < i32(num_octaves); j++) {
        fbm += amplitude * value_noise(noise, p * frequency);
        amplitude *= gain;
        frequency *= lacunarity;
    }
    return (fbm + fbm_max) / (fbm_max + fbm_max);
}
// #if vector_noise
fn vector_noise(noise: f32, p: vec3f) -> vec3f
{
    // #if linear_noise
    if (noise == 0.0) {
        return linear_vector_noise(p);
    }
    // #endif
    // #if cubic_noise
    return cubic_vector_noise(p);
    // #else
    return vec3f(0.0);
    // #endif
}

fn vector_fbm(noise: f32, num_octaves: f32, lacunarity: f32, gain: f32, p: vec3f) -> vec3f
{
    var amplitude = 1.0;
    var frequency = 1.0;
    var sum = vec3f(0.0);
    for (var j = 0; j < i32(num_octaves); j++) {
        sum += vector_noise(noise, p * frequency) * amplitude;
        amplitude *= gain;
        frequency *= lacunarity;
    }
    return sum;
}
// #endif
// #endif
