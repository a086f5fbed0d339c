"""The WGSL float32 path of the hard cases: a small compute program that runs a batch of
rays against one shape each, with the slide formula (rtfgu/wgsl/intersect_*.wgsl) or the
robust one (rtfgu/wgsl/robust_*.wgsl), and spawns secondary rays with PBRT's offset.

It reuses the WGSL path's Ray and HitInfo structs (rtfgu/wgsl/ray.wgsl, hitinfo.wgsl).
The robust plane test (compensated dot products) lives in this program only.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

from ..layout import FAR, PLANE, SPHERE, TRIANGLE
from ..material import BASE_COLOR
from ..shading import SPAWN_EPSILON

WGSL_DIR = Path(__file__).resolve().parent.parent / "wgsl"
WORKGROUP = 64

_FALLBACK_STRUCTS = """
struct Ray { origin: vec3f, direction: vec3f, tmin: f32, tmax: f32 };
struct HitInfo { has_hit: bool, dist: f32, position: vec3f, normal: vec3f };
"""

# The render never passes a non-finite number (compile_scene refuses it); the hard cases do,
# and a kernel must answer them with a miss. The test is on the bits: WGSL may assume finite
# floats and fold comparisons with NaN away.
SPHERE_ROBUST_CHECKED = """
fn sphere_robust_finite(v: vec4f) -> bool
{
    let e = bitcast<vec4u>(v) & vec4u(0x7f800000u);
    return all(e != vec4u(0x7f800000u));
}

fn intersect_sphere_robust(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, radius: f32) -> bool
{
    if (!(sphere_robust_finite(vec4f(r.origin, r.tmin)) && sphere_robust_finite(vec4f(r.direction, 0.0))
          && sphere_robust_finite(vec4f(center, radius)))) {
        return false;
    }
    return intersect_sphere_robust_unchecked(r, hit, center, radius);
}
"""

# Ogita, Rump and Oishi 2005 (Dot2), TwoProduct by a split on the bits: see
# rtfgu/robust.py, intersect_plane_robust.
PLANE_ROBUST = """
// 0 at run time, unknown to the compiler: XOR-ing the bits of an intermediate with it
// stops algebraic rewriting such as (a + b) - a -> b, which would erase the rounding error
// these error-free transformations capture.
var<private> plane_opaque_bits: u32 = 0u;

fn plane_opaque(x: f32) -> f32
{
    return bitcast<f32>(bitcast<u32>(x) ^ plane_opaque_bits);
}

fn plane_two_sum(a: f32, b: f32) -> vec2f
{
    let s = plane_opaque(a + b);
    let bb = plane_opaque(s - a);
    return vec2f(s, (a - (s - bb)) + (b - bb));
}

fn plane_two_product(a: f32, b: f32) -> vec2f
{
    // Dekker's TwoProduct with the halves cut on the bits (12 significant bits each), not by
    // Veltkamp's 4097 a - (4097 a - a), and not by fma: the shader compiler may fuse a
    // multiply and an add into an fma, and llvmpipe's fma is not exact. Products of 12-bit
    // halves are exact, so a fused multiply-add gives the same result as the two operations.
    let p = plane_opaque(a * b);
    let ah = bitcast<f32>(bitcast<u32>(a) & 0xfffff000u);
    let al = a - ah;
    let bh = bitcast<f32>(bitcast<u32>(b) & 0xfffff000u);
    let bl = b - bh;
    return vec2f(p, al * bl - (((p - ah * bh) - al * bh) - ah * bl));
}

// sum of x[i] y[i] for i < count, as if in twice the precision
fn plane_dot2(x: array<f32, 6>, y: array<f32, 6>, count: i32) -> f32
{
    var ps = plane_two_product(x[0], y[0]);
    var p = ps.x;
    var s = ps.y;
    for (var i = 1; i < count; i++) {
        let hr = plane_two_product(x[i], y[i]);
        let pq = plane_two_sum(p, hr.x);
        p = pq.x;
        s = s + (pq.y + hr.y);
    }
    return p + s;
}

fn plane_finite(v: vec4f) -> bool
{
    let e = bitcast<vec4u>(v) & vec4u(0x7f800000u);
    return all(e != vec4u(0x7f800000u));
}

