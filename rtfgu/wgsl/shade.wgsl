// The slide's shade: a switch on the shader id of the shape hit. Only the cases this scene
// uses are assembled; the default case returns the base colour.
fn shade(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    switch (*hit).shader {
        // #if lambertian
        case LAMBERTIAN { return lambertian(r, hit); }
        // #endif
        // #if phong
        case PHONG { return phong(r, hit); }
        // #endif
        // #if mirror
        case MIRROR { return mirror(r, hit); }
        // #endif
        // #if transparent
        case TRANSPARENT { return transparent(r, hit); }
        // #endif
        // #if glossy
        case GLOSSY { return glossy(r, hit); }
        // #endif
        case default { return (*hit).color; }
    }
}
