// release: solves a04
// A diffuse surface (02562, "Lambert's cosine law"): f_r = rho_d / pi with rho_d = 90 % of
// the object's colour (rtfgu.shading.lambertian); direct_light adds L_i (n . w_i).
fn brdf_lambertian(hit: ptr<function, HitInfo>, w_o: vec3f, w_i: vec3f, cos_theta: f32) -> vec3f
{
    return (*hit).color * DIFFUSE_FRACTION / PI;
}
