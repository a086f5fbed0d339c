// release: solves a03
// The hard-case program (rtfgu/hardcases/wgsl_path.py, run by rtfgu/wgsl/harness.py): one
// invocation per ray, against the shape in the ray's row. Features: the shape kind
// (sphere, plane, triangle, disk, rectangle, box,
// open_cylinder, torus, convex_part_sphere, annulus), the formula (slide, robust), and spawn (PBRT's offset
// origins of secondary rays instead of intersections). SHAPE_WIDTH is generated: the floats
// of one row, the lecture constructor's arguments before the colour (rtfgu.hardcases.kinds).

@group(0) @binding(0) var<storage, read> opaque_zero: array<u32>;  // [0]: 0, unknown to the compiler
@group(0) @binding(1) var<storage, read> rays: array<vec4f>;       // [o, tmin], [w, tmax]; spawn: [p, 0], [n, 0], [w, 0]
@group(0) @binding(2) var<storage, read> shapes: array<f32>;       // SHAPE_WIDTH floats per ray
@group(0) @binding(3) var<storage, read_write> result: array<vec4f>;  // [hit, t, 0, 0]; spawn: [origin, 0]

var<private> row: u32;

fn arg1(k: u32) -> f32
{
    return shapes[row * SHAPE_WIDTH + k];
}

fn arg3(k: u32) -> vec3f
{
    return vec3f(arg1(k), arg1(k + 1u), arg1(k + 2u));
}

// The render never passes a non-finite number (compile_scene refuses it); the hard cases
// do, and a robust test answers them with a miss. The test is on the bits: WGSL may assume
// finite floats and fold comparisons with NaN away.
fn finite4(v: vec4f) -> bool
{
    let e = bitcast<vec4u>(v) & vec4u(0x7f800000u);
    return all(e != vec4u(0x7f800000u));
}

fn finite_input(a: vec4f, b: vec4f) -> bool
{
    var ok = finite4(a) && finite4(vec4f(b.xyz, 0.0));
    for (var k = 0u; k < SHAPE_WIDTH; k++) {
        ok = ok && finite4(vec4f(arg1(k)));
    }
    return ok;
}

fn hardcase_hit(r: Ray, hit: ptr<function, HitInfo>) -> bool
{
    // #if sphere
    return intersect_sphere(r, hit, arg3(0u), arg1(3u));
    // #endif
    // #if plane
    return intersect_plane(r, hit, arg3(0u), arg3(3u));
    // #endif
    // #if triangle
    // #if robust
    return intersect_triangle_robust(r, hit, array<vec3f, 3>(arg3(0u), arg3(3u), arg3(6u)));
    // #else
    // e0, e1 and n rounded once in f32, as compile_scene stores them in rtfgu.layout
    let v0 = arg3(0u);
    let e0 = arg3(3u) - v0;
    let e1 = arg3(6u) - v0;
    return intersect_triangle(r, hit, v0, e0, e1, cross(e0, e1));
    // #endif
    // #endif
    // #if disk
    return intersect_disk(r, hit, arg3(0u), arg3(3u), arg1(6u));
    // #endif
    // #if rectangle
    return intersect_rectangle(r, hit, arg3(0u), arg3(3u), arg3(6u), normalize(cross(arg3(3u), arg3(6u))));
    // #endif
    // #if box
    return intersect_box(r, hit, arg3(0u), arg3(3u));
    // #endif
    // #if open_cylinder
    return intersect_open_cylinder(r, hit, arg1(0u), arg1(1u), arg1(2u));
    // #endif
    // #if torus
    return intersect_torus(r, hit, arg1(0u), arg1(1u));
    // #endif
    // #if convex_part_sphere
    // The angles in degrees: radians and cosines in f32 here (the render's come from the CPU).
    return intersect_convex_part_sphere(r, hit, arg3(0u), arg1(3u), radians(arg1(4u)), radians(arg1(5u)),
                                        cos(radians(arg1(6u))), cos(radians(arg1(7u))));
    // #endif
    // #if annulus
    return intersect_annulus(r, hit, arg3(0u), arg3(3u), arg1(6u), arg1(7u));
    // #endif
    // #if instance
    // An ellipsoid: the unit sphere scaled by arg3(0), moved by arg3(3), through the inverse
    // matrix Instance composes (1 / s, and (1 / s) (-t)), as intersect_instance.wgsl applies it.
    let inv = vec3f(1.0) / arg3(0u);
    let moved = inv * -arg3(3u);
    return intersect_sphere(Ray(inv * r.origin + moved, inv * r.direction, r.tmin, r.tmax), hit, vec3f(0.0), 1.0);
    // #endif
}

// #if spawn
fn point_error(p: vec3f) -> vec3f
{
    // #if sphere
    return sphere_point_error(p, arg3(0u));
    // #endif
    // #if plane
    return plane_point_error(p, arg3(0u));
    // #endif
    // #if triangle
    return triangle_point_error(array<vec3f, 3>(arg3(0u), arg3(3u), arg3(6u)));
    // #endif
}
// #endif

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3u)
{
    let i = gid.x;
    if (i >= arrayLength(&result)) {
        return;
    }
    row = i;
    // #if plane
    // #if robust
    plane_opaque_bits = opaque_zero[0];
    // #endif
    // #endif
    // #if spawn
    let p = rays[3u * i].xyz;
    result[i] = vec4f(offset_ray_origin(p, point_error(p), rays[3u * i + 1u].xyz, rays[3u * i + 2u].xyz), 0.0);
    // #else
    let a = rays[2u * i];
    let b = rays[2u * i + 1u];
    // #if robust
    if (!finite_input(a, b)) {
        result[i] = vec4f(0.0);
        return;
    }
    // #endif
    var hit = empty_hit();
    let found = hardcase_hit(Ray(a.xyz, b.xyz, a.w, b.w), &hit);
    result[i] = vec4f(select(0.0, 1.0, found), hit.dist, 0.0, 0.0);
    // #endif
}
