// Suffern ch. 31's Wood (rtfgu/textures/wood.py, after Apodaca and Gritz's RenderMan wood):
// rings about the y axis perturbed by the noise, a grain of two octaves of value noise.
fn wood_smooth_step(a: f32, b: f32, x: f32) -> f32
{
    if (x < a) {
        return 0.0;
    }
    if (x >= b) {
        return 1.0;
    }
    let y = (x - a) / (b - a);
    return y * y * (3.0 - 2.0 * y);
}

// The book's smooth_pulse_train with its mod: x - int(x / period) period, into [0, period).
fn wood_pulse_train(e0: f32, e1: f32, e2: f32, e3: f32, period: f32, x: f32) -> f32
{
    var m = x - f32(i32(x / period)) * period;
    if (m < 0.0) {
        m += period;
    }
    return wood_smooth_step(e0, e1, m) - wood_smooth_step(e2, e3, m);
}

fn texture_wood(row: u32, uv: vec2f, position: vec3f) -> vec3f
{
    let t = woods[row];
    let p = position * t.scale;
    let ring_point = p + vector_fbm(t.noise_id, t.num_octaves, t.lacunarity, t.gain, p * t.ring_noise_frequency)
                       * t.ring_noise;
    let wobble = vector_noise(t.noise_id, vec3f(0.0, 0.0, p.y * t.trunk_wobble_frequency)) * t.trunk_wobble;
    let rx = ring_point.x + wobble.x;
    let ry = ring_point.y;
    let rz = ring_point.z + wobble.z;
    var r = sqrt(rx * rx + rz * rz) * t.ring_frequency;
    let f = t.angular_wobble_frequency;
    r += t.angular_wobble * wood_smooth_step(0.0, 5.0, r) * value_noise(t.noise_id, vec3f(f * rx, f * ry * 0.1, f * rz));
    r += t.ring_uneveness * value_noise(t.noise_id, vec3f(r));
    var in_ring = wood_pulse_train(0.1, 0.55, 0.7, 0.95, 1.0, r);
    var grain_point = vec3f(p.x * t.grain_frequency, p.y * t.grain_frequency * 0.05, p.z * t.grain_frequency);
    var dpgrain = 0.2;
    var grain = 0.0;
    var amplitude = 1.0;
    for (var i = 0; i < 2; i++) {
        let grain_valid = 1.0 - wood_smooth_step(0.2, 0.6, dpgrain);
        if (grain_valid > 0.0) {
            var g = grain_valid * value_noise(t.noise_id, grain_point);
            g *= 0.3 + 0.7 * in_ring;
            g = clamp(0.8 - g, 0.0, 1.0);
            g = t.grainy * wood_smooth_step(0.5, 1.0, g * g);
            if (i == 0) {
                in_ring *= 1.0 - 0.4 * grain_valid;
            }
            grain = amplitude * max(grain, g);
        }
        grain_point = 2.0 * grain_point;
        dpgrain *= 2.0;
        amplitude *= 0.5;
    }
    let final_value = (1.0 - grain) * (in_ring * t.ringy) + grain;
    return t.light_color * (1.0 - final_value) + t.dark_color * final_value;
}
