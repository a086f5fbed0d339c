// release: solves a03 a08
// Triangle meshes (Suffern ch. 23) through a BVH, as rtfgu/kernels/mesh.py does on the numba
// path. The scene's mesh triangles arrive in storage buffers (rtfgu.layout.FlatMesh):
//   mesh_vertices  3 floats per vertex
//   mesh_faces     vec4i per face: [i0, i1, i2, place in Scene.shapes], in BVH leaf order
//   mesh_normals   3 floats per vertex (zero for a flat mesh's), only if a mesh is smooth
//   mesh_uvs       (u, v, 1) per vertex ((0, 0, 0) for a mesh without uvs), only if a mesh
//                  has uvs and a texture of the scene reads (u, v)
//   bvh_nodes      the BVH (rtfgu.accelerators.flat_bvh): a leaf has b = its face count and
//                  a = its first face; an inner node b = 0 and its children at a and a + 1.
// With the feature bvh_spheres the BVH holds the spheres too: a row [-1, row in spheres, 0,
// place in Scene.shapes] of mesh_faces is that sphere (rtfgu.layout.FlatMesh); with
// bvh_instances the instances, a row [-2, row in instances, 0, place in Scene.shapes]
// (never with instanced_mesh: an instance's mesh would enter mesh_closest from inside it).
// A face is hit where the watertight test hits it (Woop, Benthin and Wald 2013, as in
// robust_triangle.wgsl, with the ray's shear computed once per ray): faces that share an
// edge compute its edge function from the same two vertices, so no ray leaks through it.

struct BVHNode {
    lo: vec3f,
    a: i32,
    hi: vec3f,
    b: i32
};

// The deepest path from the root to a leaf that the build allows (flat_bvh.MAX_DEPTH).
const BVH_STACK = 64u;
// 1 + 2 gamma_3 in f32: mesh_closest drops a box entered beyond the best t times this, so that
// the entry's rounding never drops a box whose face ties the best t (rtfgu/kernels/mesh.py).
const CULL_WIDEN = 1.0000003576;

struct Shear {
    kx: u32,
    ky: u32,
    kz: u32,
    s: vec3f  // Sx, Sy, Sz
};

fn ray_shear(w: vec3f) -> Shear
{
    let aw = abs(w);
    var kz = 2u;
    if (aw.x > aw.y) {
        if (aw.x > aw.z) { kz = 0u; }
    } else if (aw.y > aw.z) {
        kz = 1u;
    }
    var kx = kz + 1u;
    if (kx == 3u) { kx = 0u; }
    var ky = kx + 1u;
    if (ky == 3u) { ky = 0u; }
    if (w[kz] < 0.0) {
        let swap = kx;
        kx = ky;
        ky = swap;
    }
    return Shear(kx, ky, kz, vec3f(w[kx] / w[kz], w[ky] / w[kz], 1.0 / w[kz]));
}

fn mesh_vertex(i: i32) -> vec3f
{
    let k = 3u * u32(i);
    return vec3f(mesh_vertices[k], mesh_vertices[k + 1u], mesh_vertices[k + 2u]);
}

// t of face f in [tmin, tmax), or -1 for a miss.
fn intersect_face(r: Ray, sh: Shear, f: u32) -> f32
{
    let face = mesh_faces[f];
    let A = mesh_vertex(face.x) - r.origin;
    let B = mesh_vertex(face.y) - r.origin;
    let C = mesh_vertex(face.z) - r.origin;
    let Ax = A[sh.kx] - sh.s.x * A[sh.kz];
    let Ay = A[sh.ky] - sh.s.y * A[sh.kz];
    let Bx = B[sh.kx] - sh.s.x * B[sh.kz];
    let By = B[sh.ky] - sh.s.y * B[sh.kz];
    let Cx = C[sh.kx] - sh.s.x * C[sh.kz];
    let Cy = C[sh.ky] - sh.s.y * C[sh.kz];
    let U = Cx * By - Cy * Bx;
    let V = Ax * Cy - Ay * Cx;
    let W = Bx * Ay - By * Ax;
    if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) {
        return -1.0;
    }
    let det = U + V + W;
    if (det == 0.0) {
        return -1.0;
    }
    let t = (U * (sh.s.z * A[sh.kz]) + V * (sh.s.z * B[sh.kz]) + W * (sh.s.z * C[sh.kz])) / det;
    if (t >= r.tmin && t < r.tmax) {
        return t;
    }
    return -1.0;
}

