// An experiment of benchmarks/meshes.py ("rtfgu WGSL wide"), not a piece of the render: the
// closest-hit traversal of the numba path's wide BVH (rtfgu/accelerators/wide_bvh.py,
// rtfgu/kernels/wide_bvh.py) in WGSL, to compare with intersect_mesh.wgsl's binary one on the
// same rays. Faces only: a row of mesh_faces whose x is negative (a sphere or an instance in
// the BVH) is refused before upload (benchmarks/meshes.py, WgslWide.faces_only).
//
// Needs, from the program around it: wide_nodes (array<f32>: WideBVH.nodes as stored, node n
// at n * WIDE_ROWS * WIDE_WIDTH, row r of child j at r * WIDE_WIDTH + j; row WIDE_CODE_ROW
// holds the children's codes as int32 bits, read through bitcast<i32>), mesh_faces, and
// intersect_mesh.wgsl's Shear, ray_shear, intersect_face, safe_inverse and mesh_normal with
// CULL_WIDEN; the constants WIDE_WIDTH, WIDE_ROWS, WIDE_CODE_ROW, LEAF_BITS
// (rtfgu.accelerators.wide_bvh) and WIDE_STACK (rtfgu.kernels.wide_bvh.STACK).

// The t at which the ray enters child j's box of the wide node at base within [tmin, reach],
// or -1: intersect_mesh.wgsl's box_entry (the same operations in the same order), except that
// the near plane of an axis is chosen by the direction's sign as box8 does, not by comparing
// the two planes' ts, so that an empty column (lo = +inf, hi = -inf) is entered by no ray.
fn wide_child_entry(base: u32, j: u32, o: vec3f, d: vec3f, inv: vec3f, tmin: f32, reach: f32) -> f32
{
    let lo = vec3f(wide_nodes[base + j], wide_nodes[base + WIDE_WIDTH + j],
                   wide_nodes[base + 2u * WIDE_WIDTH + j]);
    let hi = vec3f(wide_nodes[base + 3u * WIDE_WIDTH + j], wide_nodes[base + 4u * WIDE_WIDTH + j],
                   wide_nodes[base + 5u * WIDE_WIDTH + j]);
    let a = (lo - o) * inv;
    let b = (hi - o) * inv;
    var t0 = tmin;
    var t1 = reach;
    for (var k = 0u; k < 3u; k++) {
        if (d[k] == 0.0) {
            if (o[k] < lo[k] || o[k] > hi[k]) {
                return -1.0;
            }
            continue;
        }
        var near = a[k];
        var far = b[k];
        if (d[k] < 0.0) {
            near = b[k];
            far = a[k];
        }
        // 1 + 2 gamma_3 in f32 (PBRT-v4 6.1.2), as box_entry.
        far = far * 1.0000003576;
        if (near > t0) { t0 = near; }
        if (far < t1) { t1 = far; }
    }
    if (t0 > t1) {
        return -1.0;
    }
    return t0;
}

// mesh_closest (intersect_mesh.wgsl) on the wide tree, faces only: every child of a node that
// the ray enters within the best t times CULL_WIDEN goes on the stack, sorted by its entry t
// so that the nearest is popped first (rtfgu.kernels.wide_bvh.enter_node), as its code (an
// inner child's node, a leaf's ~(first << LEAF_BITS | count - 1)). An entry popped beyond the best t times CULL_WIDEN is
// dropped. The leaf loop and the tie rule (of equal ts the face earlier in Scene.shapes wins)
// are mesh_closest's. root: the wide node of the tree (WideBVH.roots).
fn mesh_closest_wide(r: ptr<function, Ray>, hit: ptr<function, HitInfo>, shape: ptr<function, i32>,
                     kind: ptr<function, i32>, row: ptr<function, u32>, root: u32) -> bool
{
    let o = (*r).origin;
    let d = (*r).direction;
    let inv = safe_inverse(d);
    let sh = ray_shear((*r).direction);
    var code_stack: array<i32, WIDE_STACK>;
    var entry_stack: array<f32, WIDE_STACK>;
    var sp = 0u;
    var found = false;
    var code = i32(root);
    var live = true;
    while (live) {
        if (code >= 0) {
            let base = u32(code) * WIDE_ROWS * WIDE_WIDTH;
            let reach = (*r).tmax * CULL_WIDEN;
            let bottom = sp;
            for (var j = 0u; j < WIDE_WIDTH; j++) {
                let t = wide_child_entry(base, j, o, d, inv, (*r).tmin, reach);
                if (t < 0.0) {
                    continue;
                }
                let child = bitcast<i32>(wide_nodes[base + WIDE_CODE_ROW * WIDE_WIDTH + j]);
                var k = sp;
                while (k > bottom && entry_stack[k - 1u] < t) {
                    code_stack[k] = code_stack[k - 1u];
                    entry_stack[k] = entry_stack[k - 1u];
                    k--;
                }
                code_stack[k] = child;
                entry_stack[k] = t;
                sp++;
            }
        } else {
            let leaf = ~code;
            let first = u32(leaf >> LEAF_BITS);
            let last = first + u32(leaf & ((1 << LEAF_BITS) - 1)) + 1u;
            var q = *r;
            q.tmax = next_up((*r).tmax);
            for (var f = first; f < last; f++) {
                let face = mesh_faces[f];
                let t = intersect_face(q, sh, f);
                if (t >= 0.0 && (t < (*r).tmax || face.w < *shape)) {
                    (*r).tmax = t;
                    q.tmax = next_up(t);
                    *shape = face.w;
                    *kind = MESH;
                    *row = f;
                    found = true;
                }
            }
        }
        live = false;
        while (!live && sp > 0u) {
            sp--;
            if (entry_stack[sp] <= (*r).tmax * CULL_WIDEN) {
                code = code_stack[sp];
                live = true;
            }
        }
    }
    if (found) {
        (*hit).has_hit = true;
        (*hit).dist = (*r).tmax;
        (*hit).position = (*r).origin + (*r).direction * (*r).tmax;
        (*hit).normal = mesh_normal(*row, (*hit).position);
    }
    return found;
}
