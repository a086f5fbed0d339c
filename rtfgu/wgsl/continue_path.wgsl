// The next ray of the path from the surface just hit: fresh tmax, so that it is not cut at
// the last hit's distance; has_hit cleared, so that main's loop goes on tracing.
fn continue_path(r: ptr<function, Ray>, hit: ptr<function, HitInfo>, direction: vec3f)
{
    (*r).origin = (*hit).position;
    (*r).direction = direction;
    (*r).tmin = SPAWN_EPSILON;
    (*r).tmax = FAR;
    (*hit).has_hit = false;
}