// BBox.hit for a node: the t at which the ray enters its box within [tmin, tmax], or -1.
// inv = 1 / direction where direction is not 0. A zero component gives no interval: the ray
// is in that slab for every t or for none (WGSL leaves 1 / 0 and 0 * inf undefined).
fn box_entry(n: u32, o: vec3f, d: vec3f, inv: vec3f, tmin: f32, tmax: f32) -> f32
{
    let node = bvh_nodes[n];
    let a = (node.lo - o) * inv;
    let b = (node.hi - o) * inv;
    var t0 = tmin;
    var t1 = tmax;
    for (var k = 0u; k < 3u; k++) {
        if (d[k] == 0.0) {
            if (o[k] < node.lo[k] || o[k] > node.hi[k]) {
                return -1.0;
            }
            continue;
        }
        var near = a[k];
        var far = b[k];
        if (near > far) {
            near = b[k];
            far = a[k];
        }
        // 1 + 2 gamma_3 in f32 (PBRT-v4 6.1.2): rounding never drops a box the face hits.
        far = far * 1.0000003576;
        if (near > t0) { t0 = near; }
        if (far < t1) { t1 = far; }
    }
    if (t0 > t1) {
        return -1.0;
    }
    return t0;
}

// 1 / d, with 1 where d is 0 (box_entry does not use those).
fn safe_inverse(d: vec3f) -> vec3f
{
    return 1.0 / select(d, vec3f(1.0), d == vec3f(0.0));
}

// The edges e0 = v1 - v0, e1 = v2 - v0 of face f and its v0.
fn face_frame(f: u32) -> array<vec3f, 3>
{
    let face = mesh_faces[f];
    let v0 = mesh_vertex(face.x);
    return array<vec3f, 3>(v0, mesh_vertex(face.y) - v0, mesh_vertex(face.z) - v0);
}

// #if smooth_mesh|texcoord
// The barycentric (beta, gamma) of p on face f (Triangle.texcoord).
fn face_barycentrics(f: u32, p: vec3f) -> vec2f
{
    let v = face_frame(f);
    let n = cross(v[1], v[2]);
    let d = p - v[0];
    let nn = dot(n, n);
    return vec2f(dot(cross(d, v[2]), n) / nn, dot(cross(v[1], d), n) / nn);
}
// #endif

// The normal of face f at p: the face's (FlatMeshTriangle), or its vertex normals
// interpolated with p's barycentrics (SmoothMeshTriangle).
fn mesh_normal(f: u32, p: vec3f) -> vec3f
{
    // #if smooth_mesh
    let face = mesh_faces[f];
    let b = face_barycentrics(f, p);
    let m = mesh_normal_at(face.x) * (1.0 - b.x - b.y) + mesh_normal_at(face.y) * b.x
          + mesh_normal_at(face.z) * b.y;
    if (dot(m, m) != 0.0) {
        return normalize(m);
    }
    // #endif
    let v = face_frame(f);
    return normalize(cross(v[1], v[2]));
}

// #if smooth_mesh
fn mesh_normal_at(i: i32) -> vec3f
{
    let k = 3u * u32(i);
    return vec3f(mesh_normals[k], mesh_normals[k + 1u], mesh_normals[k + 2u]);
}
// #endif

// #if texcoord
// MeshTriangle.texcoord: the barycentrics, or with uvs the corners' (u, v) interpolated with
// them (Suffern's UV mesh triangles).
fn texcoord_mesh(p: vec3f, f: u32) -> vec2f
{
    let b = face_barycentrics(f, p);
    // #if uv_mesh
    let face = vec3u(mesh_faces[f].xyz);
    if (mesh_uvs[3u * face.x + 2u] != 0.0) {
        let alpha = 1.0 - b.x - b.y;
        return alpha * mesh_uv(face.x) + b.x * mesh_uv(face.y) + b.y * mesh_uv(face.z);
    }
    // #endif
    return b;
}

// #if uv_mesh
fn mesh_uv(i: u32) -> vec2f
{
    return vec2f(mesh_uvs[3u * i], mesh_uvs[3u * i + 1u]);
}
// #endif
// #endif

