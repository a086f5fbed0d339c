// The next ray of the path from the surface just hit: fresh tmax, so that it is not cut at
// the last hit's distance; has_hit cleared, so that main's loop goes on tracing. ``weight``
// is what the radiance the new ray brings back is multiplied by (kr cr after a mirror, kt
// after a refraction; 1 in the 02562 shaders); a shader that also sends a second ray (a
// Transparent's reflection) sets second_direction and second_factor after this call, and
// main's loop keeps that ray until the first path ends (rtfgu.kernels.render.trace).
var<private> factor: vec3f;
var<private> second_direction: vec3f;
var<private> second_factor: vec3f;

fn continue_path(r: ptr<function, Ray>, hit: ptr<function, HitInfo>, direction: vec3f, weight: vec3f)
{
    (*r).origin = (*hit).position;
    (*r).direction = direction;
    (*r).tmin = SPAWN_EPSILON;
    (*r).tmax = FAR;
    (*hit).has_hit = false;
    factor = weight;
    second_factor = vec3f(0.0);
}
