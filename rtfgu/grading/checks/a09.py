"""a09: cosine-weighted hemisphere sampling and one bounce of diffuse interreflection
(Suffern ch. 7, "Mapping Samples to a Hemisphere", and ch. 26, "Lambertian::sample_f";
02562 worksheet 7). The probes are in rtfgu/grading/probes/a09.py (visible) and
a09_hidden.py.

Every test is statistical (rtfgu.grading.checks.statistics): the directions' distribution by
a chi-square test, the estimator f (n . w_i) g(w_i) / pdf against integrals known exactly,
the white furnace against its exact expectation rho, and the Cornell box against a reference
estimate of many samples, each within the Monte Carlo error. A correct sampler other than
the reference's (the uniform hemisphere with pdf 1 / (2 pi)) passes; its extra noise is
reported, and only noise far beyond any sensible sampler's fails. Two tests hold the contract
on inputs drawn for each grading: hemisphere_map is Suffern's map, the same direction for the
same (x, y, e), and sample_f's pdf is the density of its directions, cell by cell over the
hemisphere (an importance-weighted histogram) and at each cosine-weighted direction
(docs/grading_sandbox.md, "a09's statistical tests: calibration").
"""
from __future__ import annotations

import math

import numpy as np

from ..probes.a09 import BELOW, UNIT, bin_hemisphere, summarize_sample_f
from . import Check, close, fmt, register
from .statistics import (CHI_SQUARE_ALPHA, EXACT, PIXEL_FRACTION, Z_LIMIT, Z_PIXEL, chi_square_p, image_z, mean_z,
                         worst_cell)

SEED = 9                    # the probes' stream of uniform numbers
COUNT = 8192                # samples per set: 128 per bin of 8 x 8
IMAGE = dict(width=20, height=20, spp=64, seed=0)
FURNACE = dict(width=12, height=12, spp=64, seed=0)
REFERENCE_SEEDS = 256       # the Cornell box reference: 256 x 64 samples per pixel
REFERENCE_SEED0 = 1000      # ... from seeds the student's render does not use
IMAGE_SECONDS = 240.0       # the image test renders 25,600 paths in pure Python: about 5 s here
NOISE_LIMIT = 16.0          # an image this many times noisier (variance) than the reference fails
# The integrals of f (n . w) g(w) / rho over the hemisphere, f = rho / pi (probes.a09.G_NAMES).
G_TRUTH = {"1": 1.0, "cos": 2.0 / 3.0, "cos^2": 0.5, "lateral": 2.0 / (3.0 * math.pi)}

MAPS = ("sampling/maps.py",)


def _bad_lines(binned, what: str) -> list:
    lines = []
    if binned.get("n_bad"):
        lines.append("%d of your %s are not unit directions in the hemisphere (the +z side, or the side n points "
                     "to), for example:" % (binned["n_bad"], what))
        for reason, uv, d in binned["bad"]:
            lines.append("- from (%s, %s): %s, %s" % (fmt(uv[0]), fmt(uv[1]), fmt(d), reason))
    return lines


def _density_lines(binned, label: str, count: int):
    """(right, lines) of the chi-square test of one binned set."""
    counts = np.asarray(binned["counts"], dtype=np.float64)
    lines = _bad_lines(binned, label)
    if lines:
        return False, lines
    p = chi_square_p(counts)
    if p >= CHI_SQUARE_ALPHA:
        return True, []
    e = binned["e"]
    by_t = counts.sum(axis=1)
    by_phi = counts.sum(axis=0)
    (i, j), seen, expected = worst_cell(counts)
    line = ("- %s: the %d directions do not have the density (e + 1) / (2 pi) cos^e(theta) with e = %s "
            "(chi-square p = %.2g, below %g). Binned by t = cos(theta)^(e + 1), which that density makes uniform, "
            "the 8 bins from t = 0 (the horizon) to t = 1 (the axis) hold %s of about %d each; by the angle phi "
            "about the axis, %s. The cell t in [%g, %g), phi bin %d holds %d, about %d expected."
            % (label, count, fmt(float(e)), p, CHI_SQUARE_ALPHA, [int(c) for c in by_t], count // len(by_t),
               [int(c) for c in by_phi], i / 8, (i + 1) / 8, j, seen, round(expected)))
    spread = by_t.max() / max(by_t.min(), 1.0)
    if spread > 1.5 and by_phi.max() / max(by_phi.min(), 1.0) < 1.3:
        line += ("\n  Hint: the angle about the axis is fine and cos(theta) is not: with y uniform, cos(theta) = "
                 "(1 - y)^(1 / (e + 1)) (Suffern ch. 7), whose (e + 1)-th power is uniform")
    elif by_phi.max() / max(by_phi.min(), 1.0) > 1.3:
        line += "\n  Hint: phi = 2 pi x should cover the whole circle, each angle as often as any other"
    return False, [line]


