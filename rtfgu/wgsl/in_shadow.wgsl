// release: solves a05
// A shadow ray toward the light: is any shape hit strictly before it? It starts
// SPAWN_EPSILON off the surface so that it does not hit the surface it leaves.
fn in_shadow(position: vec3f, w_i: vec3f, dist: f32) -> bool
{
    let shadow_ray = Ray(position, w_i, SPAWN_EPSILON, dist - SPAWN_EPSILON);
    var shadow_hit = empty_hit();
    // #each row
    for (var i = 0u; i < NUM_$TABLE; i++) {
        let rec = $table[i];
        if (intersect_$kind(shadow_ray, &shadow_hit, $args)) {
            return true;
        }
    }
    // #end
    // #if mesh
    if (mesh_any(shadow_ray, 0u)) {
        return true;
    }
    // #endif
    return false;
}
