// The page's canvas: each pixel's mean so far, clamped and gamma-corrected, as 02562's
// main_fs draws the ray tracer's image (rtfgu.image.to_8bit: clamp to [0, 1], then
// the power 1/gamma). `image` is the sums buffer the scene's program adds its samples to
// (rtfgu/wgsl/main.wgsl), row 0 at the top as the canvas's.

struct Display {
    width: u32,
    height: u32,
    samples: f32,  // the samples added so far to every pixel's sum
    gamma: f32,
};

@group(0) @binding(0) var<storage, read> image: array<vec4f>;
@group(0) @binding(1) var<uniform> display: Display;

// One triangle that covers the canvas.
@vertex
fn main_vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4f
{
    let corner = vec2f(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4f(corner * 2.0 - 1.0, 0.0, 1.0);
}

@fragment
fn main_fs(@builtin(position) position: vec4f) -> @location(0) vec4f
{
    let pixel = u32(position.y) * display.width + u32(position.x);
    let mean = clamp(image[pixel].xyz / max(display.samples, 1.0), vec3f(0.0), vec3f(1.0));
    // pow(0, y) is exp2(y * log2(0)): keep the base above 0.
    return vec4f(pow(max(mean, vec3f(1e-10)), vec3f(1.0 / display.gamma)), 1.0);
}