def judge_hemisphere(check, got, reference):
    """Each set of hemisphere_map directions against its density (chi-square)."""
    if "error" in got:
        return 0.0, [got["error"]]
    sets = got["sets"]
    if len(sets) != len(reference["exponents"]):
        return 0.0, ["the test stopped before it tried every exponent"]
    right, lines = 0, []
    asked = check.probe[2]
    for entry, e in zip(sets, reference["exponents"]):
        if float(entry["e"]) != float(e):
            return 0.0, ["the test's answer was not in the form the test writes"]
        binned = bin_hemisphere(entry["directions"], e, asked["count"], asked["seed"])
        ok, more = _density_lines(binned, "hemisphere_map(x, y, %s)" % fmt(float(e)), reference["count"])
        right += ok
        lines += more
        if ok:
            lines.append("- e = %s: the %d directions have the density (e + 1) / (2 pi) cos^e(theta)"
                         % (fmt(float(e)), reference["count"]))
    return right / len(sets), lines


def judge_points(check, got, reference):
    """hemisphere_map at chosen points: a finite unit direction on the +z side."""
    if "error" in got:
        return 0.0, [got["error"]]
    points = got["points"]
    if len(points) != len(reference["points"]):
        return 0.0, ["the test stopped before it tried every point"]
    right, lines = 0, []
    for entry, want in zip(points, reference["points"]):
        x, y, e = want
        label = "hemisphere_map(%s, %s, %s)" % (fmt(float(x)), fmt(float(y)), fmt(float(e)))
        if "error" in entry:
            lines.append("- %s: your code raised %s" % (label, entry["error"]))
            continue
        d = entry["out"]
        if not all(isinstance(c, float) and math.isfinite(c) for c in d):
            lines.append("- %s is %s: not a finite direction" % (label, fmt(d)))
        elif abs(math.hypot(*d) - 1.0) > 1e-9:
            lines.append("- %s is %s, of length %.9g: not a unit vector" % (label, fmt(d), math.hypot(*d)))
        elif d[2] < -1e-9:
            lines.append("- %s is %s: below the hemisphere (z < 0)" % (label, fmt(d)))
        else:
            right += 1
    return right / len(points), lines


def judge_lobe_and_corners(check, got, reference):
    """A Phong lobe's directions (chi-square) and finite unit directions at the square's corners."""
    if "error" in got:
        return 0.0, [got["error"]]
    lobe, lobe_lines = judge_hemisphere(check, {"sets": got["sets"]}, reference)
    corners, corner_lines = judge_points(check, {"points": got["points"]}, reference)
    return (lobe + corners) / 2.0, lobe_lines + corner_lines