// The nearest face hit before (*r).tmax, nearer child first; of equal ts the face earlier in
// Scene.shapes wins, as in intersect_scene. Updates *r, *hit, *shape and *row on a hit.
// root: the tree's first node (the scene's, 0; an instanced mesh's, whose faces' w is their
// place in the mesh: intersect_instance.wgsl).
fn mesh_closest(r: ptr<function, Ray>, hit: ptr<function, HitInfo>, shape: ptr<function, i32>,
                kind: ptr<function, i32>, row: ptr<function, u32>, root: u32) -> bool
{
    var shape_hit = *hit;
    var face_hit = false;
    let o = (*r).origin;
    let d = (*r).direction;
    let inv = safe_inverse(d);
    let sh = ray_shear((*r).direction);
    var node_stack: array<u32, BVH_STACK>;
    var entry_stack: array<f32, BVH_STACK>;
    var sp = 0u;
    var found = false;
    var node = root;
    var live = box_entry(root, o, d, inv, (*r).tmin, (*r).tmax * CULL_WIDEN) >= 0.0;
    while (live) {
        let links = bvh_nodes[node];
        if (links.b > 0) {
            var q = *r;
            q.tmax = next_up((*r).tmax);
            for (var f = u32(links.a); f < u32(links.a + links.b); f++) {
                let face = mesh_faces[f];
                // #if bvh_spheres|bvh_instances
                // A row of the sphere table (face.x -1) or of the instance table (-2).
                if (face.x < 0) {
                    var candidate = *hit;
                    var hit_row = false;
                    var row_kind = SPHERE;
                    var index = face.w;
                    // #if bvh_spheres
                    if (face.x == -1) {
                        let rec = spheres[face.y];
                        hit_row = intersect_sphere(q, &candidate, rec.center, rec.radius);
                    }
                    // #endif
                    // #if bvh_instances
                    if (face.x == -2) {
                        let rec = instances[face.y];
                        hit_row = intersect_instance(q, &candidate, rec.row0, rec.t0, rec.row1, rec.t1, rec.row2,
                                                     rec.t2, rec.object_kind, rec.object_row);
                        row_kind = INSTANCE;
                        // #if instanced_mesh
                        index += instanced_place;   // an instance of a Mesh: the face's place
                        // #endif
                    }
                    // #endif
                    if (hit_row && (candidate.dist < (*r).tmax || index < *shape)) {
                        shape_hit = candidate;
                        (*r).tmax = candidate.dist;
                        q.tmax = next_up(candidate.dist);
                        *shape = index;
                        // #if bvh_instances
                        // #if instanced_mesh
                        instanced_face = candidate_face;
                        // #endif
                        // #endif
                        *kind = row_kind;
                        *row = u32(face.y);
                        found = true;
                        face_hit = false;
                    }
                    continue;
                }
                // #endif
                let t = intersect_face(q, sh, f);
                if (t >= 0.0 && (t < (*r).tmax || face.w < *shape)) {
                    (*r).tmax = t;
                    q.tmax = next_up(t);
                    *shape = face.w;
                    *kind = MESH;
                    *row = f;
                    found = true;
                    face_hit = true;
                }
            }
            live = false;
        } else {
            let left = u32(links.a);
            let t_left = box_entry(left, o, d, inv, (*r).tmin, (*r).tmax * CULL_WIDEN);
            let t_right = box_entry(left + 1u, o, d, inv, (*r).tmin, (*r).tmax * CULL_WIDEN);
            if (t_left >= 0.0 && t_right >= 0.0) {
                var near = left;
                var far = left + 1u;
                var t_far = t_right;
                if (t_right < t_left) {
                    near = left + 1u;
                    far = left;
                    t_far = t_left;
                }
                node_stack[sp] = far;
                entry_stack[sp] = t_far;
                sp++;
                node = near;
            } else if (t_left >= 0.0) {
                node = left;
            } else if (t_right >= 0.0) {
                node = left + 1u;
            } else {
                live = false;
            }
        }
        while (!live && sp > 0u) {
            sp--;
            if (entry_stack[sp] <= (*r).tmax * CULL_WIDEN) {
                node = node_stack[sp];
                live = true;
            }
        }
    }
    if (face_hit) {
        (*hit).has_hit = true;
        (*hit).dist = (*r).tmax;
        (*hit).position = (*r).origin + (*r).direction * (*r).tmax;
        (*hit).normal = mesh_normal(*row, (*hit).position);
    } else if (found) {
        *hit = shape_hit;
    }
    return found;
}

// A shadow ray: is any face hit in [tmin, tmax)?
fn mesh_any(r: Ray, root: u32) -> bool
{
    let d = r.direction;
    let inv = safe_inverse(d);
    let sh = ray_shear(r.direction);
    var node_stack: array<u32, BVH_STACK>;
    var sp = 0u;
    var node = root;
    var live = box_entry(root, r.origin, d, inv, r.tmin, r.tmax) >= 0.0;
    while (live) {
        let links = bvh_nodes[node];
        if (links.b > 0) {
            for (var f = u32(links.a); f < u32(links.a + links.b); f++) {
                // #if bvh_spheres|bvh_instances
                let face = mesh_faces[f];
                // #endif
                // #if bvh_spheres
                if (face.x == -1) {
                    let rec = spheres[face.y];
                    var candidate = empty_hit();
                    if (intersect_sphere(r, &candidate, rec.center, rec.radius)) {
                        return true;
                    }
                    continue;
                }
                // #endif
                // #if bvh_instances
                if (face.x == -2) {
                    let rec = instances[face.y];
                    var candidate = empty_hit();
                    if (intersect_instance(r, &candidate, rec.row0, rec.t0, rec.row1, rec.t1, rec.row2, rec.t2,
                                           rec.object_kind, rec.object_row)) {
                        return true;
                    }
                    continue;
                }
                // #endif
                if (intersect_face(r, sh, f) >= 0.0) {
                    return true;
                }
            }
            live = false;
        } else {
            let left = u32(links.a);
            let hit_left = box_entry(left, r.origin, d, inv, r.tmin, r.tmax) >= 0.0;
            let hit_right = box_entry(left + 1u, r.origin, d, inv, r.tmin, r.tmax) >= 0.0;
            if (hit_left && hit_right) {
                node_stack[sp] = left + 1u;
                sp++;
                node = left;
            } else if (hit_left) {
                node = left;
            } else if (hit_right) {
                node = left + 1u;
            } else {
                live = false;
            }
        }
        if (!live && sp > 0u) {
            sp--;
            node = node_stack[sp];
            live = true;
        }
    }
    return false;
}
