// release: solves a02
// Suffern's fish-eye camera (ch. 11.2, rtfgu/cameras/fish_eye.py): the image point's polar
// coordinates r, alpha give the ray psi = r psi_max away from v, alpha around it from b1.
// Outside the unit circle (r^2 > 1) the ray is blank: its interval [BLANK_TMIN, BLANK_TMAX)
// is empty, so it hits nothing and the pixel is what a ray leaving the scene sees.
fn get_camera_ray(sx: f32, sy: f32) -> Ray
{
    let r_squared = sx * sx + sy * sy;
    if (r_squared > 1.0) {
        return Ray(camera.eye, camera.v, BLANK_TMIN, BLANK_TMAX);
    }
    let r = sqrt(r_squared);
    let psi = r * camera.psi_max;
    let sin_psi = sin(psi);
    let cos_psi = cos(psi);
    var sin_alpha = 0.0;
    var cos_alpha = 1.0;
    if (r > 0.0) {
        sin_alpha = sy / r;
        cos_alpha = sx / r;
    }
    let direction = camera.b1 * (sin_psi * cos_alpha) + camera.b2 * (sin_psi * sin_alpha) + camera.v * cos_psi;
    return Ray(camera.eye, normalize(direction), 0.0, FAR);
}
