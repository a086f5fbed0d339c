"""Probes of a09's visible tests: Suffern's hemisphere map (``hemisphere_map``), the sampled
Lambertian BRDF (``Lambertian.sample_f``) and images path traced with them (Suffern ch. 7
and 26; 02562 worksheet 7).

The tests are statistical: a probe draws many samples with the student's code from uniform
numbers of its own fixed stream and returns every one of them, never a verdict, nor a
histogram or a sum: the probe runs in the student's interpreter, whose code could replace it,
and a histogram or a sum is easily forged where its truth is known exactly (flat counts, the
integral's value), every sample only by drawing them from the right density. The grader bins
and sums them with this module's functions (bin_hemisphere, summarize_sample_f). Directions
are binned by t = cos(theta)^(e + 1), which is uniform in [0, 1) for the density (e + 1) /
(2 pi) cos^e(theta), and by phi; the judge applies a chi-square test. The estimator of the
reflected light is summed as mean and variance of f (n . w_i) g(w_i) / pdf for a few
functions g whose integrals are known exactly. Images come back as per-pixel
means and variances over the samples. The contract's probes return what the code gave, point
by point: hemisphere_map twice at each point, and sample_f's every direction with its pdf."""
from __future__ import annotations

import importlib
import math
import random

from .support import StudentError, num, vec

T_BINS = 8          # bins of t = cos(theta)^(e + 1)
PHI_BINS = 8        # bins of the angle about the axis
SHOWN = 5           # the bad samples shown in a message
UNIT = 1e-9         # |length - 1| allowed of a direction
BELOW = 1e-9        # n . w allowed below 0 (rounding at the horizon)


def _uniforms(count: int, seed: int):
    stream = random.Random(seed)
    return [(stream.random(), stream.random()) for _ in range(count)]


def _frame(n):
    """Two unit vectors that make an orthonormal frame with the unit n (plain lists)."""
    a = [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0]
    t = [n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]]
    length = math.sqrt(sum(c * c for c in t))
    t = [c / length for c in t]
    b = [n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]]
    return t, b


def _dot(a, b) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


class Binned:
    """Directions about an axis binned by t = cos^(e + 1) and phi, and the bad ones."""

    def __init__(self, axis, e: float):
        self.axis, self.e = axis, e
        self.t, self.b = _frame(axis)
        self.counts = [[0] * PHI_BINS for _ in range(T_BINS)]
        self.bad = []          # [what, the uniform numbers, the direction]
        self.n_bad = 0

    def add(self, d, uv) -> bool:
        length = math.sqrt(_dot(d, d)) if all(math.isfinite(c) for c in d) else math.nan
        cos_theta = _dot(d, self.axis)
        what = None
        if not math.isfinite(length):
            what = "not finite"
        elif abs(length - 1.0) > UNIT:
            what = "length %.9g, not 1" % length
        elif cos_theta < -BELOW:
            what = "below the surface (cos(theta) = %.6g)" % cos_theta
        if what is not None:
            self.n_bad += 1
            if len(self.bad) < SHOWN:
                self.bad.append([what, list(uv), d])
            return False
        cos_theta = min(max(cos_theta, 0.0), 1.0)
        t = cos_theta ** (self.e + 1.0)
        phi = math.atan2(_dot(d, self.b), _dot(d, self.t)) % (2.0 * math.pi)
        i = min(int(t * T_BINS), T_BINS - 1)
        j = min(int(phi / (2.0 * math.pi) * PHI_BINS), PHI_BINS - 1)
        self.counts[i][j] += 1
        return True

    def result(self) -> dict:
        return {"axis": list(self.axis), "e": self.e, "counts": self.counts, "bad": self.bad, "n_bad": self.n_bad}


def maps(rt):
    """The student's rtfgu.sampling.maps."""
    return importlib.import_module(rt.__name__ + ".sampling.maps")


def observe_hemisphere(rt, exponents, count: int, seed: int):
    """hemisphere_map(x, y, e) for ``count`` uniform points per exponent: every direction."""
    out = []
    for e in exponents:
        out.append({"e": float(e), "directions": [
            vec(maps(rt).hemisphere_map(x, y, float(e)), "hemisphere_map(%r, %r, %r)" % (x, y, e))
            for x, y in _uniforms(count, seed)]})
    return {"sets": out}


def _count_of(samples, count: int, what: str) -> list:
    if not isinstance(samples, list) or len(samples) != count:
        raise ValueError("%s: not the %d samples the test drew" % (what, count))
    return samples


