// release: solves a05
// Refraction by Snell's law with relative index eta = n1 / n2 (PerfectTransmitter, rtfgu/btdfs/perfect_transmitter.py).
// w . n < 0: the ray enters (eta = 1 / ior); otherwise it leaves (eta = ior, normal
// flipped). With no real refracted direction (total internal reflection) it is mirrored,
// weighted by 1; otherwise the refracted ray is weighted by kt and, where kr cr is not 0,
// the reflected ray waits as the second ray (Transparent.shade, Suffern ch. 27).
fn transparent(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    let d = (*r).direction;
    var n = (*hit).normal;
    var cos_i = -dot(d, n);
    var eta: f32;
    if (cos_i >= 0.0) {
        eta = 1.0 / (*hit).ior;
    } else {
        eta = (*hit).ior;
        n = -n;
        cos_i = -cos_i;
    }
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t > 1.0) {
        continue_path(r, hit, d + n * (2.0 * cos_i), vec3f(1.0));
    } else {
        let cos_t = sqrt(1.0 - sin2_t);
        continue_path(r, hit, d * eta + n * (eta * cos_i - cos_t), vec3f((*hit).kt));
        // #if two_rays
        second_direction = d - (*hit).normal * (2.0 * dot(d, (*hit).normal));
        second_factor = (*hit).reflection;
        // #endif
    }
    return (*hit).emission;
}
