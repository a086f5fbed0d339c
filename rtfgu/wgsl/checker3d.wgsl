// Suffern ch. 30's 3D checker (rtfgu/textures/checker3d.py): cubes of side size in space,
// the point moved by the book's small epsilon so that a face on a cube boundary falls in one.
const CHECKER3D_EPSILON = -0.000187453738;

fn texture_checker3d(row: u32, uv: vec2f, p: vec3f) -> vec3f
{
    let c = checker3ds[row];
    let q = p * c.scale + vec3f(CHECKER3D_EPSILON);
    let cells = i32(floor(q.x / c.size)) + i32(floor(q.y / c.size)) + i32(floor(q.z / c.size));
    if ((cells & 1) == 0) {   // even, also below zero (two's complement)
        return c.color1;
    }
    return c.color2;
}
