// Suffern's thin-lens camera (ch. 10, rtfgu/cameras/thin_lens.py): from the lens point
// eye + lens_radius (l.x b1 + l.y b2) to where the pinhole ray through (sx, sy)
// (camera_pinhole.wgsl) meets the focal plane; `lens` is a point of the unit disk.
fn get_lens_ray(sx: f32, sy: f32, lens: vec2f) -> Ray
{
    let pinhole = get_camera_ray(sx, sy);
    let focus = pinhole.origin + pinhole.direction * (camera.focal_distance / dot(pinhole.direction, camera.v));
    let l = lens * camera.lens_radius;
    let origin = camera.eye + camera.b1 * l.x + camera.b2 * l.y;
    return Ray(origin, normalize(focus - origin), 0.0, FAR);
}
