// release: solves a12
// The random stream's dimensions of a path's vertex (rtfgu.sampling.random.path_dimension: vertex
// depth draws 2 + depth * VERTEX_DIMENSIONS + k), and a point drawn on an area light, for the
// tracers that sample lights (PathTrace, GlobalTrace, AreaLighting).
const VERTEX_DIMENSIONS = 65536u;
const LIGHT_U = 8u;

// The point (u, v) of the unit square from which a light or a BRDF draws (Scene.light_sample,
// BRDF.sample_point): its own sampler's (set_sampler; `sets` is its row's light_sampler, or
// the material's diffuse_sampler or specular_sampler: first sample, num_samples, num_sets),
// else the render's pair: Burley's Sobol pair (sobol.wgsl) where the render's sampler is a
// Sobol, the random stream's `dimension` and the next otherwise. Light i of a kind draws in dimensions
// LIGHT_U + 2 i and the next of its vertex.
fn sampler_point(pixel: u32, s: u32, dimension: u32, sets: vec3f) -> vec2f
{
    // #if own_sampler
    let n = u32(sets.y);
    if (n > 0u) {
        let jump = u32(sets.x) + (random_u32(pixel, s / n, dimension, uniforms.seed) % u32(sets.z)) * n;
        return own_samples[jump + u32(own_shuffled[jump + s % n])];
    }
    // #endif
    // #if sobol
    return sobol_pair(pixel, s, dimension, uniforms.seed);
    // #else
    return vec2f(random_float(pixel, s, dimension, uniforms.seed), random_float(pixel, s, dimension + 1u, uniforms.seed));
    // #endif
}

// #if area_lighting
// AreaLighting's ray-cast loop: (pixel, sample, first dimension of the bounce), set per bounce
// by main, read by sample_area_light (lights.wgsl).
var<private> stream: vec3u;
// #endif

// #if area_light
// AreaLight.get_direction then incident (L G / pdf) under a tracer that samples area lights:
// L_e A cos(theta_l) / d^2 toward a point of area light i uniform by area, zero from behind.
fn sample_area_light_area(pos: vec3f, i: u32, u: f32, v: f32) -> Light
{
    let light = area_lights[i];
    var point: vec3f;
    var normal: vec3f;
    var area: f32;
    if (light.radius > 0.0) {
        let z = 1.0 - 2.0 * u;
        let s = sqrt(max(0.0, 1.0 - z * z));
        let phi = 2.0 * PI * v;
        normal = vec3f(s * cos(phi), s * sin(phi), z);
        point = light.v0 + normal * light.radius;
        area = 4.0 * PI * light.radius * light.radius;
    } else if (light.rectangle > 0.0) {
        // Rectangle.sample: p0 + u a + v b, area |a| |b| (Suffern ch. 18.6)
        point = light.v0 + light.e0 * u + light.e1 * v;
        normal = normalize(cross(light.e0, light.e1));
        area = length(light.e0) * length(light.e1);
    } else {
        let n = cross(light.e0, light.e1);
        point = light.v0 + (light.e0 * v + light.e1 * (1.0 - v)) * sqrt(u);
        normal = normalize(n);
        area = 0.5 * length(n);
    }
    let to_light = point - pos;
    let dist = length(to_light);
    if (!(dist > 0.0)) {
        return Light(vec3f(0.0), normal, 0.0);
    }
    let w_i = to_light / dist;
    let cos_l = -dot(normal, w_i);
    if (!(cos_l > 0.0)) {
        return Light(vec3f(0.0), w_i, dist);
    }
    return Light(light.emission * (area * cos_l / (dist * dist)), w_i, dist);
}
// #endif
