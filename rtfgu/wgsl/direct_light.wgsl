// release: solves a04
// The light loop (02562, "Sampling light in the shader"), written once for every shader
// that reflects light (rtfgu.registry ShaderKind.brdf): L_e + L_a, plus for every light the
// shader's BRDF term times L_i (n . w_i), unless the light is below the surface or, with
// shadows, hidden (Matte.shade and phong compute the same sum in this order).
fn brdf(hit: ptr<function, HitInfo>, w_o: vec3f, w_i: vec3f, cos_theta: f32) -> vec3f
{
    switch (*hit).shader {
        // #each brdf
        case $ID { return brdf_$of(hit, w_o, w_i, cos_theta); }
        // #end
        case default { return vec3f(0.0); }
    }
}

fn direct_light(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    var result = (*hit).emission + (*hit).color * (*hit).ambient;
    let w_o = -(*r).direction;
    // #each light
    for (var i = 0u; i < NUM_$TABLE; i++) {
        let light = sample_$kind((*hit).position, i);
        let cos_theta = max(dot((*hit).normal, light.w_i), 0.0);
        if (cos_theta == 0.0) {
            continue;
        }
        // #if shadows
        if (in_shadow((*hit).position, light.w_i, light.dist)) {
            continue;
        }
        // #endif
        result += brdf(hit, w_o, light.w_i, cos_theta) * light.L_i * cos_theta;
    }
    // #end
    return result;
}
