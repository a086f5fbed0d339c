// release: solves a05 a11
// A dielectric in the ray-cast loop (rtfgu.materials.Dielectric): it refracts as transparent does;
// the path tracer's Fresnel choice is in path_trace.wgsl.
fn dielectric(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    return transparent(r, hit);
}

// #if path_trace
// Fresnel's reflectance R for unpolarised light, 1 under total internal reflection
// (rtfgu.brdfs.fresnel_reflector.fresnel_reflectance).
fn fresnel_reflectance(cos_i: f32, eta: f32) -> f32
{
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) {
        return 1.0;
    }
    let cos_t = sqrt(1.0 - sin2_t);
    let r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_par = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (r_perp * r_perp + r_par * r_par);
}

// The next direction: reflected if xi < R, refracted otherwise (rtfgu.materials.dielectric.scatter).
fn scatter(direction: vec3f, normal: vec3f, ior: f32, xi: f32) -> vec3f
{
    var cos_i = -dot(direction, normal);
    var eta = 1.0 / ior;
    var n = normal;
    if (cos_i < 0.0) {
        eta = ior;
        n = -normal;
        cos_i = -cos_i;
    }
    if (xi < fresnel_reflectance(cos_i, eta)) {
        return direction + n * (2.0 * cos_i);
    }
    let cos_t = sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i));
    return direction * eta + n * (eta * cos_i - cos_t);
}
// #endif
