"""Known mistakes, computed on the staff side from a test's inputs: the numbers a student's
code gives when it errs in a way the hints name (the sphere's t with b^2 + 4ac, with a = 1,
the far root; Lambert's law without its cosine; a texture lookup with v not flipped or
without bilinear's half-texel shift; a slab test that does not swap t_near and t_far or
ignores tmax). They are solution maths, so this module is never shipped: ``write_known``
stores the numbers per case in ``reference/<assignment>/known.json`` and a hint only
compares numbers with them (it gets them as ``inputs["known"]``). ``slab_exact`` is also
the exact truth of a08's box tests (tests/test_grading.py holds the references to it).

A check names its function here with ``Check(known="sphere")``.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

REFERENCE_DIR = Path(__file__).resolve().parent / "reference"


def _quadratic(a, b, c):
    disc = float(b * b - 4 * a * c)
    if disc < 0:
        return disc, []
    e = math.sqrt(disc)
    return disc, [(-b - e) / (2 * a), (-b + e) / (2 * a)]


def sphere(inputs: dict) -> dict:
    """The slide's quadratic for the ray o + t d and the sphere (center, radius): a, the
    discriminant b^2 - 4ac, its roots; the roots with b^2 + 4ac and with a taken as 1."""
    o, d, c, r = inputs["o"], inputs["d"], inputs["center"], inputs["radius"]
    oc = [o[i] - c[i] for i in range(3)]
    a = float(sum(x * x for x in d))
    b = 2.0 * sum(oc[i] * d[i] for i in range(3))
    cc = float(sum(x * x for x in oc) - r * r)
    disc, roots = _quadratic(a, b, cc)
    plus = b * b + 4 * a * cc
    roots_plus = [] if plus < 0 else [(-b - math.sqrt(plus)) / (2 * a), (-b + math.sqrt(plus)) / (2 * a)]
    _, roots_a_is_one = _quadratic(1.0, b, cc)
    return {"a": a, "disc": disc, "roots": roots, "roots_plus_4ac": roots_plus, "roots_a_is_one": roots_a_is_one}


def triangle(inputs: dict) -> dict:
    """The barycentric coordinates where the ray meets the triangle's plane, exactly (the
    slides' p = v0 + beta e0 + gamma e1, e0 = v1 - v0, e1 = v2 - v0), and whether the point
    counts as inside with the classic slips: gamma's or beta's sign flipped, e0 and e1
    swapped (which flips both), the edge v1 v2 left out (beta + gamma < 1). None where the
    ray is parallel to the plane."""
    from fractions import Fraction

    v0, v1, v2, o, d = ([Fraction(c) for c in inputs[k]] for k in ("v0", "v1", "v2", "o", "d"))
    e0, e1 = [v1[i] - v0[i] for i in range(3)], [v2[i] - v0[i] for i in range(3)]
    n = [e0[1] * e1[2] - e0[2] * e1[1], e0[2] * e1[0] - e0[0] * e1[2], e0[0] * e1[1] - e0[1] * e1[0]]
    denom = sum(d[i] * n[i] for i in range(3))
    if denom == 0:
        return {}
    a = [v0[i] - o[i] for i in range(3)]
    c = [a[1] * d[2] - a[2] * d[1], a[2] * d[0] - a[0] * d[2], a[0] * d[1] - a[1] * d[0]]
    beta = sum(c[i] * e1[i] for i in range(3)) / denom
    gamma = -sum(c[i] * e0[i] for i in range(3)) / denom
    t = sum(a[i] * n[i] for i in range(3)) / denom

    def inside(b, g, closed=True):
        return b >= 0 and g >= 0 and (b + g <= 1 if closed else b + g < 1)

    return {"beta": float(beta), "gamma": float(gamma), "t": float(t), "inside": inside(beta, gamma),
            "gamma_sign": inside(beta, -gamma), "beta_sign": inside(-beta, gamma),
            "swapped_edges": inside(-gamma, -beta), "open_edge": inside(beta, gamma, closed=False)}


def concentric(inputs: dict) -> dict:
    """What concentric_map's classic slips give at (x, y): the polar map (r = sqrt(x),
    phi = 2 pi y: uniform on the disk too, but not Shirley and Chiu's), the map without the
    shift to [-1, 1]^2 (sx = x, sy = y), and phi left in eighths of a turn (no pi / 4)."""
    x, y = inputs["x"], inputs["y"]
    polar = [math.sqrt(x) * math.cos(2 * math.pi * y), math.sqrt(x) * math.sin(2 * math.pi * y)]

    def regions(sx, sy, scale):
        if sx > -sy:
            r, phi = (sx, sy / sx) if sx > sy else (sy, 2.0 - sx / sy)
        elif sx < sy:
            r, phi = -sx, 4.0 + sy / sx
        else:
            r, phi = -sy, (6.0 - sx / sy) if sy != 0.0 else 0.0
        return [r * math.cos(phi * scale), r * math.sin(phi * scale)]

    out = {"polar": polar, "no_pi_over_4": regions(2 * x - 1, 2 * y - 1, 1.0)}
    if x > 0.0 and y > 0.0:
        out["unshifted"] = regions(x, y, math.pi / 4)
    return out


def fresnel(inputs: dict) -> dict:
    """Fresnel's R at (cos_i, eta) with the classic slips: the two polarisations summed, not
    averaged; r_perp alone; eta turned over (n2 / n1); Schlick's approximation
    R0 + (1 - R0)(1 - cos_i)^5 instead of the equations."""
    cos_i, eta = inputs["cos_i"], inputs["eta"]

    def terms(eta):
        sin2_t = eta * eta * (1.0 - cos_i * cos_i)
        if sin2_t >= 1.0:
            return None
        cos_t = math.sqrt(1.0 - sin2_t)
        return ((eta * cos_i - cos_t) / (eta * cos_i + cos_t)) ** 2, ((cos_i - eta * cos_t) / (cos_i + eta * cos_t)) ** 2

    out = {}
    right = terms(eta)
    if right is not None:
        out["summed"], out["perp_only"] = right[0] + right[1], right[0]
    turned = terms(1.0 / eta)
    out["inverted_eta"] = 1.0 if turned is None else 0.5 * (turned[0] + turned[1])
    r0 = ((1.0 - eta) / (1.0 + eta)) ** 2
    out["schlick"] = r0 + (1.0 - r0) * (1.0 - cos_i) ** 5
    return out


def bouguer(inputs: dict) -> dict:
    """Bouguer's law with the sign of the exponent lost, and its first-order line 1 - sigma s."""
    a, s = inputs["absorption"], inputs["distance"]
    return {"plus": [math.exp(c * s) for c in a], "linear": [1.0 - c * s for c in a]}


