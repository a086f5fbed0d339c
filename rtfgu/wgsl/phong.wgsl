// release: solves a05
// Lambertian plus the normalised Phong lobe (02562 worksheet 3; Phong):
//   f_r = rho_d / pi + rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s
// with w_r = 2 (n . w_i) n - w_i, the mirrored light direction.
fn brdf_phong(hit: ptr<function, HitInfo>, w_o: vec3f, w_i: vec3f, cos_theta: f32) -> vec3f
{
    let rho_d = (*hit).color * (*hit).kd;
    let w_r = (*hit).normal * (2.0 * cos_theta) - w_i;
    let cos_r = max(dot(w_o, w_r), 0.0);
    // WGSL leaves pow(0, 0) undefined; Python's 0 ** 0 is 1.
    let lobe_cos = select(pow(cos_r, (*hit).shininess), 1.0, (*hit).shininess == 0.0);
    let lobe = (*hit).specular * (((*hit).shininess + 2.0) / (2.0 * PI) * lobe_cos);
    return rho_d / PI + lobe;
}
