// Lambertian plus the normalised Phong lobe (02562 worksheet 3; rtfgu.shading.phong):
//   L_r = (rho_d / pi + rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s) L_i (n . w_i)
// with w_o = -direction and w_r = 2 (n . w_i) n - w_i, the mirrored light direction.
fn phong(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    let rho_d = (*hit).color * DIFFUSE_FRACTION;
    let L_a = (*hit).color * AMBIENT_FRACTION;
    let w_o = -(*r).direction;
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
        let w_r = (*hit).normal * (2.0 * cos_theta) - light.w_i;
        let cos_r = max(dot(w_o, w_r), 0.0);
        // WGSL leaves pow(0, 0) undefined; Python's 0 ** 0 is 1.
        let lobe_cos = select(pow(cos_r, (*hit).shininess), 1.0, (*hit).shininess == 0.0);
        let lobe = (*hit).specular * (((*hit).shininess + 2.0) / (2.0 * PI) * lobe_cos);
        result += (rho_d / PI + lobe) * light.L_i * cos_theta;
    }
    // #endif
    return result;
}
