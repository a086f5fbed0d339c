// release: solves a04
// A diffuse surface (02562, "Lambert's cosine law"): f_r = kd cd / pi (Lambertian.f,
// rtfgu/brdfs/lambertian.py; the 02562 kd is 0.9); direct_light adds L_i (n . w_i).
fn brdf_lambertian(hit: ptr<function, HitInfo>, w_o: vec3f, w_i: vec3f, cos_theta: f32) -> vec3f
{
    return (*hit).color * (*hit).kd / PI;
}
