// The slide's intersect_scene: every shape of every kind in turn; each hit shrinks
// (*r).tmax, so the last shape that reports a hit is the nearest one. The material of that
// shape is then copied into the hit (rtfgu.scene.Scene.intersect). Shapes are visited kind
// by kind (planes, triangles, spheres), so of two shapes of different kinds at exactly the
// same distance the first kind wins; the reference visits Scene.shapes in their order.

// Index arrays (int32) arrive packed four to a vec4i (a uniform array needs a 16-byte
// stride): entry k is [k / 4][k % 4].
// #if shapes
fn set_material(hit: ptr<function, HitInfo>, k: u32)
{
    let m = materials[k];
    (*hit).color = m.color;
    (*hit).shader = shaders[k / 4u][k % 4u];
    (*hit).specular = m.specular;
    (*hit).shininess = m.shininess;
    (*hit).ior = m.ior;
    (*hit).emission = m.emission;
}
// #endif

fn intersect_scene(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> bool
{
    var shape = -1;  // place in Scene.shapes of the nearest shape hit so far
    // #if plane
    for (var i = 0u; i < NUM_PLANES; i++) {
        if (intersect_plane(*r, hit, planes[i].point, planes[i].normal)) {
            (*r).tmax = (*hit).dist;
            shape = plane_index[i / 4u][i % 4u];
        }
    }
    // #endif
    // #if triangle
    for (var i = 0u; i < NUM_TRIANGLES; i++) {
        let tri = triangles[i];
        if (intersect_triangle(*r, hit, tri.v0, tri.e0, tri.e1, tri.n)) {
            (*r).tmax = (*hit).dist;
            shape = triangle_index[i / 4u][i % 4u];
        }
    }
    // #endif
    // #if sphere
    for (var i = 0u; i < NUM_SPHERES; i++) {
        if (intersect_sphere(*r, hit, spheres[i].center, spheres[i].radius)) {
            (*r).tmax = (*hit).dist;
            shape = sphere_index[i / 4u][i % 4u];
        }
    }
    // #endif
    // #if shapes
    if (shape >= 0) {
        set_material(hit, u32(shape));
    }
    // #endif
    return (*hit).has_hit;
}
