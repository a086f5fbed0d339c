// release: solves a04
// A light sample (02562, "Sampling light in the shader"): incident radiance, unit direction
// toward the light, and distance to it.
struct Light {
    L_i: vec3f,
    w_i: vec3f,
    dist: f32
};

// #if point_light
// Kepler's inverse square law: L_i = I / ||p - x||^2 for the point light number i.
fn sample_point_light(pos: vec3f, i: u32) -> Light
{
    let to_light = point_lights[i].position - pos;
    let dist_squared = dot(to_light, to_light);
    let dist = sqrt(dist_squared);
    let L_i = point_lights[i].intensity / dist_squared;
    return Light(L_i, to_light / dist, dist);
}
// #endif
// #if directional
// A directional light (rtfgu/directional_light.py): the same L_i from -direction everywhere,
// at no finite distance (FAR, as a fresh ray's tmax).
fn sample_directional(pos: vec3f, i: u32) -> Light
{
    return Light(directionals[i].intensity, -normalize(directionals[i].direction), FAR);
}
// #endif