def bin_hemisphere(directions, e: float, count: int, seed: int) -> dict:
    """The grader's side of observe_hemisphere: the ``count`` directions (those of the
    uniform points of ``seed``) binned about +z (Binned.result)."""
    binned = Binned([0.0, 0.0, 1.0], float(e))
    for d, uv in zip(_count_of(directions, count, "hemisphere_map"), _uniforms(count, seed)):
        binned.add([float(c) for c in d], uv)
    return binned.result()


def observe_hemisphere_points(rt, points):
    """hemisphere_map at chosen points (x, y, e): the directions, for the judge's exact checks."""
    out = []
    for x, y, e in points:
        try:
            out.append({"in": [x, y, e], "out": vec(maps(rt).hemisphere_map(x, y, e),
                                                    "hemisphere_map(%r, %r, %r)" % (x, y, e))})
        except StudentError as error:
            out.append({"in": [x, y, e], "error": str(error)})
    return {"points": out}


def observe_hemisphere_twice(rt, points):
    """hemisphere_map at every point (x, y, e), then at every point again: both rounds'
    directions, for the judge (a function of its arguments gives the same twice)."""
    return {"first": observe_hemisphere_points(rt, points)["points"],
            "second": observe_hemisphere_points(rt, points)["points"]}


# The functions g(w) of the estimator test, of c = n . w (cos(theta)) and of w itself, and
# their integrals over the hemisphere of n (exact: the judge holds the same table).
G_NAMES = ("1", "cos", "cos^2", "lateral")


def _g(name, c, d, lateral):
    if name == "1":
        return 1.0
    if name == "cos":
        return c
    if name == "cos^2":
        return c * c
    return max(_dot(d, lateral), 0.0)   # light from one side: max(w . a, 0), a in the tangent plane


def _sample_f(brdf, sr, wo, u, v):
    """(f, w_i, pdf) of brdf.sample_f(sr, wo, u, v) as plain lists and a float."""
    got = brdf.sample_f(sr, wo, u, v)
    if not isinstance(got, tuple) or len(got) != 3:
        raise StudentError("Lambertian.sample_f should return a tuple (f, w_i, pdf), but it returned %r" % (got,))
    return (vec(got[0], "f (the first value of sample_f)"), vec(got[1], "w_i (the second value of sample_f)"),
            num(got[2], "pdf (the third value of sample_f)"))


def _lambertian(rt, normal, rho):
    """(Lambertian(1, rho), a HitInfo whose normal is ``normal``)."""
    brdf = importlib.import_module(rt.__name__ + ".brdfs.lambertian").Lambertian(1.0, rt.Float3(*rho))
    sr = rt.HitInfo()
    sr.normal = rt.Float3(*normal)
    return brdf, sr


def observe_sample_directions(rt, normals, count: int, seed: int):
    """Lambertian(1, 1).sample_f(sr, wo, u, v), sr.normal = n, for ``count`` uniform (u, v)
    per normal: every direction w_i and pdf as returned, [x, y, z, pdf] (the judge bins them
    and tests pdf as the density of the directions)."""
    out = []
    for n in normals:
        brdf, sr = _lambertian(rt, n, (1.0, 1.0, 1.0))
        samples = []
        for u, v in _uniforms(count, seed):
            _, d, pdf = _sample_f(brdf, sr, sr.normal, u, v)
            samples.append(d + [pdf])
        out.append({"normal": list(n), "samples": samples})
    return {"sets": out}


def observe_sample_f(rt, normals, rhos, count: int, seed: int):
    """Lambertian(1, rho).sample_f(sr, wo, u, v), sr.normal = n, for ``count`` uniform (u, v)
    per normal: every sample as returned, [f_r, f_g, f_b, x, y, z, pdf] (summarize_sample_f
    makes what the judge reads of them)."""
    out = []
    for n, rho in zip(normals, rhos):
        brdf, sr = _lambertian(rt, n, rho)
        wo = sr.normal
        samples = []
        for u, v in _uniforms(count, seed):
            f, d, pdf = _sample_f(brdf, sr, wo, u, v)
            samples.append(f + d + [pdf])
        out.append({"normal": list(n), "rho": list(rho), "samples": samples})
    return {"sets": out}


