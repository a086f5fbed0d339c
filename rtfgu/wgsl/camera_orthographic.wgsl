// release: solves a02
// OrthographicCamera::gen_ray (lecture 01, "Orthographic Camera"): parallel rays along -z
// from the view plane z = hither, for (sx, sy) in [-1, 1]^2.
fn get_camera_ray(sx: f32, sy: f32) -> Ray
{
    let u = 0.5 + sx / 2.0;
    let v = 0.5 + sy / 2.0;
    let x = camera.left + (camera.right - camera.left) * u;
    let y = camera.bottom + (camera.top - camera.bottom) * v;
    return Ray(vec3f(x, y, camera.hither), vec3f(0.0, 0.0, -1.0), camera.tmin,
               camera.yon - camera.hither);
}
