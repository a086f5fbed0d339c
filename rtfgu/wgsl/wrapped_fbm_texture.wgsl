// Suffern ch. 31's WrappedFBmTexture (rtfgu/textures/wrapped_fbm_texture.py): the fractional
// part of expansion_number value_fbm, mapped to [min_value, max_value], times the colour.
fn texture_wrapped_fbm_texture(row: u32, uv: vec2f, p: vec3f) -> vec3f
{
    let t = wrapped_fbm_textures[row];
    let noise = t.expansion_number
              * value_fbm(t.noise_id, t.num_octaves, t.lacunarity, t.gain, t.fbm_max, p * t.scale);
    let value = t.min_value + (t.max_value - t.min_value) * (noise - floor(noise));
    return t.color * value;
}