def judge_sample_f(check, got, reference):
    """Lambertian.sample_f: f = rho / pi, unit directions about n with pdf > 0, and the
    estimator f (n . w) g(w) / pdf / rho with the mean of the exact integral (z-test)."""
    if "error" in got:
        return 0.0, [got["error"]]
    sets = got["sets"]
    if len(sets) != len(reference["sets"]):
        return 0.0, ["the test stopped before it tried every normal"]
    right, lines = 0, []
    asked = check.probe[2]
    for s, want in zip(sets, reference["sets"]):
        n, rho = want["normal"], want["rho"]
        s = summarize_sample_f(n, rho, s["samples"], asked["count"], asked["seed"])
        label = "Lambertian(%s).sample_f(n = %s, ...)" % (fmt(rho), fmt(n))
        problems = _bad_lines(s["directions"], "directions w_i")
        f = s.get("f")
        expected_f = [c / math.pi for c in rho]
        if not (isinstance(f, list) and all(abs(a - b) <= 1e-12 + 1e-9 * abs(b) for a, b in zip(f, expected_f))):
            problems.append("f should be rho / pi = %s, yours is %s" % (fmt(expected_f), fmt(f)))
        if s["n_bad_pdf"]:
            problems.append("%d of your pdfs are not a number above 0, for example %s: a direction you can draw "
                            "has a density above 0" % (s["n_bad_pdf"], fmt(s["bad_pdf"][0][2])))
        if not problems:
            for g, truth in G_TRUTH.items():
                for k in range(3):
                    total, squares = s["sums"][g][k]
                    mean, error, z = mean_z(total, squares, s["used"], truth)
                    if not math.isfinite(mean):
                        problems.append("the sum of f (n . w_i) g(w_i) / pdf over your %d samples is not a finite "
                                        "number for g = %s: some sample's f, pdf or direction is NaN or infinite"
                                        % (s["used"], g))
                        break
                    if abs(z) > Z_LIMIT:
                        text = ("the mean of f (n . w_i) g(w_i) / pdf over your %d samples, divided by rho, is %.5g "
                                "+- %.2g for g = %s, but the integral it estimates is %.5g (%.1f standard errors off)"
                                % (s["used"], mean, error, g, truth, abs(z)))
                        if g == "cos" and abs(mean / truth - 2.0) < 0.1:
                            text += ("\n  Hint: twice the truth: the pdf you return is (n . w_i) / (2 pi), half the "
                                     "density of cosine-weighted directions; pdf is the density you drew w_i with")
                        elif g == "cos" and abs(mean / truth - 1.5) < 0.1:
                            text += ("\n  Hint: 1.5 times the truth, as when directions drawn cosine-weighted are "
                                     "weighted as uniform ones (pdf 1 / (2 pi)): pdf must be the density of the "
                                     "directions you drew, (n . w_i) / pi for cosine-weighted ones")
                        elif g == "1" and abs(mean - 4.0 / 3.0) < 0.03:
                            text += ("\n  Hint: 4/3 of the truth, as when directions drawn cosine-weighted are "
                                     "weighted as uniform ones (pdf 1 / (2 pi)): pdf must be the density of the "
                                     "directions you drew, (n . w_i) / pi for cosine-weighted ones")
                        elif g == "1" and abs(mean - 1.0) > 0.02:
                            text += ("\n  Hint: in the white furnace (g = 1) f (n . w_i) / pdf averages rho; your "
                                     "f, pdf or directions do not agree with one another")
                        problems.append(text)
                        break
                else:
                    continue
                break
        if problems:
            lines.append("- %s: %s" % (label, "; ".join(problems)))
        else:
            right += 1
            lines.append("- %s: f = rho / pi, and f (n . w_i) / pdf averages rho (and the other tests' integrals) "
                         "within the noise" % label)
    return right / len(sets), lines


def _image_arrays(got):
    mean = np.asarray(got["mean"], dtype=np.float64)
    variance = np.asarray(got["variance"], dtype=np.float64)
    if mean.ndim != 3 or mean.shape[2] != 3 or variance.shape != mean.shape:
        raise ValueError("malformed image")
    return mean, variance


def _finite_lines(mean, variance):
    bad = ~(np.isfinite(mean) & np.isfinite(variance)).all(axis=2)
    if bad.any():
        row, col = np.argwhere(bad)[0]
        return ["%d pixels are not finite numbers, the first at column %d, row %d (row 0 at the top): a NaN or an "
                "infinity came out of your code there (a pdf of 0?)" % (int(bad.sum()), col, row)]
    return []


