// A procedural checker in texture space (rtfgu/textures/checker.py, Suffern ch. 30).
fn texture_checker(row: u32, uv: vec2f, p: vec3f) -> vec3f
{
    let c = checkers[row];
    let q = uv * c.scale;
    let cells = i32(floor(q.x / c.size)) + i32(floor(q.y / c.size));
    if ((cells & 1) == 0) {   // even, also below zero (two's complement)
        return c.color1;
    }
    return c.color2;
}
