// release: solves a03
// The slide's hit record (02562, "struct HitInfo"): the ray meets the shape at distance t,
// at position, where the shape's normal is normal. True, for the intersection function to
// return (the box's and the torus's, which compute the normal from the position).
fn record_hit(hit: ptr<function, HitInfo>, t: f32, position: vec3f, normal: vec3f) -> bool
{
    (*hit).has_hit = true;
    (*hit).dist = t;
    (*hit).position = position;
    (*hit).normal = normal;
    return true;
}
