// What a ray that leaves the scene sees (rtfgu.Scene.background_radiance): the
// EnvironmentLight's lat-long image (rtfgu/lights/environment_light.py, 02562 worksheet 9), the
// nearest texel at u = 1/2 + atan2(x, -z) / (2 pi), v = acos(y) / pi; else the background.
fn background_radiance(direction: vec3f) -> vec3f
{
    // #if environment
    let u = 0.5 + atan2(direction.x, -direction.z) / (2.0 * PI);
    let v = acos(clamp(direction.y, -1.0, 1.0)) / PI;
    let column = min(u32(u * f32(ENVIRONMENT_WIDTH)), ENVIRONMENT_WIDTH - 1u);
    let row = min(u32(v * f32(ENVIRONMENT_HEIGHT)), ENVIRONMENT_HEIGHT - 1u);
    let k = 3u * (row * ENVIRONMENT_WIDTH + column);
    return vec3f(environment[k], environment[k + 1u], environment[k + 2u]);
    // #else
    return uniforms.background;
    // #endif
}