def judge_estimate(mean, variance, count, truth, truth_variance=None, truth_count=1, whole_variance=None):
    """(fraction, lines) of an image of per-pixel means and variances against a truth or a
    reference estimate: the whole image within Z_LIMIT standard errors per channel, at most
    PIXEL_FRACTION of the pixel channels beyond Z_PIXEL, and (against a reference) no more than
    NOISE_LIMIT times its variance.

    ``whole_variance`` (against a reference): per channel, the variance of the sum of the
    pixels of a ``count``-sample image, measured over the reference's independent renders.
    The sum of the pixels' own variances overstates it about five times on the Cornell box
    (the pixel sampler's strata and the stream's sets make pixels' errors partly cancel), which
    would hide a bias of a few per cent. The student's sum is taken to be as much overstated
    as the reference's (a noisier sampler keeps its extra noise), and never less noisy."""
    lines = _finite_lines(mean, variance)
    if lines:
        return 0.0, lines
    z, whole = image_z(mean, variance, count, truth, truth_variance, truth_count)
    if whole_variance is not None:
        reference_variance = np.asarray(truth_variance, dtype=np.float64)
        ref_whole = np.asarray(whole_variance, dtype=np.float64)
        overstated = reference_variance.sum(axis=(0, 1)) / count / np.maximum(ref_whole, 1e-300)
        own = np.maximum(variance, reference_variance).sum(axis=(0, 1)) / count / overstated
        noise = np.maximum(own, ref_whole) + ref_whole * count / truth_count
        whole = (mean - truth).sum(axis=(0, 1)) / np.sqrt(noise)
    far = np.abs(z) > Z_PIXEL
    lines = []
    ratio = None
    if truth_variance is not None:
        ratio = float(variance.sum() / max(np.asarray(truth_variance).sum(), 1e-300))
    brightness = float(mean.sum() / max(np.asarray(truth, dtype=np.float64).sum() * (mean.size / np.size(truth)), 1e-300))
    if np.any(np.abs(whole) > Z_LIMIT):
        c = int(np.argmax(np.abs(whole)))
        lines.append("your image is biased: over the whole image, channel %s is %.1f standard errors %s the truth "
                     "(the image is %.3f times as bright on average; at most %g standard errors are noise). A sampler "
                     "whose pdf is not the density of the directions it draws does this."
                     % ("RGB"[c], abs(float(whole[c])), "above" if whole[c] > 0 else "below", brightness, Z_LIMIT))
    if far.mean() > PIXEL_FRACTION:
        row, col, k = np.unravel_index(np.argmax(np.where(np.isfinite(z), np.abs(z), 1e300)), z.shape)
        lines.append("%d of %d pixel channels (%.1f%%) are more than %g standard errors from the truth (at most %g%% "
                     "may be); the furthest is channel %s at column %d, row %d (row 0 at the top): yours %.4g, the "
                     "truth %.4g" % (int(far.sum()), far.size, 100.0 * far.mean(), Z_PIXEL, 100 * PIXEL_FRACTION,
                                     "RGB"[k], col, row, mean[row, col, k],
                                     np.broadcast_to(truth, mean.shape)[row, col, k]))
    if ratio is not None and ratio > NOISE_LIMIT:
        lines.append("your image is %.1f times as noisy (variance per sample) as the reference's, more than the %g "
                     "a correct sampler comes near: the estimate is right on average but far too noisy" % (ratio, NOISE_LIMIT))
    if lines:
        return 0.0, lines
    text = ("the image agrees with the truth within the Monte Carlo error (the whole image within %.1f standard "
            "errors per channel, %d of %d pixel channels beyond %g)" % (float(np.abs(whole).max()), int(far.sum()),
                                                                        far.size, Z_PIXEL))
    if ratio is not None:
        text += "; its variance per sample is %.2f times the reference's" % ratio
        if ratio > 1.2:
            text += " (correct, but the cosine-weighted bounce would be less noisy)"
    return 1.0, [text]


def judge_furnace(check, got, reference):
    if "error" in got:
        return 0.0, ["rendering the image failed: " + got["error"]]
    mean, variance = _image_arrays(got)
    return judge_estimate(mean, variance, got["spp"], np.asarray(reference["rho"], dtype=np.float64))


def judge_image(check, got, reference):
    if "error" in got:
        return 0.0, ["rendering the image failed: " + got["error"]]
    mean, variance = _image_arrays(got)
    truth = np.asarray(reference["mean"], dtype=np.float64)
    if mean.shape != truth.shape:
        return 0.0, ["the render has shape %s; expected %s" % (mean.shape, truth.shape)]
    ref_variance = np.asarray(reference["variance"], dtype=np.float64)
    return judge_estimate(mean, variance, got["spp"], truth, ref_variance, reference["count"],
                          reference["whole_variance"])


# --- the contract: Suffern's map itself, and pdf as the density of the directions ----------
#
# The tests above judge distributions and means, which a map that ignores its sample, or a
# pdf whose errors cancel in the few averages taken, can pass. These two take inputs drawn
# when the test runs (Check.draw), so that nothing is tuned to them in advance.

MAP_EXPONENTS = (0.0, 1.0, 10.0, 100.0)
MAP_POINTS = 4              # points (x, y) drawn per exponent
MAP_ATOL = 1e-9             # per component, against the solution's hemisphere_map
SHOWN = 3                   # examples shown per kind of mistake


