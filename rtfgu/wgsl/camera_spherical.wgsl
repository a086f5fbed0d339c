// release: solves a02
// Suffern's spherical panoramic camera (ch. 11.3, rtfgu/cameras/spherical.py): the image
// point's longitude lambda = sx lambda_max and latitude psi = sy psi_max, the book's polar
// angles phi = pi - lambda and theta = pi / 2 - psi written out.
fn get_camera_ray(sx: f32, sy: f32) -> Ray
{
    let lambda = sx * camera.lambda_max;
    let psi = sy * camera.psi_max;
    let cos_psi = cos(psi);
    let direction = camera.b1 * (cos_psi * sin(lambda)) + camera.b2 * sin(psi) + camera.v * (cos_psi * cos(lambda));
    return Ray(camera.eye, normalize(direction), 0.0, FAR);
}