fn intersect_plane_robust(r: Ray, hit: ptr<function, HitInfo>, position: vec3f, normal: vec3f) -> bool
{
    if (!(plane_finite(vec4f(r.origin, r.tmin)) && plane_finite(vec4f(r.direction, 0.0))
          && plane_finite(vec4f(position, 0.0)) && plane_finite(vec4f(normal, 0.0)))) {
        return false;
    }
    let w = r.direction;
    let n = normal;
    let denom = plane_dot2(array<f32, 6>(w.x, w.y, w.z, 0.0, 0.0, 0.0),
                           array<f32, 6>(n.x, n.y, n.z, 0.0, 0.0, 0.0), 3);
    if (denom == 0.0) {
        return false;
    }
    let sx = plane_two_sum(position.x, -r.origin.x);
    let sy = plane_two_sum(position.y, -r.origin.y);
    let sz = plane_two_sum(position.z, -r.origin.z);
    let num = plane_dot2(array<f32, 6>(sx.x, sy.x, sz.x, sx.y, sy.y, sz.y),
                         array<f32, 6>(n.x, n.y, n.z, n.x, n.y, n.z), 6);
    let t = num / denom;
    if (!(t >= r.tmin && t < r.tmax)) {
        return false;
    }
    (*hit).has_hit = true;
    (*hit).dist = t;
    (*hit).position = r.origin + w * t;
    (*hit).normal = normalize(n);
    return true;
}

fn plane_point_error(p: vec3f, a: vec3f) -> vec3f
{
    let u = 0.5 * 1.1920929e-7;
    let g7 = 7.0 * u / (1.0 - 7.0 * u);
    return g7 * (abs(p) + abs(a));
}
"""

MAIN = """
struct HardCaseParams { kind: u32, robust: u32, count: u32, spawn: u32, zero: u32, pad0: u32, pad1: u32, pad2: u32 };
@group(0) @binding(0) var<uniform> params: HardCaseParams;
@group(0) @binding(1) var<storage, read> rays: array<vec4f>;      // [o, tmin], [w, tmax]
@group(0) @binding(2) var<storage, read> shapes: array<vec4f>;    // 3 vec4f: 12 floats
@group(0) @binding(3) var<storage, read_write> result: array<vec4f>;