def draw_map_points(rng) -> dict:
    return {"points": [[rng.random(), rng.random(), e] for e in MAP_EXPONENTS for _ in range(MAP_POINTS)]}


def map_reference(points) -> dict:
    """Suffern's map at ``points``, by the solution's hemisphere_map (the grader's package)."""
    from rtfgu.sampling.maps import hemisphere_map

    return {"out": [[d.x, d.y, d.z] for d in (hemisphere_map(x, y, e) for x, y, e in points)]}


def judge_map_contract(check, got, reference):
    """hemisphere_map at points drawn for this grading, twice each: the same direction both
    times, and Suffern's (the solution's) within MAP_ATOL."""
    if "error" in got:
        return 0.0, [got["error"]]
    points, truth = reference["drawn"]["points"], reference["out"]
    first, second = got["first"], got["second"]
    if len(first) != len(points) or len(second) != len(points):
        return 0.0, ["the test stopped before it tried every point"]
    right, raised, changed, wrong = 0, [], [], []
    for (x, y, e), a, b, want in zip(points, first, second, truth):
        label = "hemisphere_map(%.17g, %.17g, %s)" % (x, y, fmt(float(e)))
        if "error" in a or "error" in b:
            raised.append("- %s: your code raised %s" % (label, a.get("error") or b.get("error")))
        elif not close(b["out"], a["out"], 0.0, 0.0):      # exactly the same (a NaN the same as a NaN)
            changed.append("- %s gave %s, and %s when called again" % (label, fmt(a["out"]), fmt(b["out"])))
        elif not close(a["out"], want, 0.0, MAP_ATOL):
            wrong.append("- %s is %s; Suffern's map gives %s" % (label, fmt(a["out"]), fmt(want)))
        else:
            right += 1
    lines = raised[:SHOWN]
    if changed:
        lines.append("%d of %d points gave another direction the second time: hemisphere_map must be a function "
                     "of (x, y, e) alone, drawing no random numbers of its own (the sampler's strata and each "
                     "pixel's sample set decide where a direction goes)" % (len(changed), len(points)))
        lines += changed[:SHOWN]
    if wrong:
        lines.append("%d of %d points are not where Suffern's map puts them, phi = 2 pi x and cos(theta) = "
                     "(1 - y)^(1 / (e + 1)): a map with the same density but another correspondence (x and y "
                     "swapped, y for 1 - y) draws other directions from the same samples than the numba and WGSL "
                     "paths do" % (len(wrong), len(points)))
        lines += wrong[:SHOWN]
    if right == len(points):
        lines.append("all %d points, each called twice, give Suffern's direction" % len(points))
    return right / len(points), lines


DENSITY_NORMALS = 2         # normals drawn per grading
DENSITY_COUNT = 16384       # directions per normal
COS_BINS = 4                # cells: cos(theta) in quarters ...
PHI_BINS = 8                # ... and phi in eighths about the normal
# In the band at the horizon (cos(theta) below 1 / COS_BINS) 1 / pdf has no finite variance for
# cosine-weighted directions; the band's cells weigh cos(theta) / pdf and compare the mean with
# their projected solid angle instead.
PDF_RTOL = 1e-6             # pdf against (n . w_i) / pi where the directions are cosine-weighted


def draw_normals(rng) -> dict:
    """Unit normals uniform on the sphere and the seed of the probe's uniform numbers."""
    normals = []
    while len(normals) < DENSITY_NORMALS:
        v = [rng.gauss(0.0, 1.0) for _ in range(3)]
        length = math.hypot(*v)
        if length > 1e-6:
            normals.append([c / length for c in v])
    return {"normals": normals, "seed": rng.randrange(1 << 31)}


def cell_moments():
    """Per cell (COS_BINS x PHI_BINS): the exact integral of the cell's weight w over the cell
    (w = 1, its solid angle; w = cos(theta) in the horizon band, its projected solid angle)
    and the integral of w^2 / p for cosine-weighted directions, p = cos(theta) / pi."""
    lo = np.arange(COS_BINS)[:, None] / COS_BINS * np.ones((1, PHI_BINS))
    hi = lo + 1.0 / COS_BINS
    dphi = 2.0 * math.pi / PHI_BINS
    band = lo == 0.0
    truth = np.where(band, (hi * hi - lo * lo) / 2.0, hi - lo) * dphi
    squares = np.where(band, math.pi * truth, math.pi * dphi * np.log(hi / np.where(band, 1.0, lo)))
    return truth, squares


