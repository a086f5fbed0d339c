// A second ray waiting to be traced: where it starts, its direction, its weight, its depth.
// #if two_rays
struct WaitingRay {
    origin: vec3f,
    direction: vec3f,
    weight: vec3f,
    depth: i32
};
// #endif

// The main program (02562, "Intersecting with the scene and tracing a path"), as a compute
// shader over one tile of the image: for each sample of the pixel, trace its path (with
// PathTrace: trace_path, path_trace.wgsl) with at most max_depth shaded hits, adding the background where the path leaves the scene, and
// add the colour to the pixel's sum in `image` (the host divides by the samples; passes
// that split the samples add them in the same order). The pixel loop is the slide's
// (lecture 01, "Rendering a Scene"): iy counts from the bottom.
@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3u)
{
    if (id.x >= uniforms.tile_size.x || id.y >= uniforms.tile_size.y) {
        return;
    }
    let ix = uniforms.tile_origin.x + id.x;
    let row = uniforms.tile_origin.y + id.y;
    let iy = uniforms.height - 1u - row;
    let pixel = row * uniforms.width + ix;
    var total = image[pixel].xyz;
    for (var s = uniforms.first_sample; s < uniforms.end_sample; s++) {
        let sp = pixel_sample(pixel, s, PIXEL_SET);
        let sx = 2.0 * (f32(ix) + sp.x) / f32(uniforms.width) - 1.0;
        let sy = 2.0 * (f32(iy) + sp.y) / f32(uniforms.height) - 1.0;
        // #if thin_lens
        var r = get_lens_ray(sx, sy, concentric_map(pixel_sample(pixel, s, LENS_SET)));
        // #else
        var r = get_camera_ray(sx, sy);
        // #endif
        var result = vec3f(0.0);
        // #if ray_direction
        // Week 1's first image: the eye ray's direction as a colour.
        result = r.direction * 0.5 + vec3f(0.5);
        // #else
        // #if path_trace
        result = trace_path(r, pixel, s);
        // #else
        var hit = empty_hit();
        // The radiance a hit adds is weighted by the factors of the rays that led to it.
        var weight = vec3f(1.0);
        var first = 0;
        // #if two_rays
        // Whitted's second rays (a Transparent's reflections) wait here until the path ends.
        var waiting: array<WaitingRay, max_depth>;
        var pending = 0;
        loop {
        // #endif
        for (var i = first; i < max_depth; i++) {
            // #if area_lighting
            stream = vec3u(pixel, s, 2u + u32(i) * VERTEX_DIMENSIONS);
            // #endif
            if (intersect_scene(&r, &hit)) {
                result += weight * shade(&r, &hit);
            } else {
                result += weight * background_radiance(r.direction);
                break;
            }
            if (hit.has_hit) {
                break;
            }
            // #if two_rays
            if (i + 1 < max_depth && any(second_factor != vec3f(0.0))) {
                waiting[pending] = WaitingRay(hit.position, second_direction, weight * second_factor, i + 1);
                pending++;
            }
            // #endif
            // #if continues
            weight *= factor;
            // #endif
        }
        // #if two_rays
        if (pending == 0) {
            break;
        }
        pending--;
        r = Ray(waiting[pending].origin, waiting[pending].direction, SPAWN_EPSILON, FAR);
        weight = waiting[pending].weight;
        first = waiting[pending].depth;
        hit = empty_hit();
        }
        // #endif
        // #endif
        // #endif
        total += result;
    }
    image[pixel] = vec4f(total, 1.0);
}
