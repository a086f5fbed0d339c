"""a06: the intersection functions in WGSL (02562 week 2), run on the GPU adapter through wgpu.
The probes are in rtfgu/grading/probes/a06.py; each runs in a newly started interpreter (a
GPU driver does not survive fork), in float32."""
from __future__ import annotations

from . import Check, image_check, register
from .a03 import hint_sphere


def hint_sphere_wgsl(inputs, want, got):
    """a03's sphere hints, on what the WGSL function returned and put in the HitInfo."""
    def as_a03(out):
        return {"returned": out.get("returned"),
                "ray.tmax": out.get("hit.dist", inputs["tmax"]) if out.get("returned") else inputs["tmax"]}
    return hint_sphere(inputs, as_a03(want), as_a03(got))


OPTIONS = dict(fresh=True, memory_mb=0, rtol=1e-4, atol=1e-5)

register("a06_wgsl_intersections", [
    Check("intersect_plane in WGSL: hits, misses, the interval and the HitInfo", 2, ("a06", "observe_plane"),
          needs=("wgsl/intersect_plane.wgsl",), **OPTIONS),
    Check("intersect_sphere in WGSL: near and far roots, misses and [tmin, tmax)", 3, ("a06", "observe_sphere"),
          hint=hint_sphere_wgsl, known="sphere", needs=("wgsl/intersect_sphere.wgsl",), **OPTIONS),
    Check("intersect_triangle in WGSL: inside, outside and the interval", 2, ("a06", "observe_triangle"),
          needs=("wgsl/intersect_triangle.wgsl",), **OPTIONS),
    image_check("image: 02562 default scene in flat colours, rendered by your WGSL", 2, "default_flat_colors",
                size=(32, 32), render="a06.render_wgsl", fresh=True, memory_mb=0),
])