def density_reference(normals, seed) -> dict:
    return {"cells": cell_moments()[0].tolist()}


def _frame(n):
    a = np.eye(3)[int(np.argmin(np.abs(n)))]
    t = np.cross(n, a)
    t /= np.linalg.norm(t)
    return t, np.cross(n, t)


def density_stats(normal, samples) -> dict:
    """The importance-weighted histogram of ``samples`` ([x, y, z, pdf] per direction) about
    the unit ``normal``: per cell the mean over all N samples of w / pdf (w = 1, or
    cos(theta) in the horizon band) for the directions in the cell, its exact value, its
    standard error (the larger of the samples' own and that of cosine-weighted directions)
    and z; the chi-square p of the directions against the cosine-weighted density; and the
    directions whose pdf is not (n . w_i) / pi. Invalid samples are listed and nothing else
    is computed."""
    n = np.asarray(normal, dtype=np.float64)
    x = np.asarray(samples, dtype=np.float64).reshape(-1, 4)
    d, pdf = x[:, :3], x[:, 3]
    count = len(x)
    finite = np.isfinite(x).all(axis=1)
    length = np.where(finite, np.linalg.norm(np.where(finite[:, None], d, 0.0), axis=1), np.nan)
    c = np.where(finite, d @ np.where(np.isfinite(n), n, 0.0), np.nan)
    bad = ~finite | ~(np.abs(length - 1.0) <= UNIT) | ~(c >= -BELOW) | ~(pdf > 0.0)
    if bad.any() or count < 2:
        return {"count": count, "bad": [[x[k].tolist(), float(c[k])] for k in np.flatnonzero(bad)[:SHOWN]],
                "n_bad": int(bad.sum())}
    c = np.clip(c, 0.0, 1.0)
    t, b = _frame(n)
    phi = np.arctan2(d @ b, d @ t) % (2.0 * math.pi)
    i = np.minimum((c * COS_BINS).astype(int), COS_BINS - 1)
    j = np.minimum((phi / (2.0 * math.pi) * PHI_BINS).astype(int), PHI_BINS - 1)
    w = np.where(i == 0, c, 1.0) / pdf
    cell = i * PHI_BINS + j
    sums = np.bincount(cell, w, COS_BINS * PHI_BINS).reshape(COS_BINS, PHI_BINS) / count
    squares = np.bincount(cell, w * w, COS_BINS * PHI_BINS).reshape(COS_BINS, PHI_BINS) / count
    truth, contract_squares = cell_moments()
    own = np.maximum(squares - sums * sums, 0.0) * count / (count - 1) / count
    contract = np.maximum(contract_squares - truth * truth, 0.0) / count
    sigma = np.sqrt(np.maximum(own, contract))
    z = (sums - truth) / sigma
    passed = np.abs(sums - truth) <= Z_LIMIT * sigma + EXACT * truth
    t_bins = np.minimum((c * c * 8).astype(int), 7)
    counts = np.bincount(t_bins * 8 + np.minimum((phi / (2.0 * math.pi) * 8).astype(int), 7), minlength=64)
    want = c / math.pi
    off = np.abs(pdf - want) > PDF_RTOL * want + 1e-12
    worst = int(np.argmax(np.abs(pdf - want) / np.maximum(want, 1e-300)))
    return {"count": count, "n_bad": 0, "estimate": sums, "truth": truth, "sigma": sigma, "z": z, "passed": passed,
            "cosine_p": chi_square_p(counts), "n_off": int(off.sum()),
            "worst_off": [d[worst].tolist(), float(c[worst]), float(pdf[worst]), float(want[worst])]}


def _cell_label(i: int, j: int) -> str:
    return "cos(theta) in [%g, %g), phi in [%g, %g) degrees" % (i / COS_BINS, (i + 1) / COS_BINS,
                                                              360.0 * j / PHI_BINS, 360.0 * (j + 1) / PHI_BINS)


