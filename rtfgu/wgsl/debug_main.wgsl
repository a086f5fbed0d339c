// release: solves a03 a04 a05
// The pixel debugger's entry (rtfgu/wgsl/debug.py), assembled in place of main.wgsl: the
// same path loop, with every bounce written to `image` instead of one colour per pixel.
//
// Path k owns DEBUG_STRIDE vec4f from k * DEBUG_STRIDE: two of input, (origin, tmin) and
// (direction, tmax) of a given ray, then four a bounce: (ray origin, hit t), (ray
// direction, shader id), (normal, place in Scene.shapes), (radiance added, what happened:
// 1 a hit, 2 the ray left the scene, 3 the ray-direction image; 0 no such bounce).
// uniforms.tile_size.y == 0 traces the tile_size.x given rays; otherwise the pixel at
// uniforms.tile_origin (column, row with row 0 at the top), as main.wgsl does.
const DEBUG_STRIDE = 2u + 4u * u32(max_depth);

fn record_bounce(base: u32, origin: vec3f, direction: vec3f, t: f32, shader: i32, normal: vec3f,
                 shape: i32, color: vec3f, what: f32)
{
    image[base] = vec4f(origin, t);
    image[base + 1u] = vec4f(direction, f32(shader));
    image[base + 2u] = vec4f(normal, f32(shape));
    image[base + 3u] = vec4f(color, what);
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u)
{
    let given = uniforms.tile_size.y == 0u;
    if ((given && id.x >= uniforms.tile_size.x) || (!given && id.x != 0u)) {
        return;
    }
    let start = id.x * DEBUG_STRIDE;
    var r: Ray;
    if (given) {
        r = Ray(image[start].xyz, image[start + 1u].xyz, image[start].w, image[start + 1u].w);
    } else {
        let ix = uniforms.tile_origin.x;
        let iy = uniforms.height - 1u - uniforms.tile_origin.y;
        let sx = 2.0 * (f32(ix) + 0.5) / f32(uniforms.width) - 1.0;
        let sy = 2.0 * (f32(iy) + 0.5) / f32(uniforms.height) - 1.0;
        r = get_camera_ray(sx, sy);
    }
    for (var k = 2u; k < DEBUG_STRIDE; k++) {
        image[start + k] = vec4f(0.0);
    }
    // #if ray_direction
    record_bounce(start + 2u, r.origin, r.direction, 0.0, -1, vec3f(0.0), -1,
                  r.direction * 0.5 + vec3f(0.5), 3.0);
    // #else
    var hit = empty_hit();
    for (var i = 0; i < max_depth; i++) {
        let base = start + 2u + 4u * u32(i);
        let origin = r.origin;
        let direction = r.direction;
        if (intersect_scene(&r, &hit)) {
            let found = hit;  // before shade moves the ray on
            record_bounce(base, origin, direction, found.dist, found.shader, found.normal, hit_shape,
                          shade(&r, &hit), 1.0);
        } else {
            record_bounce(base, origin, direction, 0.0, -1, vec3f(0.0), -1, background_radiance(direction),
                          2.0);
            break;
        }
        if (hit.has_hit) {
            break;
        }
    }
    // #endif
}
