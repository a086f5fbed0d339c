// The main program (02562, "Intersecting with the scene and tracing a path"), as a compute
// shader over one tile of the image: trace the pixel's path with at most max_depth shaded
// hits, add the background where the path leaves the scene, apply gamma, store the colour.
// The pixel loop is the slide's (lecture 01, "Rendering a Scene"): iy counts from the bottom.
@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3u)
{
    if (id.x >= uniforms.tile_size.x || id.y >= uniforms.tile_size.y) {
        return;
    }
    let ix = uniforms.tile_origin.x + id.x;
    let row = uniforms.tile_origin.y + id.y;
    let iy = uniforms.height - 1u - row;
    let sx = 2.0 * (f32(ix) + 0.5) / f32(uniforms.width) - 1.0;
    let sy = 2.0 * (f32(iy) + 0.5) / f32(uniforms.height) - 1.0;
    var r = get_camera_ray(sx, sy);
    var result = vec3f(0.0);
    // #if ray_direction
    // Week 1's first image: the eye ray's direction as a colour.
    result = r.direction * 0.5 + vec3f(0.5);
    // #else
    var hit = empty_hit();
    for (var i = 0; i < max_depth; i++) {
        if (intersect_scene(&r, &hit)) {
            result += shade(&r, &hit);
        } else {
            result += uniforms.background;
            break;
        }
        if (hit.has_hit) {
            break;
        }
    }
    // #endif
    if (uniforms.gamma != 1.0) {
        result = pow(result, vec3f(1.0 / uniforms.gamma));
    }
    image[id.y * uniforms.tile_size.x + id.x] = vec4f(result, 1.0);
}