def density_problems(stats) -> list:
    """What is wrong with one normal's samples (density_stats), in words; [] if nothing."""
    if stats["n_bad"]:
        return ["%d of your %d samples are not a unit direction w_i about n with a pdf above 0, for example %s"
                % (stats["n_bad"], stats["count"], "; ".join("w_i = %s (n . w_i = %.6g), pdf %s"
                                                            % (fmt(s[:3]), c, fmt(s[3])) for s, c in stats["bad"]))]
    problems = []
    failed = np.argwhere(~stats["passed"])
    if len(failed):
        order = sorted(failed.tolist(), key=lambda ij: -abs(stats["z"][ij[0], ij[1]]))
        shown = []
        for i, j in order[:SHOWN]:
            weight, exact = (("cos(theta) / (N pdf)", "projected solid angle") if i == 0
                             else ("1 / (N pdf)", "solid angle"))
            shown.append("%s: the sum of %s is %.5g, its %s %.5g (%.1f standard errors off)"
                         % (_cell_label(i, j), weight, stats["estimate"][i, j], exact, stats["truth"][i, j],
                            stats["z"][i, j]))
        problems.append("over the directions that fall in a cell of the hemisphere, the sum of 1 / (N pdf) estimates "
                        "the cell's solid angle whatever the density, if pdf is the density the directions were drawn "
                        "with; in %d of the %d cells it does not: %s" % (len(failed), COS_BINS * PHI_BINS,
                                                                        "; ".join(shown)))
    if stats["cosine_p"] >= CHI_SQUARE_ALPHA and stats["n_off"]:
        d, c, pdf, want = stats["worst_off"]
        problems.append("your directions are cosine-weighted (chi-square p = %.2g), so pdf must be their density "
                        "(n . w_i) / pi at each, but %d of %d are not; the furthest: w_i = %s, n . w_i = %.6g, "
                        "pdf %.6g instead of %.6g (%.3g times)" % (stats["cosine_p"], stats["n_off"], stats["count"], fmt(d),
                                                         c, pdf, want, pdf / want if want > 0 else math.inf))
    return problems


def judge_pdf_density(check, got, reference):
    """Lambertian.sample_f about normals drawn for this grading: valid samples; per cell of the
    hemisphere the importance-weighted sum against the cell's exact solid angle (within
    Z_LIMIT standard errors); and, where the directions are cosine-weighted, pdf = (n . w_i)
    / pi at each direction."""
    if "error" in got:
        return 0.0, [got["error"]]
    normals = reference["drawn"]["normals"]
    sets = got["sets"]
    if len(sets) != len(normals):
        return 0.0, ["the test stopped before it tried every normal"]
    right, lines = 0, []
    for s, n in zip(sets, normals):
        if len(s["samples"]) != check.probe[2]["count"]:     # the count drawn, not the answer's own
            raise ValueError("not the samples the test drew")
        stats = density_stats(n, s["samples"])
        label = "Lambertian.sample_f about n = %s (drawn for this grading), %d directions" % (fmt(n), stats["count"])
        problems = density_problems(stats)
        if problems:
            lines.append("- %s: %s" % (label, "; ".join(problems)))
            continue
        right += 1
        text = ("the sum of 1 / (N pdf) over each cell estimates its solid angle within the noise (the furthest %.1f "
                "standard errors)" % float(np.abs(stats["z"]).max()))
        if stats["cosine_p"] >= CHI_SQUARE_ALPHA:
            text += ", and pdf = (n . w_i) / pi at every direction"
        lines.append("- %s: %s" % (label, text))
    return right / len(normals), lines


# --- references (grader side, from the staff renderer) --------------------------------------

def reference_image(scene: str, width: int, height: int, spp: int, seed: int):
    """The mean and per-sample variance of ``scene`` (probes.a09.SCENES) over REFERENCE_SEEDS
    renders of ``spp`` samples on the numba path in float64, whose paths are the lecture
    layer's to rounding (tests/test_path_trace.py), from seeds the student's render does not
    use: each render's samples one at a time, as the probe takes them."""
    import rtfgu
    import rtfgu.scenes  # noqa: F401  (the probe's scene is a homework scene's)
    from rtfgu.renderer import render_passes

    from ..probes import a09 as probes

    built = probes.SCENES[scene](rtfgu)
    total = np.zeros((height, width, 3))
    variance = np.zeros((height, width, 3))
    wholes = []
    for k in range(REFERENCE_SEEDS):
        previous = np.zeros((height, width, 3))
        samples = []
        for done, image in render_passes(built, width, height, "numba", "float64", spp=spp,
                                         seed=REFERENCE_SEED0 + k, passes=spp):
            sums = image * done
            samples.append(sums - previous)
            previous = sums
        samples = np.asarray(samples)
        total += samples.sum(axis=0)
        variance += samples.var(axis=0, ddof=1)
        wholes.append(samples.mean(axis=0).sum(axis=(0, 1)))
    count = REFERENCE_SEEDS * spp
    return {"mean": (total / count).tolist(), "variance": (variance / REFERENCE_SEEDS).tolist(), "count": count,
            "whole_variance": np.var(wholes, axis=0, ddof=1).tolist()}