def summarize_sample_f(n, rho, samples, count: int, seed: int) -> dict:
    """The grader's side of observe_sample_f for the normal ``n`` and albedo ``rho`` the test
    asked for: the directions binned (e = 1, the cosine-weighted density, for the hint only),
    the bad ones, the first f, and per g of G_NAMES the sum and the sum of squares of f (n .
    w_i) g(w_i) / pdf divided by rho (channel by channel)."""
    binned = Binned(list(n), 1.0)
    lateral = _frame(n)[0]
    sums = {g: [[0.0, 0.0] for _ in range(3)] for g in G_NAMES}
    f_seen, bad_pdf, n_bad_pdf, used = None, [], 0, 0
    for sample, (u, v) in zip(_count_of(samples, count, "sample_f"), _uniforms(count, seed)):
        if not isinstance(sample, list) or len(sample) != 7:
            raise ValueError("sample_f: a sample is not [f, w_i, pdf]")
        values = [float(c) for c in sample]
        f, d, pdf = values[:3], values[3:6], values[6]
        if f_seen is None:
            f_seen = f
        if not binned.add(d, (u, v)):
            continue
        if not (math.isfinite(pdf) and pdf > 0.0):
            n_bad_pdf += 1
            if len(bad_pdf) < SHOWN:
                bad_pdf.append([[u, v], d, pdf])
            continue
        used += 1
        c = max(_dot(d, n), 0.0)
        for g in G_NAMES:
            w = _g(g, c, d, lateral) * c / pdf
            for k in range(3):
                x = f[k] * w / rho[k]
                sums[g][k][0] += x
                sums[g][k][1] += x * x
    return {"normal": list(n), "rho": list(rho), "f": f_seen, "count": count, "used": used,
            "directions": binned.result(), "bad_pdf": bad_pdf, "n_bad_pdf": n_bad_pdf, "sums": sums}


# --- images ----------------------------------------------------------------------------------

def one_bounce_scene(rt):
    """Worksheet 5's Cornell box with its blocks, path traced with two vertices: the direct
    light and one bounce of diffuse interreflection. A point light just under the ceiling (and
    no ceiling lamp) makes the direct light exact, so that the image's noise is the bounce's
    own: a bias in it stands out of less noise than under the area light."""
    scene = rt.scenes.get_scene("cornell_box_area_light")()
    scene.shapes = [s for s in scene.shapes if max(s.material.emission.x, s.material.emission.y,
                                                   s.material.emission.z) == 0.0]
    scene.lights = [rt.PointLight(rt.Float3(0.278, 0.45, 0.2795), rt.Float3(0.2, 0.2, 0.2))]
    scene.tracer = rt.PathTrace(max_depth=2)
    return scene


def furnace_scene(rt, rho):
    """The white furnace: a diffuse sphere of albedo ``rho`` under a white sky (background 1),
    path traced with two vertices, seen from 3 away with d = 5, so that the sphere (19.5 degrees
    across from the eye) fills the image (17.5 degrees to its corners). The sphere is convex, so
    every bounce leaves to the sky: every pixel is rho in expectation, exactly."""
    F = rt.Float3
    scene = rt.Scene(rt.PinholeCamera(eye=(0.0, 0.0, 3.0), lookat=(0.0, 0.0, 0.0), up=(0.0, 1.0, 0.0), d=5.0))
    scene.background = F(1.0)
    scene.shapes.append(rt.Sphere(F(0.0, 0.0, 0.0), 1.0, F(*rho), rt.Matte(ka=0.0, kd=1.0)))
    scene.tracer = rt.PathTrace(max_depth=2)
    return scene


SCENES = {"one_bounce": one_bounce_scene}


def build(rt, scene, rho=None):
    if scene == "furnace":
        return furnace_scene(rt, rho)
    return SCENES[scene](rt)


def observe_image(rt, scene: str, width: int, height: int, spp: int, seed: int, rho=None):
    """The scene rendered with the student's code, one sample of every pixel at a time: the
    per-pixel mean and the per-pixel variance of the samples (channel by channel)."""
    renderer = importlib.import_module(rt.__name__ + ".renderer")
    built = build(rt, scene, rho)
    sampler = renderer.pixel_sampler(built, spp)
    total = [[[0.0] * 3 for _ in range(width)] for _ in range(height)]
    squares = [[[0.0] * 3 for _ in range(width)] for _ in range(height)]
    for s in range(spp):
        one = renderer.render_reference(built, width, height, sampler=sampler, seed=seed, samples=(s, s + 1))
        for j in range(height):
            for i in range(width):
                for k in range(3):
                    x = float(one[j, i, k])
                    total[j][i][k] += x
                    squares[j][i][k] += x * x
    mean = [[[c / spp for c in px] for px in row] for row in total]
    variance = [[[max(squares[j][i][k] / spp - mean[j][i][k] ** 2, 0.0) * spp / (spp - 1) for k in range(3)]
                 for i in range(width)] for j in range(height)]
    return {"mean": mean, "variance": variance, "spp": spp}
