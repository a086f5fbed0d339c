// What a ray-surface intersection records (02562, "struct HitInfo"); after the slide's dots
// come the material of the shape hit: shader id, rho_s, s, ior, L_e, its diffuse kd, its
// ambient term ka L_a, and the weights of the rays it sends on, kr cr and kt (rtfgu/hit_info.py,
// rtfgu/materials).
struct HitInfo {
    has_hit: bool,
    dist: f32,
    position: vec3f,
    normal: vec3f,
    color: vec3f,
    shader: i32,
    specular: vec3f,
    shininess: f32,
    ior: f32,
    emission: vec3f,
    kd: f32,
    ambient: vec3f,
    reflection: vec3f,
    kt: f32
};

fn empty_hit() -> HitInfo
{
    return HitInfo(false, 0.0, vec3f(0.0), vec3f(0.0), vec3f(0.0), BASE_COLOR,
                   vec3f(0.0), 0.0, 1.0, vec3f(0.0), 0.0, vec3f(0.0), vec3f(0.0), 0.0);
}
