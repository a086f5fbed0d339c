"""Maps of unit-square samples on every path, and Pearson's chi-square test of a histogram
against a density, as Nori's warptest does it: the domain cut into cells of known exact
probability, cells with an expected count below 5 pooled, the p-value from the regularized
upper incomplete gamma function (mpmath)."""
from __future__ import annotations

import math

import mpmath
import numpy as np
from numba import njit

from rtfgu.kernels import sampling as ks
from rtfgu.sampling import maps
from rtfgu.sampling.random import random_float

# Where a map is evaluated: the lecture layer, the numba kernels in float64 and float32,
# and WGSL through the batch harness.
MAP_PATHS = ("reference", "numba-float64", "numba-float32", "wgpu-float32")


def uniform_points(n: int, seed: int = 7) -> np.ndarray:
    """n points of [0, 1)^2 from the random stream (pixel k, dimensions 0 and 1)."""
    return np.array([(random_float(k, 0, 0, seed), random_float(k, 0, 1, seed)) for k in range(n)])


@njit(cache=True)
def _disk_numba(points, out):
    for k in range(points.shape[0]):
        out[k, 0], out[k, 1] = ks.concentric_map(points[k, 0], points[k, 1])


@njit(cache=True)
def _hemisphere_numba(points, e, out):
    for k in range(points.shape[0]):
        out[k, 0], out[k, 1], out[k, 2] = ks.hemisphere_map(points[k, 0], points[k, 1], e)


_WGSL_MAIN = """
@group(0) @binding(0) var<storage, read> points: array<vec2f>;
@group(0) @binding(1) var<storage, read> e: array<vec4f>;
@group(0) @binding(2) var<storage, read_write> out: array<vec4f>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u)
{
    if (id.x >= arrayLength(&points)) {
        return;
    }
    // #if disk
    out[id.x] = vec4f(concentric_map(points[id.x]), 0.0, 0.0);
    // #else
    out[id.x] = vec4f(hemisphere_map(points[id.x], e[0].x), 0.0);
    // #endif
}
"""


def _wgsl(name: str, points: np.ndarray, e: float) -> np.ndarray:
    from rtfgu.wgsl.harness import batch_program, run_batch

    piece = "concentric_map.wgsl" if name == "disk" else "hemisphere_map.wgsl"
    program = batch_program([piece, "map_main.wgsl"], features={name},
                            overrides={"map_main.wgsl": _WGSL_MAIN})
    data = points.astype(np.float32)
    out = run_batch(program, [data, np.array([e, 0, 0, 0], dtype=np.float32)], len(points))
    return out[:, 0, :2 if name == "disk" else 3].astype(np.float64)


def map_points(path: str, name: str, points: np.ndarray, e: float = 1.0) -> np.ndarray:
    """``points`` (n, 2) through the map ``name`` ("disk" or "hemisphere") on ``path``:
    (n, 2) disk points or (n, 3) directions."""
    if path == "reference":
        if name == "disk":
            return np.array([maps.concentric_map(x, y) for x, y in points])
        return np.array([tuple(maps.hemisphere_map(x, y, e)) for x, y in points])
    if path.startswith("numba"):
        dtype = np.float32 if path.endswith("32") else np.float64
        p = points.astype(dtype)
        if name == "disk":
            out = np.zeros((len(p), 2), dtype=dtype)
            _disk_numba(p, out)
        else:
            out = np.zeros((len(p), 3), dtype=dtype)
            _hemisphere_numba(p, dtype(e), out)
        return out.astype(np.float64)
    return _wgsl(name, points, e)


def chi_square_p(observed: np.ndarray, expected: np.ndarray) -> float:
    """The p-value of Pearson's statistic, cells with expected < 5 pooled into one."""
    observed = np.asarray(observed, dtype=float).ravel()
    expected = np.asarray(expected, dtype=float).ravel()
    small = expected < 5
    obs = list(observed[~small])
    exp = list(expected[~small])
    if small.any():
        obs.append(observed[small].sum())
        exp.append(expected[small].sum())
    obs, exp = np.array(obs), np.array(exp)
    statistic = float(np.sum((obs - exp) ** 2 / exp))
    dof = len(obs) - 1
    return float(mpmath.gammainc(dof / 2.0, statistic / 2.0, mpmath.inf, regularized=True))


def disk_histogram(points: np.ndarray, bins: int = 16):
    """Observed and expected counts of disk points in cells of equal area: r^2 and phi cut
    into ``bins`` equal parts each (uniform density 1 / pi)."""
    r2 = np.clip(points[:, 0] ** 2 + points[:, 1] ** 2, 0, np.nextafter(1, 0))
    phi = (np.arctan2(points[:, 1], points[:, 0]) / (2 * math.pi)) % 1.0
    observed, _, _ = np.histogram2d(r2, phi, bins=bins, range=[[0, 1], [0, 1]])
    return observed, np.full((bins, bins), len(points) / bins ** 2)


def hemisphere_histogram(directions: np.ndarray, e: float, bins: int = 16):
    """Observed and expected counts of directions in cells of cos(theta) x phi; the
    density (e + 1) / (2 pi) cos^e gives cos(theta) in [a, b] the exact probability
    b^(e + 1) - a^(e + 1), and phi is uniform."""
    z = np.clip(directions[:, 2], 0, 1)
    phi = (np.arctan2(directions[:, 1], directions[:, 0]) / (2 * math.pi)) % 1.0
    observed, _, _ = np.histogram2d(z, phi, bins=bins, range=[[0, 1], [0, 1]])
    edges = np.linspace(0, 1, bins + 1)
    p_z = edges[1:] ** (e + 1) - edges[:-1] ** (e + 1)
    expected = np.outer(p_z, np.full(bins, 1.0 / bins)) * len(directions)
    return observed, expected
