// release: solves a13
// An instance (Suffern ch. 21, "Instancing"; rtfgu.shapes.instance): its object hit by the
// ray through the inverse matrix (rows row0, row1, row2, the translation t0, t1, t2 after
// each), the direction not normalised so that t is the same in both spaces; the object's
// normal through the transpose of the inverse, normalised. The object is row object_row of
// the instanced table of its kind object_kind, reached through the switch below, which names
// only the kinds the scene's instances hold.
//
// An instanced mesh (one mesh, many instances: rtfgu.layout.compile_mesh) is the tree whose
// first node is object_row, its faces' w their place in the mesh. As the lecture layer traces
// an Instance of a Mesh (an Instance of each face, Instance.parts), the instance's hit is its
// first index plus the face's place (instanced_place, which intersect_scene adds), and the
// face it hit (candidate_face) is kept as instanced_face where intersect_scene keeps the hit,
// for the face's (u, v) (texcoord.wgsl).
// #if instanced_mesh
var<private> instanced_place: i32;
var<private> candidate_face: u32;
var<private> instanced_face: u32;
// #endif

fn intersect_instanced(r: Ray, hit: ptr<function, HitInfo>, kind: i32, row: u32) -> bool
{
    // #if instanced_mesh
    instanced_place = 0;
    if (kind == MESH) {
        var q = r;
        var place = -1;      // no face earlier in Scene.shapes than the first one hit
        var mesh_kind = -1;
        var face = 0u;
        // #if bvh_instances
        // The scene's tree holds this instance: its own copy of the traversal (assemble.py).
        if (object_mesh_closest(&q, hit, &place, &mesh_kind, &face, row)) {
        // #else
        if (mesh_closest(&q, hit, &place, &mesh_kind, &face, row)) {
        // #endif
            instanced_place = place;
            candidate_face = face;
            return true;
        }
        return false;
    }
    // #endif
    // #each instanced
    if (kind == $KIND) {
        let rec = $table[row];
        return intersect_$kind(r, hit, $args);
    }
    // #end
    return false;
}

fn intersect_instance(r: Ray, hit: ptr<function, HitInfo>, row0: vec3f, t0: f32, row1: vec3f, t1: f32,
                      row2: vec3f, t2: f32, object_kind: f32, object_row: f32) -> bool
{
    let origin = vec3f(dot(row0, r.origin) + t0, dot(row1, r.origin) + t1, dot(row2, r.origin) + t2);
    let direction = vec3f(dot(row0, r.direction), dot(row1, r.direction), dot(row2, r.direction));
    if (!intersect_instanced(Ray(origin, direction, r.tmin, r.tmax), hit, i32(object_kind), u32(object_row))) {
        return false;
    }
    let n = (*hit).normal;
    (*hit).normal = normalize(row0 * n.x + row1 * n.y + row2 * n.z);
    (*hit).position = r.origin + r.direction * (*hit).dist;
    return true;
}
