"""intersect_sphere in WGSL runs far past any time limit: a loop whose exit is never taken, each step 4096 sines and cosines (Mesa cuts it after 65535 steps, about 40 s here): its test and the image stop at the limit."""
ASSIGNMENT = "a06"
SPIN = """\
// Each spin doubles the work of the one before: spin9 is 512 of spin0, 4096 sines and cosines.
fn spin0(x: vec4f) -> vec4f { return sin(x.yzwx) * 0.999 + cos(x) * 0.001; }
fn spin1(x: vec4f) -> vec4f { return spin0(spin0(x)); }
fn spin2(x: vec4f) -> vec4f { return spin1(spin1(x)); }
fn spin3(x: vec4f) -> vec4f { return spin2(spin2(x)); }
fn spin4(x: vec4f) -> vec4f { return spin3(spin3(x)); }
fn spin5(x: vec4f) -> vec4f { return spin4(spin4(x)); }
fn spin6(x: vec4f) -> vec4f { return spin5(spin5(x)); }
fn spin7(x: vec4f) -> vec4f { return spin6(spin6(x)); }
fn spin8(x: vec4f) -> vec4f { return spin7(spin7(x)); }
fn spin9(x: vec4f) -> vec4f { return spin8(spin8(x)); }
"""
REPLACE = [
    ("wgsl/intersect_sphere.wgsl", "fn intersect_sphere(", SPIN + "fn intersect_sphere("),
    ("wgsl/intersect_sphere.wgsl", "    let temp = r.origin - center;\n",
     "    var k = vec4f(r.tmin);\n    loop {\n        k = spin9(k);\n        if (k.x > 2.0) {\n            break;\n        }\n    }\n"
     "    if (k.y == 12345.0) {\n        return false;\n    }\n    let temp = r.origin - center;\n"),
]
