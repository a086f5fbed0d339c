// The least f32 above t (t finite): a shape that looks for its far root beyond the near
// one asks from here on (the open cylinder, the part objects of Suffern ch. 19).
fn next_after(t: f32) -> f32
{
    if (t == 0.0) {
        return bitcast<f32>(1u);
    }
    let bits = bitcast<u32>(t);
    return bitcast<f32>(select(bits - 1u, bits + 1u, t > 0.0));
}