@compute @workgroup_size(%(workgroup)d)
fn main(@builtin(global_invocation_id) gid: vec3u)
{
    let i = gid.x;
    plane_opaque_bits = params.zero;
    if (i >= params.count) {
        return;
    }
    let a = rays[2u * i];
    let b = rays[2u * i + 1u];
    let s0 = shapes[3u * i];
    let s1 = shapes[3u * i + 1u];
    let s2 = shapes[3u * i + 2u];
    if (params.spawn == 1u) {
        // a = [p, 0], b = [normal, 0], s = the surface left; rays[2 count + i] = [w, 0]
        let w = rays[2u * params.count + i].xyz;
        var err = vec3f(0.0);
        if (params.kind == %(sphere)du) {
            err = sphere_point_error(a.xyz, s0.xyz);
        } else if (params.kind == %(triangle)du) {
            err = triangle_point_error(array<vec3f, 3>(s0.xyz, vec3f(s0.w, s1.xy), vec3f(s1.zw, s2.x)));
        } else {
            err = plane_point_error(a.xyz, s0.xyz);
        }
        result[i] = vec4f(offset_ray_origin(a.xyz, err, b.xyz, w), 0.0);
        return;
    }
    let r = Ray(a.xyz, b.xyz, a.w, b.w);
    var hit: HitInfo;
    hit.has_hit = false;
    var found = false;
    if (params.kind == %(sphere)du) {
        if (params.robust == 1u) {
            found = intersect_sphere_robust(r, &hit, s0.xyz, s0.w);
        } else {
            found = intersect_sphere(r, &hit, s0.xyz, s0.w);
        }
    } else if (params.kind == %(plane)du) {
        let p = s0.xyz;
        let n = vec3f(s0.w, s1.xy);
        if (params.robust == 1u) {
            found = intersect_plane_robust(r, &hit, p, n);
        } else {
            found = intersect_plane(r, &hit, p, n);
        }
    } else {
        let v0 = s0.xyz;
        let v1 = vec3f(s0.w, s1.xy);
        let v2 = vec3f(s1.zw, s2.x);
        if (params.robust == 1u) {
            found = intersect_triangle_robust(r, &hit, array<vec3f, 3>(v0, v1, v2));
        } else {
            // the layout's rows: e0, e1 and n rounded once in f32, as compile_scene stores them
            let e0 = v1 - v0;
            let e1 = v2 - v0;
            found = intersect_triangle(r, &hit, v0, e0, e1, cross(e0, e1));
        }
    }
    result[i] = vec4f(select(0.0, 1.0, found), hit.dist, 0.0, 0.0);
}
"""


def _read(name: str) -> str | None:
    path = WGSL_DIR / name
    return path.read_text() if path.exists() else None


def program_source() -> str:
    """The compute program: structs, slide and robust functions, main, in that order."""
    ray, hitinfo = _read("ray.wgsl"), _read("hitinfo.wgsl")
    if ray and hitinfo:
        structs = ray + "\n" + hitinfo
        if "BASE_COLOR" in hitinfo and "const BASE_COLOR" not in hitinfo:
            structs = "const BASE_COLOR: i32 = %d;\n" % BASE_COLOR + structs
    else:
        structs = _FALLBACK_STRUCTS
    pieces = [structs]
    for name in ("intersect_sphere.wgsl", "intersect_plane.wgsl", "intersect_triangle.wgsl",
                 "robust_sphere.wgsl", "robust_triangle.wgsl"):
        text = _read(name)
        if text is None:
            raise FileNotFoundError("rtfgu/wgsl/%s is missing" % name)
        if name == "robust_sphere.wgsl":
            # Both sphere files define the render's intersect_sphere; here they sit side by side.
            text = text.replace("fn intersect_sphere(", "fn intersect_sphere_robust_unchecked(")
        pieces.append(text)
    pieces.append(SPHERE_ROBUST_CHECKED)
    pieces.append(PLANE_ROBUST)
    pieces.append(MAIN % {"workgroup": WORKGROUP, "sphere": SPHERE, "plane": PLANE,
                          "triangle": TRIANGLE})
    return "\n".join(pieces)


@lru_cache(maxsize=1)
def _device():
    try:
        from ..wgsl.device import get_device
        return get_device()
    except ImportError:
        import wgpu
        adapter = wgpu.gpu.request_adapter_sync()
        return adapter, adapter.request_device_sync()


def wgsl_unavailable_reason() -> str | None:
    """None if a WebGPU adapter exists, else why not (naming the missing package)."""
    try:
        _device()
    except Exception as error:  # no wgpu, or no adapter
        return str(error) or type(error).__name__
    return None


def wgsl_available() -> bool:
    return wgsl_unavailable_reason() is None


@lru_cache(maxsize=1)
def _pipeline():
    import wgpu
    _, device = _device()
    module = device.create_shader_module(code=program_source())
    pipeline = device.create_compute_pipeline(layout="auto",
                                              compute={"module": module, "entry_point": "main"})
    return device, pipeline, wgpu


def _pack_shapes(shapes: np.ndarray) -> np.ndarray:
    out = np.zeros((shapes.shape[0], 12), np.float32)
    out[:, :shapes.shape[1]] = shapes
    return out


def _run(kind: int, robust: bool, spawn: bool, rays: np.ndarray, shapes: np.ndarray, count: int):
    device, pipeline, wgpu = _pipeline()
    params = np.array([kind, int(robust), count, int(spawn), 0, 0, 0, 0], np.uint32)
    usage = wgpu.BufferUsage
    buffers = [
        device.create_buffer_with_data(data=params.tobytes(), usage=usage.UNIFORM),
        device.create_buffer_with_data(data=np.ascontiguousarray(rays, np.float32).tobytes(),
                                       usage=usage.STORAGE),
        device.create_buffer_with_data(data=_pack_shapes(shapes).tobytes(), usage=usage.STORAGE),
        device.create_buffer(size=16 * max(count, 1), usage=usage.STORAGE | usage.COPY_SRC),
    ]
    group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
        {"binding": i, "resource": {"buffer": b}} for i, b in enumerate(buffers)])
    encoder = device.create_command_encoder()
    compute = encoder.begin_compute_pass()
    compute.set_pipeline(pipeline)
    compute.set_bind_group(0, group)
    compute.dispatch_workgroups(-(-count // WORKGROUP), 1, 1)
    compute.end()
    device.queue.submit([encoder.finish()])
    data = np.frombuffer(device.queue.read_buffer(buffers[3]), dtype=np.float32)
    return data.reshape(-1, 4)[:count]


class WgslPath:
    """The WGSL float32 path: one dispatch per batch of rays."""

    name = "wgsl"
    precision = "float32"

    def __init__(self, formula: str):
        if formula not in ("slide", "robust"):
            raise ValueError("formula must be slide or robust, got %r" % (formula,))
        self.formula = formula

    def __call__(self, kind, origins, directions, tmin, tmax, shapes):
        n = origins.shape[0]
        rays = np.zeros((n, 2, 4), np.float32)
        rays[:, 0, :3] = origins
        rays[:, 0, 3] = tmin
        rays[:, 1, :3] = directions
        # WGSL has no inf literal and may assume finite floats: a far tmax stands in for inf.
        rays[:, 1, 3] = np.where(np.isposinf(tmax), FAR, tmax)
        out = _run(kind, self.formula == "robust", False, rays.reshape(-1, 4), shapes, n)
        return np.where(out[:, 0] > 0.5, out[:, 1], np.inf).astype(np.float32)

    def spawn(self, kind, positions, normals, directions, shapes):
        n = positions.shape[0]
        if self.formula == "slide":
            return positions.copy(), np.full(n, SPAWN_EPSILON, np.float32)
        rays = np.zeros((3 * n, 4), np.float32)
        rays[0:2 * n:2, :3] = positions
        rays[1:2 * n:2, :3] = normals
        rays[2 * n:, :3] = directions
        out = _run(kind, True, True, rays, shapes, n)
        return out[:, :3].copy(), np.zeros(n, np.float32)
