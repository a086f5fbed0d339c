// release: solves a04 a05 a09 a11
// PathTrace (rtfgu/tracers/path_trace.py; Suffern ch. 26, 02562 worksheet 7): one path per sample,
// next-event estimation at every diffuse vertex (an area light through a point of it drawn
// from the random stream), a cosine-weighted bounce with Russian roulette, emission counted
// where the eye sees it and after a mirror or a refraction, from the front of a surface.
// The numbers of vertex `depth` are the stream's dimensions 2 + depth * 65536 + k
// (rtfgu.sampling.random.path_dimension), as on the other paths.
const BOUNCE_U = 0u;
const ROULETTE = 2u;
const CHOICE = 3u;
const LOBE = 4u;
// The first vertex whose continuation Russian roulette decides (rtfgu.tracers.path_trace).
const ROULETTE_DEPTH = 1u;

// Duff et al. 2017's orthonormal basis: local (x, y, z) in the frame whose z is the unit axis.
fn about(axis: vec3f, local: vec3f) -> vec3f
{
    let sign = select(-1.0, 1.0, axis.z >= 0.0);
    let a = -1.0 / (sign + axis.z);
    let b = axis.x * axis.y * a;
    let t = vec3f(1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
    let bt = vec3f(b, sign + axis.y * axis.y * a, -axis.y);
    return t * local.x + bt * local.y + axis * local.z;
}

// A direction about n with density cos(theta) / pi (rtfgu.brdfs.Lambertian.sample_f).
fn cosine_direction(n: vec3f, u: f32, v: f32) -> vec3f
{
    return about(n, hemisphere_map(vec2f(u, v), 1.0));
}

// #if glossy_reflector
// The normalised Phong lobe rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s, w_r the mirrored w_i,
// and a direction about the mirror direction with density (s + 1) / (2 pi) cos^s
// (GlossySpecular.f and sample_f, rtfgu/brdfs/glossy_specular.py).
fn glossy_lobe(specular: vec3f, shininess: f32, normal: vec3f, w_o: vec3f, w_i: vec3f, cos_theta: f32) -> vec3f
{
    let w_r = normal * (2.0 * cos_theta) - w_i;
    let cos_r = max(dot(w_o, w_r), 0.0);
    return specular * ((shininess + 2.0) / (2.0 * PI) * pow(cos_r, shininess));
}

fn lobe_direction(w_r: vec3f, shininess: f32, u: f32, v: f32) -> vec3f
{
    return about(w_r, hemisphere_map(vec2f(u, v), shininess));
}
// #endif

// #if area_light
fn sample_path_area_light(pos: vec3f, normal: vec3f, i: u32, first: u32, pixel: u32, s: u32) -> Light
{
    let uv = sampler_point(pixel, s, first + LIGHT_U + 2u * i, area_lights[i].light_sampler);
    return sample_area_light_area(pos, i, uv.x, uv.y);
}
// #endif
// #if ambient_occluder
// AmbientOccluder.sample_area: 2 pi L toward a direction uniform on the hemisphere about the
// normal, unbounded (rtfgu/lights/ambient_occluder.py).
fn sample_path_ambient_occluder(pos: vec3f, normal: vec3f, i: u32, first: u32, pixel: u32, s: u32) -> Light
{
    let uv = sampler_point(pixel, s, first + LIGHT_U + 2u * i, ambient_occluders[i].light_sampler);
    return Light(ambient_occluders[i].radiance * (2.0 * PI), about(normal, hemisphere_map(uv, 0.0)), FAR);
}
// #endif
// #if point_light
fn sample_path_point_light(pos: vec3f, normal: vec3f, i: u32, first: u32, pixel: u32, s: u32) -> Light
{
    return sample_point_light(pos, i);
}
// #endif
// #if directional
fn sample_path_directional(pos: vec3f, normal: vec3f, i: u32, first: u32, pixel: u32, s: u32) -> Light
{
    return sample_directional(pos, i);
}
// #endif

// The light of every light reflected by f_r = rho / pi plus the glossy lobe
// (Matte.direct_light, rtfgu/materials/matte.py).
fn direct_path(position: vec3f, normal: vec3f, w_o: vec3f, rho: vec3f, specular: vec3f, shininess: f32,
               first: u32, pixel: u32, s: u32) -> vec3f
{
    var result = vec3f(0.0);
    let f = rho / PI;
    // #each light
    for (var i = 0u; i < NUM_$TABLE; i++) {
        let light = sample_path_$kind(position, normal, i, first, pixel, s);
        if (all(light.L_i == vec3f(0.0))) {
            continue;
        }
        let cos_theta = dot(normal, light.w_i);
        if (!(cos_theta > 0.0)) {
            continue;
        }
        // #if shadows
        if (in_shadow(position, light.w_i, light.dist)) {
            continue;
        }
        // #endif
        // #if glossy_reflector
        let f_r = f + glossy_lobe(specular, shininess, normal, w_o, light.w_i, cos_theta);
        // #else
        let f_r = f;
        // #endif
        result += f_r * light.L_i * cos_theta;
    }
    // #end
    return result;
}

fn trace_path(eye_ray: Ray, pixel: u32, s: u32) -> vec3f
{
    var r = eye_ray;
    var result = vec3f(0.0);
    var throughput = vec3f(1.0);
    var sees_emission = true;
    for (var depth = 0u; depth < PATH_MAX_DEPTH; depth++) {
        if (depth > ROULETTE_DEPTH) {
            // Russian roulette on the throughput, for the ray from the vertex before (PathTrace).
            let q = max(max(throughput.x, throughput.y), throughput.z);
            if (q < 1.0) {
                if (!(random_float(pixel, s, 2u + (depth - 1u) * VERTEX_DIMENSIONS + ROULETTE, uniforms.seed) < q)) {
                    break;
                }
                throughput = throughput * (1.0 / q);
            }
        }
        var hit = empty_hit();
        if (!intersect_scene(&r, &hit)) {
            result += throughput * background_radiance(r.direction);
            break;
        }
        let facing = dot(hit.normal, r.direction);
        if (sees_emission && facing < 0.0) {
            result += throughput * hit.emission;
        }
        let first = 2u + depth * VERTEX_DIMENSIONS;
        // #if lambertian|glossy_reflector
        if (hit.shader == LAMBERTIAN || hit.shader == GLOSSY_REFLECTOR) {
            let n = select(hit.normal, -hit.normal, facing > 0.0);
            let rho = hit.color * hit.kd;
            let specular = select(vec3f(0.0), hit.specular, hit.shader == GLOSSY_REFLECTOR);
            // #if lights
            // GlobalTrace (PATH_LIGHTS_AT_EVERY_VERTEX 0) samples the lights at the first vertex only.
            if (PATH_LIGHTS_AT_EVERY_VERTEX == 1u || depth == 0u) {
                result += throughput * direct_path(hit.position, n, -r.direction, rho, specular, hit.shininess,
                                                   first, pixel, s);
            }
            // #endif
            if (depth + 1u == PATH_MAX_DEPTH) {
                break;
            }
            // The lobe the path follows, in the ratio of the albedos (a Matte's q_d is 1).
            var q_d = (rho.x + rho.y + rho.z) / 3.0;
            var q_s = (specular.x + specular.y + specular.z) / 3.0;
            if (!(q_d + q_s > 0.0)) {
                break;
            }
            let total = q_d + q_s;
            q_d = q_d / total;
            q_s = q_s / total;
            let xi = random_float(pixel, s, first + LOBE, uniforms.seed);
            // The chosen BRDF's own sampler's point, or the stream's (BRDF.sample_point).
            // #if own_sampler
            let m = materials[material_row(u32(hit_shape))];
            let uv = sampler_point(pixel, s, first + BOUNCE_U, select(m.specular_sampler, m.diffuse_sampler, xi < q_d));
            // #else
            let uv = sampler_point(pixel, s, first + BOUNCE_U, vec3f(0.0));
            // #endif
            let u = uv.x;
            let v = uv.y;
            var w_i: vec3f;
            if (xi < q_d) {
                // rtfgu.brdfs.Lambertian.sample_f: f = rho / pi, pdf = cos(theta) / pi
                let f = rho * (1.0 / PI);
                w_i = cosine_direction(n, u, v);
                let cos_theta = dot(n, w_i);
                let pdf = cos_theta / PI;
                if (!(pdf > 0.0 && cos_theta > 0.0)) {
                    break;
                }
                throughput = throughput * f * (cos_theta / (pdf * q_d));
            } else if (q_s > 0.0) {
                // #if glossy_reflector
                let d = r.direction;
                w_i = lobe_direction(d - n * (2.0 * dot(d, n)), hit.shininess, u, v);
                let cos_theta = dot(n, w_i);
                if (!(cos_theta > 0.0)) {
                    break;
                }
                throughput *= specular * ((hit.shininess + 2.0) / (hit.shininess + 1.0) * cos_theta / q_s);
                // #endif
            } else {
                break;
            }
            r = Ray(hit.position, w_i, SPAWN_EPSILON, FAR);
            sees_emission = !(PATH_LIGHTS_AT_EVERY_VERTEX == 1u || depth == 0u);
            continue;
        }
        // #endif
        // #if mirror
        if (hit.shader == MIRROR) {
            mirror(&r, &hit);
            sees_emission = true;
            continue;
        }
        // #endif
        // #if transparent
        if (hit.shader == TRANSPARENT) {
            transparent(&r, &hit);
            sees_emission = true;
            continue;
        }
        // #endif
        // #if dielectric
        if (hit.shader == DIELECTRIC) {
            if (facing > 0.0) {     // met from inside: Bouguer's law over the way here
                throughput *= exp(-materials[material_row(u32(hit_shape))].absorption * hit.dist);
            }
            let xi = random_float(pixel, s, first + CHOICE, uniforms.seed);
            r = Ray(hit.position, scatter(r.direction, hit.normal, hit.ior, xi), SPAWN_EPSILON, FAR);
            sees_emission = true;
            continue;
        }
        // #endif
        if (hit.shader == BASE_COLOR) {
            result += throughput * hit.color;
        }
        break;
    }
    return result;
}
