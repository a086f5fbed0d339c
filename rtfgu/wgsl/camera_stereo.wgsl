// release: solves a02
// Suffern's stereo camera (ch. 12, rtfgu/cameras/stereo_camera.py): two pinhole views side
// by side, hres + pixel_gap + hres pixels of the stereo image. The column c picks the view
// on the left (eye moved by offset along b1, its window by shift), the gap (a blank ray,
// hitting nothing: the background) or the view on the right (the opposite offset and shift).
fn get_camera_ray(sx: f32, sy: f32) -> Ray
{
    let hres = camera.hres;
    let gap = camera.pixel_gap;
    var c = (sx + 1.0) * 0.5 * (hres + hres + gap);
    var offset = camera.offset;
    var shift = camera.shift;
    if (c >= hres + gap) {
        offset = -camera.offset;
        shift = -camera.shift;
        c = c - (hres + gap);
    } else if (c >= hres) {
        return Ray(camera.eye, camera.v, BLANK_TMIN, BLANK_TMAX);
    }
    let u = (c / hres - 0.5) * camera.aspect + shift;
    let w = sy * 0.5;
    let q = camera.b1 * u + camera.b2 * w + camera.v * camera.d;
    return Ray(camera.eye + camera.b1 * offset, normalize(q), 0.0, FAR);
}
