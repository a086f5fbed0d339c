// A diffuse surface (02562, "Sampling light in the shader"; Kepler and Lambert):
//   L_o = L_e + sum over lights of rho_d / pi * L_i * max(n . w_i, 0) + L_a
// with rho_d = 90 % and L_a = 10 % of the object's colour (rtfgu.shading.lambertian).
fn lambertian(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    let rho_d = (*hit).color * DIFFUSE_FRACTION;
    let L_a = (*hit).color * AMBIENT_FRACTION;
    var result = (*hit).emission + L_a;
    // #if lights
    for (var i = 0u; i < NUM_LIGHTS; i++) {
        let light = sample_point_light((*hit).position, i);
        let cos_theta = max(dot((*hit).normal, light.w_i), 0.0);
        if (cos_theta == 0.0) {
            continue;
        }
        // #if shadows
        if (in_shadow((*hit).position, light.w_i, light.dist)) {
            continue;
        }
        // #endif
        result += rho_d / PI * light.L_i * cos_theta;
    }
    // #endif
    return result;
}