def _image_reference():
    return reference_image("one_bounce", IMAGE["width"], IMAGE["height"], IMAGE["spp"], IMAGE["seed"])


NORMALS = [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]
RHOS = [[0.5, 0.5, 0.5], [0.8, 0.8, 0.8]]
FURNACE_RHO = [0.5, 0.7, 0.9]


register("a09_path_tracing", [
    Check("hemisphere_map: e = 1, the cosine-weighted hemisphere (chi-square)", 2,
          ("a09", "observe_hemisphere", dict(exponents=[1], count=COUNT, seed=SEED)), kind="statistic",
          judge=judge_hemisphere, reference=lambda: {"exponents": [1], "count": COUNT}, needs=MAPS),
    Check("hemisphere_map: e = 0 (the uniform hemisphere) and e = 10 (a Phong lobe) (chi-square)", 1,
          ("a09", "observe_hemisphere", dict(exponents=[0, 10], count=COUNT, seed=SEED + 1)), kind="statistic",
          judge=judge_hemisphere, reference=lambda: {"exponents": [0, 10], "count": COUNT}, needs=MAPS),
    Check("Lambertian.sample_f: f = rho / pi, and f (n . w_i) / pdf averages rho (the estimator's mean)", 2,
          ("a09", "observe_sample_f", dict(normals=NORMALS, rhos=RHOS, count=COUNT, seed=SEED + 2)),
          kind="statistic", judge=judge_sample_f,
          reference=lambda: {"sets": [{"normal": n, "rho": r} for n, r in zip(NORMALS, RHOS)]}),
    Check("The white furnace: a diffuse sphere under a white sky is rho in every pixel (exact)", 1,
          ("a09", "observe_image", dict(scene="furnace", rho=FURNACE_RHO, **FURNACE)), kind="statistic",
          judge=judge_furnace, reference=lambda: {"rho": FURNACE_RHO}),
    Check("The Cornell box, direct light and one bounce of diffuse interreflection, against the reference", 3,
          ("a09", "observe_image", dict(scene="one_bounce", **IMAGE)), kind="statistic", judge=judge_image,
          reference=_image_reference, time_limit=IMAGE_SECONDS),
    Check("hemisphere_map is Suffern's map: a function of (x, y, e) alone, at points drawn for each grading", 1,
          ("a09", "observe_hemisphere_twice"), kind="statistic", judge=judge_map_contract, needs=MAPS,
          draw=draw_map_points, reference=map_reference),
    Check("Lambertian.sample_f: pdf is the density of its directions, about normals drawn for each grading", 2,
          ("a09", "observe_sample_directions", dict(count=DENSITY_COUNT)), kind="statistic",
          judge=judge_pdf_density, draw=draw_normals, reference=density_reference),
    # ### BEGIN HIDDEN
    Check("hemisphere_map: e = 100, and the corners of the unit square", 1,
          ("a09_hidden", "observe_lobe_and_corners", dict(count=COUNT, seed=SEED + 3)), kind="statistic",
          judge=judge_lobe_and_corners, visibility="hidden", needs=MAPS,
          reference=lambda: {"exponents": [100], "count": COUNT,
                             "points": [[x, y, e] for e in (0.0, 1.0, 1000.0) for x in (0.0, 1.0 - 2.0 ** -53)
                                        for y in (0.0, 1.0 - 2.0 ** -53)]}),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("Lambertian.sample_f: normals along y and off every axis, coloured albedos", 1,
          ("a09_hidden", "observe_sample_f_more", dict(count=COUNT, seed=SEED + 4)),
          kind="statistic", judge=judge_sample_f, visibility="hidden",
          reference=lambda: {"sets": [{"normal": [0.0, 1.0, 0.0], "rho": [0.25, 0.5, 0.75]},
                                      {"normal": [0.26726124191242440, -0.53452248382484879, 0.80178372573727319],
                                       "rho": [0.9, 0.6, 0.3]}]}),
    # ### END HIDDEN
])
