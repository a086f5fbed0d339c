// Suffern ch. 31's marble, RampFBmTexture (rtfgu/textures/ramp_fbm_texture.py): the ramp's
// entry int(u (n - 1)) for u = (1 + sin(y + perturbation value_fbm)) / 2; the ramp's colours
// sit in `texels` from t.offset.
fn texture_ramp_fbm_texture(row: u32, uv: vec2f, p: vec3f) -> vec3f
{
    let t = ramp_fbm_textures[row];
    let q = p * t.scale;
    let y = q.y + t.perturbation * value_fbm(t.noise_id, t.num_octaves, t.lacunarity, t.gain, t.fbm_max, q);
    let u = (1.0 + sin(y)) / 2.0;
    let k = 3u * (u32(t.offset) + u32(i32(u * (t.width - 1.0))));
    return vec3f(texels[k], texels[k + 1u], texels[k + 2u]);
}
