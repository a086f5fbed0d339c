// release: solves a02
// The 02562 week-1 pinhole camera: q = b1 u + b2 w + v d with (u, w) the slide's
// uv = (coords.x * aspect * 0.5, coords.y * 0.5); the basis comes from rtfgu.layout.
fn get_camera_ray(sx: f32, sy: f32) -> Ray
{
    let u = sx * camera.aspect * 0.5;
    let w = sy * 0.5;
    let q = camera.b1 * u + camera.b2 * w + camera.v * camera.d;
    return Ray(camera.eye, normalize(q), 0.0, FAR);
}
