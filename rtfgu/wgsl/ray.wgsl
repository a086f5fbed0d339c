// A ray r(t) = o + t w with t in [tmin, tmax) (02562, "Rays in theory and in practice").
// Every new ray of a path starts with a fresh tmax; intersect_scene shrinks it to the
// nearest hit found so far.
struct Ray {
    origin: vec3f,
    direction: vec3f,
    tmin: f32,
    tmax: f32
};
