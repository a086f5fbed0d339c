// A shadow ray toward the light: is any shape hit strictly before it? It starts
// SPAWN_EPSILON off the surface so that it does not hit the surface it leaves.
fn in_shadow(position: vec3f, w_i: vec3f, dist: f32) -> bool
{
    let shadow_ray = Ray(position, w_i, SPAWN_EPSILON, dist - SPAWN_EPSILON);
    var shadow_hit = empty_hit();
    // #if plane
    for (var i = 0u; i < NUM_PLANES; i++) {
        if (intersect_plane(shadow_ray, &shadow_hit, planes[i].point, planes[i].normal)) {
            return true;
        }
    }
    // #endif
    // #if triangle
    for (var i = 0u; i < NUM_TRIANGLES; i++) {
        let tri = triangles[i];
        if (intersect_triangle(shadow_ray, &shadow_hit, tri.v0, tri.e0, tri.e1, tri.n)) {
            return true;
        }
    }
    // #endif
    // #if sphere
    for (var i = 0u; i < NUM_SPHERES; i++) {
        if (intersect_sphere(shadow_ray, &shadow_hit, spheres[i].center, spheres[i].radius)) {
            return true;
        }
    }
    // #endif
    return false;
}
