// release: solves a04
// A light sample (02562, "Sampling light in the shader"): incident radiance, unit direction
// toward the light, and distance to it.
struct Light {
    L_i: vec3f,
    w_i: vec3f,
    dist: f32
};

// #if point_light|area_light
// Kepler's inverse square law: L_i = I / ||p - x||^2 for a point light at p with intensity I.
fn point_light(position: vec3f, intensity: vec3f, pos: vec3f) -> Light
{
    let to_light = position - pos;
    let dist_squared = dot(to_light, to_light);
    let dist = sqrt(dist_squared);
    let L_i = intensity / dist_squared;
    return Light(L_i, to_light / dist, dist);
}
// #endif
// #if point_light
// The point light number i.
fn sample_point_light(pos: vec3f, i: u32) -> Light
{
    return point_light(point_lights[i].position, point_lights[i].intensity, pos);
}
// #endif
// #if directional
// A directional light (rtfgu/lights/directional.py): the same L_i from its direction (toward the light) everywhere,
// at no finite distance (FAR, as a fresh ray's tmax).
fn sample_directional(pos: vec3f, i: u32) -> Light
{
    return Light(directionals[i].intensity, normalize(directionals[i].direction), FAR);
}
// #endif
// #if area_light
// An area light in the ray-cast loop (rtfgu/lights/area_light.py, AreaLight.sample): a point light at
// its shape's centre; a triangle or a rectangle sends L_e A cos(theta_l), a sphere L_e pi r^2
// and stops the shadow ray at its surface.
fn sample_area_light(pos: vec3f, i: u32) -> Light
{
    // #if area_lighting
    // AreaLighting (rtfgu/tracers/area_lighting.py): a point of the light drawn from the stream.
    let uv = sampler_point(stream.x, stream.y, stream.z + LIGHT_U + 2u * i, area_lights[i].light_sampler);
    return sample_area_light_area(pos, i, uv.x, uv.y);
    // #else
    let light = area_lights[i];
    if (light.radius > 0.0) {
        let sample = point_light(light.v0, light.emission * (PI * light.radius * light.radius), pos);
        return Light(sample.L_i, sample.w_i, sample.dist - light.radius);
    }
    let n = cross(light.e0, light.e1);
    var center = light.v0 + (light.e0 + light.e1) / 3.0;
    var area = 0.5 * length(n);
    if (light.rectangle > 0.0) {
        center = light.v0 + (light.e0 + light.e1) * 0.5;
        area = length(light.e0) * length(light.e1);
    }
    let sample = point_light(center, light.emission * area, pos);
    let cos_l = max(-dot(normalize(n), sample.w_i), 0.0);
    return Light(sample.L_i * cos_l, sample.w_i, sample.dist);
    // #endif
}
// #endif
