// release: solves a09
// A direction about +z with density (e + 1) / (2 pi) cos^e(theta), as Suffern's
// Sampler::map_samples_to_hemisphere (rtfgu/sampling/maps.py); e = 1 is cosine-weighted.
fn hemisphere_map(p: vec2f, e: f32) -> vec3f
{
    let cos_phi = cos(2.0 * PI * p.x);
    let sin_phi = sin(2.0 * PI * p.x);
    let cos_theta = pow(1.0 - p.y, 1.0 / (e + 1.0));
    let sin_theta = sqrt(1.0 - cos_theta * cos_theta);
    return vec3f(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta);
}
