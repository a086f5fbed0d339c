// release: solves a13
// An instance (Suffern ch. 21, "Instancing"; rtfgu.shapes.instance): its object hit by the
// ray through the inverse matrix (rows row0, row1, row2, the translation t0, t1, t2 after
// each), the direction not normalised so that t is the same in both spaces; the object's
// normal through the transpose of the inverse, normalised. The object is row object_row of
// the instanced table of its kind object_kind, reached through the switch below, which names
// only the kinds the scene's instances hold.
fn intersect_instanced(r: Ray, hit: ptr<function, HitInfo>, kind: i32, row: u32) -> bool
{
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
