// The slide's shade: a switch on the shader id of the shape hit. Only the cases this scene
// uses are assembled (rtfgu.registry.SHADERS): a shader that reflects light goes through
// the one light loop, a shader that continues the path is its own function; the default
// case returns the base colour.
fn shade(r: ptr<function, Ray>, hit: ptr<function, HitInfo>) -> vec3f
{
    switch (*hit).shader {
        // #each shader
        case $ID { return $body; }
        // #end
        case default { return (*hit).color; }
    }
}
