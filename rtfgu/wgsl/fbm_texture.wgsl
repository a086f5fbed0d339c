// Suffern ch. 31's FBmTexture (rtfgu/textures/fbm_texture.py): value_fbm mapped to
// [min_value, max_value] times the colour; red outside [0, 1], as the book's.
fn texture_fbm_texture(row: u32, uv: vec2f, p: vec3f) -> vec3f
{
    let t = fbm_textures[row];
    let value = t.min_value + (t.max_value - t.min_value)
              * value_fbm(t.noise_id, t.num_octaves, t.lacunarity, t.gain, t.fbm_max, p * t.scale);
    if (value < 0.0 || value > 1.0) {
        return vec3f(1.0, 0.0, 0.0);
    }
    return t.color * value;
}
