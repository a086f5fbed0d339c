// Texture coordinates (u, v) of a point on each shape kind, as Shape.texcoord in the
// lecture layer (rtfgu/shapes/): worksheet 3's plane frame, Suffern's SphericalMap, the
// triangle's barycentrics, the rectangle's edge projections, the box's face frame and
// Suffern's CylindricalMap (a part object's are its whole shape's). shape_texcoord picks the
// function of the kind hit.
// #if plane|disk|annulus|instanced_plane|instanced_disk|instanced_annulus
fn texcoord_plane(p: vec3f, point: vec3f, normal: vec3f) -> vec2f
{
    let n = normalize(normal);
    var binormal = vec3f(0.0, 0.0, 1.0) - n * n.z;
    if (dot(binormal, binormal) < 1e-12) {
        binormal = vec3f(1.0, 0.0, 0.0) - n * n.x;
    }
    binormal = normalize(binormal);
    let tangent = cross(binormal, n);
    let d = p - point;
    return vec2f(dot(d, tangent), dot(d, binormal));
}
// #endif
// #if disk|instanced_disk
fn texcoord_disk(p: vec3f, center: vec3f, normal: vec3f, radius: f32) -> vec2f
{
    return texcoord_plane(p, center, normal);
}
// #endif
// #if rectangle|instanced_rectangle
fn texcoord_rectangle(p: vec3f, p0: vec3f, a: vec3f, b: vec3f, normal: vec3f) -> vec2f
{
    let d = p - p0;
    return vec2f(dot(d, a) / dot(a, a), dot(d, b) / dot(b, b));
}
// #endif
// #if box|instanced_box
fn texcoord_box(p: vec3f, p0: vec3f, p1: vec3f) -> vec2f
{
    let axis = box_face(p, p0, p1) % 3u;
    let i = (axis + 1u) % 3u;
    let j = (axis + 2u) % 3u;
    return vec2f((p[i] - p0[i]) / (p1[i] - p0[i]), (p[j] - p0[j]) / (p1[j] - p0[j]));
}
// #endif
// #if open_cylinder|open_part_cylinder|instanced_open_cylinder|instanced_open_part_cylinder
fn texcoord_open_cylinder(p: vec3f, y0: f32, y1: f32, radius: f32) -> vec2f
{
    var phi = atan2(p.x, p.z);
    if (phi < 0.0) {
        phi += 2.0 * PI;
    }
    return vec2f(phi / (2.0 * PI), (p.y - y0) / (y1 - y0));
}
// #endif
// #if torus|instanced_torus
fn texcoord_torus(p: vec3f, a: f32, b: f32) -> vec2f
{
    var phi = atan2(p.x, p.z);
    if (phi < 0.0) {
        phi += 2.0 * PI;
    }
    var theta = atan2(p.y, sqrt(p.x * p.x + p.z * p.z) - a);
    if (theta < 0.0) {
        theta += 2.0 * PI;
    }
    return vec2f(phi / (2.0 * PI), theta / (2.0 * PI));
}
// #endif
// #if sphere|convex_part_sphere|concave_part_sphere|instanced_sphere|instanced_convex_part_sphere|instanced_concave_part_sphere
fn texcoord_sphere(p: vec3f, center: vec3f, radius: f32) -> vec2f
{
    let d = p - center;
    let theta = acos(clamp(d.y / radius, -1.0, 1.0));
    var phi = atan2(d.x / radius, d.z / radius);
    if (phi < 0.0) {
        phi += 2.0 * PI;
    }
    return vec2f(phi / (2.0 * PI), 1.0 - theta / PI);
}
// #endif
// #if annulus|instanced_annulus
fn texcoord_annulus(p: vec3f, center: vec3f, normal: vec3f, inner_radius: f32, outer_radius: f32) -> vec2f
{
    return texcoord_plane(p, center, normal);
}
// #endif
// #if open_part_cylinder|instanced_open_part_cylinder
fn texcoord_open_part_cylinder(p: vec3f, y0: f32, y1: f32, radius: f32, phi_min: f32, phi_max: f32) -> vec2f
{
    return texcoord_open_cylinder(p, y0, y1, radius);
}
// #endif
// #if convex_part_sphere|instanced_convex_part_sphere
fn texcoord_convex_part_sphere(p: vec3f, center: vec3f, radius: f32, phi_min: f32, phi_max: f32,
                               cos_theta_min: f32, cos_theta_max: f32) -> vec2f
{
    return texcoord_sphere(p, center, radius);
}
// #endif
// #if concave_part_sphere|instanced_concave_part_sphere
fn texcoord_concave_part_sphere(p: vec3f, center: vec3f, radius: f32, phi_min: f32, phi_max: f32,
                                cos_theta_min: f32, cos_theta_max: f32) -> vec2f
{
    return texcoord_sphere(p, center, radius);
}
// #endif
// #if triangle|instanced_triangle
fn texcoord_triangle(p: vec3f, v0: vec3f, e0: vec3f, e1: vec3f, n: vec3f) -> vec2f
{
    let d = p - v0;
    let nn = dot(n, n);
    return vec2f(dot(cross(d, e1), n) / nn, dot(cross(e0, d), n) / nn);
}
// #endif

// #if instance
// An instance's (u, v): its object's at the point through the inverse matrix
// (Instance.texcoord), the object found as intersect_instanced finds it.
fn instanced_texcoord(kind: i32, row: u32, p: vec3f) -> vec2f
{
    // #if instanced_mesh
    if (kind == MESH) {
        return texcoord_mesh(p, instanced_face);
    }
    // #endif
    // #each instanced
    if (kind == $KIND) {
        let rec = $table[row];
        return texcoord_$kind(p, $args);
    }
    // #end
    return vec2f(0.0);
}

fn texcoord_instance(p: vec3f, row0: vec3f, t0: f32, row1: vec3f, t1: f32, row2: vec3f, t2: f32,
                     object_kind: f32, object_row: f32) -> vec2f
{
    let q = vec3f(dot(row0, p) + t0, dot(row1, p) + t1, dot(row2, p) + t2);
    return instanced_texcoord(i32(object_kind), u32(object_row), q);
}
// #endif

fn shape_texcoord(kind: i32, row: u32, p: vec3f) -> vec2f
{
    // #each shape
    if (kind == $KIND) {
        let rec = $table[row];
        return texcoord_$kind(p, $args);
    }
    // #end
    // #if mesh
    if (kind == MESH) {
        return texcoord_mesh(p, row);
    }
    // #endif
    return vec2f(0.0);
}
