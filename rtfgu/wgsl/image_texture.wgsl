// release: solves a07
// An image texture (rtfgu/textures/image_texture.py; 02562 worksheet 3): the texels are
// linear RGB in a storage buffer (`texels`, three f32 a texel, rows from the top), read
// with the same addressing and filtering as the lecture layer, so every path sees the same
// colours. (A WebGPU texture with a sampler would filter in the hardware's own precision.)
fn texel(t: ImageTexture, i: i32, j: i32) -> vec3f
{
    let w = i32(t.width);
    let h = i32(t.height);
    var x = i;
    var y = j;
    if (u32(t.address_mode) == 0u) {   // repeat: wrap into [0, w) with a floored division,
        x = x - w * i32(floor(f32(x) / f32(w)));   // as Python's %; an i32 % of a negative
        y = y - h * i32(floor(f32(y) / f32(h)));   // number is undefined in GLSL (OpenGL)
    } else {                      // clamp
        x = clamp(x, 0, w - 1);
        y = clamp(y, 0, h - 1);
    }
    let k = 3u * (u32(t.offset) + u32(y * w + x));
    return vec3f(texels[k], texels[k + 1u], texels[k + 2u]);
}

// The mapping's (u, v) of the point p (rtfgu.registry.MAPPING_IDS; Suffern ch. 29), each
// mapping assembled only into a scene that uses it.
fn mapped_coordinates(mapping: i32, p: vec3f) -> vec2f
{
    // #if spherical_map
    if (mapping == 0) {
        return spherical_map(p);
    }
    // #endif
    // #if cylindrical_map
    if (mapping == 1) {
        return cylindrical_map(p);
    }
    // #endif
    // #if rectangular_map
    if (mapping == 2) {
        return rectangular_map(p);
    }
    // #endif
    // #if light_probe|panoramic
    if (mapping >= 3) {
        return light_probe(p, mapping == 4);
    }
    // #endif
    return vec2f(0.0);
}

fn texture_image_texture(row: u32, uv: vec2f, p: vec3f) -> vec3f
{
    let t = image_textures[row];
    var st = uv;
    if (t.mapping_id >= 0.0) {
        st = mapped_coordinates(i32(t.mapping_id), p);
    }
    var u = st.x * t.scale;
    var v = st.y * t.scale;
    if (u32(t.address_mode) == 0u) {
        u = u - floor(u);
        v = v - floor(v);
    } else {
        u = clamp(u, 0.0, 1.0);
        v = clamp(v, 0.0, 1.0);
    }
    var x = u * t.width;
    var y = (1.0 - v) * t.height;
    if (u32(t.filter_mode) == 0u) {    // nearest
        return texel(t, i32(floor(x)), i32(floor(y)));
    }
    x = x - 0.5;                  // bilinear: texel centres at whole numbers + 0.5
    y = y - 0.5;
    let fi = floor(x);
    let fj = floor(y);
    let fx = x - fi;
    let fy = y - fj;
    let i = i32(fi);
    let j = i32(fj);
    let top = texel(t, i, j) * (1.0 - fx) + texel(t, i + 1, j) * fx;
    let bottom = texel(t, i, j + 1) * (1.0 - fx) + texel(t, i + 1, j + 1) * fx;
    return top * (1.0 - fy) + bottom * fy;
}
