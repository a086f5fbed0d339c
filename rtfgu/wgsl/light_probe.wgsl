// #if light_probe|panoramic
// Suffern ch. 29's LightProbe (rtfgu/mappings/light_probe.py): Debevec's angular map of a
// unit sphere; panoramic takes acos(-z), the view from inside. On the z axis beta is 0.
fn light_probe(p: vec3f, panoramic: bool) -> vec2f
{
    let d = sqrt(p.x * p.x + p.y * p.y);
    var sin_beta = 0.0;
    var cos_beta = 1.0;
    if (d > 0.0) {
        sin_beta = p.y / d;
        cos_beta = p.x / d;
    }
    var z = p.z;
    if (panoramic) {
        z = -p.z;
    }
    let r = acos(clamp(z, -1.0, 1.0)) / PI;
    return vec2f((1.0 + r * cos_beta) * 0.5, (1.0 + r * sin_beta) * 0.5);
}
// #endif
