// The slide's intersect_scene: every shape of every kind in turn; each hit shrinks
// (*r).tmax, so the last shape that reports a hit is the nearest one. The material of that
// shape is then copied into the hit (rtfgu.scene.Scene.intersect).
//
// One rule for ties on every path: of two shapes at the same distance, the one earlier in
// Scene.shapes wins, as in the reference's loop over Scene.shapes. Shapes are visited kind
// by kind, so each is tested up to the next float above the nearest t so far (t <= tmax),
// and a hit at exactly that t counts only for a shape earlier than the one it would replace.

// Index arrays (int32) arrive packed four to a vec4i (a uniform array needs a 16-byte
// stride): entry k is [k / 4][k % 4].
// #if shapes
// Shape k's row in the distinct materials and their shaders (rtfgu.layout.FlatScene).
fn material_row(k: u32) -> u32
{
    return u32(material_of[k / 4u][k % 4u]);
}

fn set_material(hit: ptr<function, HitInfo>, k: u32, kind: i32, row: u32)
{
    let j = material_row(k);
    let m = materials[j];
    (*hit).color = m.color;
    // #if textures
    // A texture's colour at the hit replaces the shape's (rtfgu.scene.Scene.intersect).
    if (m.texture >= 0.0) {
        // #if texcoord
        let uv = shape_texcoord(kind, row, (*hit).position);
        // #else
        let uv = vec2f(0.0);      // only solid textures: they read the point
        // #endif
        // #each texture
        if (i32(m.texture) == $ID) {
            (*hit).color = texture_$kind(u32(m.texture_row), uv, (*hit).position);
        }
        // #end
    }
    // #endif
    (*hit).shader = shaders[j / 4u][j % 4u];
    (*hit).specular = m.specular;
    (*hit).shininess = m.shininess;
    (*hit).ior = m.ior;
    (*hit).emission = m.emission;
    (*hit).kd = m.kd;
    (*hit).ambient = m.ambient;
    (*hit).reflection = m.reflection;
    (*hit).kt = m.kt;
}
// #endif

// The next f32 above x, for 0 <= x < infinity.
fn next_up(x: f32) -> f32
{
    return bitcast<f32>(bitcast<u32>(x) + 1u);
}

// #if debug|dielectric|own_sampler
// The place in Scene.shapes of the shape the last intersect_scene hit, -1 for none: for the
// pixel debugger (debug_main.wgsl), a path through a dielectric (its absorption) and a BRDF
// with a sampler of its own (its material's row).
var<private> hit_shape: i32;
// #endif

fn intersect_scene(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> bool
{
    var shape = -1;  // place in Scene.shapes of the nearest shape hit so far
    var kind = -1;   // its kind and row in that kind's table
    var row = 0u;
    var q = *r;
    q.tmax = next_up((*r).tmax);
    var candidate = *hit;
    // #each row
    for (var i = 0u; i < NUM_$TABLE; i++) {
        let rec = $table[i];
        if (intersect_$kind(q, &candidate, $args)) {
            let index = $index[i / 4u][i % 4u]$place;
            if (candidate.dist < (*r).tmax || index < shape) {
                *hit = candidate;
                (*r).tmax = candidate.dist;
                q.tmax = next_up(candidate.dist);
                shape = index;
                kind = $KIND;
                row = i;
                $keep
            }
        }
    }
    // #end
    // #if mesh
    // The mesh triangles (and the spheres, with bvh_spheres): through the BVH
    // (intersect_mesh.wgsl), with the same tie rule.
    mesh_closest(r, hit, &shape, &kind, &row, 0u);
    // #endif
    // #if debug|dielectric|own_sampler
    hit_shape = shape;
    // #endif
    // #if shapes
    if (shape >= 0) {
        set_material(hit, u32(shape), kind, row);
    }
    // #endif
    return (*hit).has_hit;
}