def lambert(inputs: dict) -> dict:
    """n . w_i for every light of a lambertian case (n the unit normal, w_i toward the light)."""
    normal, position = inputs["normal"], inputs["position"]
    length = math.sqrt(sum(v * v for v in normal))
    n = [v / length for v in normal]
    cos = []
    for light in inputs["lights"]:
        w = [light[i] - position[i] for i in range(3)]
        dist = math.sqrt(sum(v * v for v in w))
        cos.append(sum(n[i] * w[i] / dist for i in range(3)))
    return {"cos": [float(c) for c in cos]}


def kepler(inputs: dict) -> dict:
    """The distance from the sampled point to the light."""
    return {"dist": float(math.dist(inputs["p"], inputs["x"]))}


def _texel(texels, i, j, address):
    """Texel column i, row j from the top of ``texels`` (rows of [r, g, b]), addressed."""
    height, width = len(texels), len(texels[0])
    if address == "repeat":
        i, j = i % width, j % height
    else:
        i, j = min(max(i, 0), width - 1), min(max(j, 0), height - 1)
    return [float(c) for c in texels[j][i]]


def _lookup(texels, u, v, filter, address, texel_address=None, shift=0.5, flip=True, nearest=math.floor):
    """Worksheet 3's lookup, with the parts a known mistake changes as parameters: the address
    mode of the texel indices, the half-texel shift of bilinear, the flip of v (row 0 at v = 1)
    and how nearest picks its texel."""
    height, width = len(texels), len(texels[0])
    if address == "repeat":
        u, v = u - math.floor(u), v - math.floor(v)
    else:
        u, v = min(max(u, 0.0), 1.0), min(max(v, 0.0), 1.0)
    texel_address = texel_address or address
    x = u * width
    y = (1.0 - v) * height if flip else v * height
    if filter == "nearest":
        return _texel(texels, int(nearest(x)), int(nearest(y)), texel_address)
    x, y = x - shift, y - shift
    i, j = math.floor(x), math.floor(y)
    fx, fy = x - i, y - j
    corners = [_texel(texels, i + a, j + b, texel_address) for b in (0, 1) for a in (0, 1)]
    weights = ((1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy)
    return [float(sum(w * c[k] for w, c in zip(weights, corners))) for k in range(3)]


def texture(inputs: dict) -> dict:
    """An a07 case: for texel(i, j) the texel under the other address mode and counted from
    the bottom row; for get_color(u, v) the colour with v not flipped, without the half-texel
    shift (bilinear), rounded to the nearest texel index instead of floored (nearest), and
    with the other address mode (clamp: the indices wrapped, or u, v and the indices
    wrapped; repeat: clamped)."""
    texels, address = inputs["texels"], inputs["address"]
    other = "clamp" if address == "repeat" else "repeat"
    if "i" in inputs:
        i, j = inputs["i"], inputs["j"]
        return {"other_address": _texel(texels, i, j, other),
                "row_from_bottom": _texel(texels, i, len(texels) - 1 - j, address)}
    args = (texels, inputs["u"], inputs["v"], inputs["filter"])
    known = {"v_not_flipped": _lookup(*args, address, flip=False)}
    if inputs["filter"] == "bilinear":
        known["no_half_texel_shift"] = _lookup(*args, address, shift=0.0)
    else:
        known["nearest_rounds"] = _lookup(*args, address, nearest=lambda x: math.floor(x + 0.5))
    if address == "clamp":
        known["clamp_wraps"] = _lookup(*args, address, texel_address="repeat")
        known["clamp_is_repeat"] = _lookup(*args, "repeat")
    else:
        known["repeat_clamps"] = _lookup(*args, "clamp")
    return known


def slab_exact(p0, p1, o, d, tmin, tmax, swap=True, use_tmin=True, use_tmax=True, zero_axes=True,
               closed=True, result="enter"):
    """The slab test (Williams et al. 2005) in rationals (every input float converts to a
    Fraction without rounding): the t at which the ray o + t d enters the box [p0, p1] within
    [tmin, tmax], as a float, or inf if it misses. The box and the interval are closed. The
    keywords switch off one part each, for the known mistakes: the swap of t_near and t_far,
    tmin or tmax, the check of an axis whose direction component is 0 (``zero_axes``); with
    ``closed=False`` a touch misses, with ``result="exit"`` the exit t is returned."""
    from fractions import Fraction as Q

    t0 = Q(float(tmin)) if use_tmin else None                       # None: -infinity
    t1 = Q(float(tmax)) if use_tmax and not math.isinf(tmax) else None  # None: +infinity
    for a in range(3):
        oa, wa, lo, hi = Q(float(o[a])), Q(float(d[a])), Q(float(p0[a])), Q(float(p1[a]))
        if wa == 0:
            if not zero_axes:
                continue
            if (oa < lo or oa > hi) if closed else (oa <= lo or oa >= hi):
                return math.inf
            continue
        t_near, t_far = (lo - oa) / wa, (hi - oa) / wa
        if swap and t_near > t_far:
            t_near, t_far = t_far, t_near
        t0 = t_near if t0 is None else max(t0, t_near)
        t1 = t_far if t1 is None else min(t1, t_far)
        if (t0 > t1) if closed else (t0 >= t1):
            return math.inf
    t = t0 if result == "enter" else t1
    if t is None:
        return -math.inf if result == "enter" else math.inf
    return float(t)


def _slab_float(p0, p1, o, d, tmin, tmax, widen=True):
    """The slab test in floats, as BBox.hit computes it, with or without the widening of t_far."""
    wider = 1.0 + 2.0 * (3 * 2.0 ** -53) / (1 - 3 * 2.0 ** -53)
    t0, t1 = float(tmin), float(tmax)
    for a in range(3):
        if d[a] == 0.0:
            if o[a] < p0[a] or o[a] > p1[a]:
                return math.inf
            continue
        t_near, t_far = (p0[a] - o[a]) / d[a], (p1[a] - o[a]) / d[a]
        if t_near > t_far:
            t_near, t_far = t_far, t_near
        if widen:
            t_far *= wider
        t0, t1 = max(t0, t_near), min(t1, t_far)
        if t0 > t1:
            return math.inf
    return t0


def slab(inputs: dict) -> dict:
    """An a08 box case: BBox.hit's answer without the swap of t_near and t_far, ignoring tmax,
    ignoring tmin, returning the exit, skipping the axes of direction component 0, with an
    open box (a touch misses), and (in floats) without widening t_far."""
    args = (inputs["p0"], inputs["p1"], inputs["o"], inputs["d"], inputs["tmin"], inputs["tmax"])
    return {"no_swap": slab_exact(*args, swap=False), "ignores_tmax": slab_exact(*args, use_tmax=False),
            "ignores_tmin": slab_exact(*args, use_tmin=False), "exit": slab_exact(*args, result="exit"),
            "zero_skipped": slab_exact(*args, zero_axes=False), "open_box": slab_exact(*args, closed=False),
            "no_widen": _slab_float(*args, widen=False)}


def known_for(check, observation: dict):
    """The known mistakes of every case of ``observation`` (a reference observation of
    ``check``), or None if the check names none."""
    if not check.known:
        return None
    function = globals()[check.known]
    return [function(case.get("in", {})) for case in observation.get("cases", [])]


def write_known(assignment, reference_dir: Path = REFERENCE_DIR):
    """Write ``known.json`` (slug -> one dict per case) beside the assignment's reference
    observations, from their inputs; returns its path (None, and no file, if no test of the
    assignment names known mistakes)."""
    from .checks import checks_for

    folder = Path(reference_dir) / assignment.id
    observations = json.loads((folder / "observations.json").read_text())
    known = {}
    for check in checks_for(assignment.id):
        if check.kind == "cases" and check.slug in observations:
            cases = known_for(check, observations[check.slug])
            if cases is not None:
                known[check.slug] = cases
    path = folder / "known.json"
    if not known:
        if path.exists():
            path.unlink()
        return None
    path.write_text(json.dumps(known, indent=1, sort_keys=True) + "\n")
    return path


def area_sample(inputs: dict) -> dict:
    """A triangle's point at (u, v) without the square root (v0 + (e0 v + e1 (1 - v)) u: the
    points crowd toward v0) and with the barycentrics taken as (u, v) directly (not uniform,
    and off the triangle where u + v > 1)."""
    if inputs["kind"] != "triangle":
        return {}
    (v0, v1, v2), u, v = inputs["corners"], inputs["u"], inputs["v"]
    e0 = [v1[k] - v0[k] for k in range(3)]
    e1 = [v2[k] - v0[k] for k in range(3)]
    return {"no_sqrt": [v0[k] + (e0[k] * v + e1[k] * (1.0 - v)) * u for k in range(3)],
            "direct": [v0[k] + e0[k] * u + e1[k] * v for k in range(3)]}


def light_terms(inputs: dict) -> dict:
    """G and pdf of an area light's point with the classic slips: G without its square
    (cos / d), G without the light's cosine (1 / d^2), pdf = A instead of 1 / A."""
    point, position = inputs["point"], inputs["position"]
    d = [point[k] - position[k] for k in range(3)]
    dist = math.sqrt(sum(x * x for x in d))
    kind, corners = inputs["kind"], inputs["corners"]
    if kind == "sphere":
        c, r = corners[0], corners[1][0]
        n = [(point[k] - c[k]) / r for k in range(3)]
        area = 4.0 * math.pi * r * r
    else:
        origin = corners[0]
        e0 = [corners[1][k] - origin[k] for k in range(3)] if kind == "triangle" else corners[1]
        e1 = [corners[2][k] - origin[k] for k in range(3)] if kind == "triangle" else corners[2]
        cross = [e0[1] * e1[2] - e0[2] * e1[1], e0[2] * e1[0] - e0[0] * e1[2], e0[0] * e1[1] - e0[1] * e1[0]]
        length = math.sqrt(sum(x * x for x in cross))
        n = [x / length for x in cross]
        area = length / 2.0 if kind == "triangle" else math.sqrt(sum(x * x for x in e0)) * math.sqrt(sum(x * x for x in e1))
    cos_l = -sum(n[k] * d[k] for k in range(3)) / dist
    return {"G_unsquared": max(cos_l, 0.0) / dist, "G_no_cosine": 1.0 / (dist * dist), "pdf_area": area}
