// Ray-disk intersection (Suffern ch. 19, "Disks"; rtfgu.shapes.disk): the plane of the disk
// (intersect_plane), then the hit counts when (p - c) . (p - c) <= r^2.
fn intersect_disk(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, normal: vec3f, radius: f32) -> bool
{
    var on_plane = *hit;
    if (!intersect_plane(r, &on_plane, center, normal)) {
        return false;
    }
    let to_hit = on_plane.position - center;
    if (dot(to_hit, to_hit) <= radius * radius) {
        *hit = on_plane;
        return true;
    }
    return false;
}
