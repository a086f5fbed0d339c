"""Statistical judging (grader side and in the student checker): a chi-square test of binned
samples and z-tests of Monte Carlo means against a truth or a reference estimate.

A Monte Carlo answer is right when it differs from the truth by no more than its noise
explains. Each test here says so with a threshold in standard errors (or a p-value), chosen
so that a correct submission fails far less often than once in 10^4 gradings, while a bias
of a few per cent over an image is many standard errors away. numpy only, and nothing of the
renderer: judging never loads student code.
"""
from __future__ import annotations

import math

import numpy as np

# A chi-square test fails below this p-value (a correct sampler: once in 10^4 gradings).
CHI_SQUARE_ALPHA = 1e-4
# A mean over many samples fails beyond this many standard errors of the truth.
Z_LIMIT = 5.0
# An image fails when more than this fraction of its pixel channels are beyond Z_PIXEL.
Z_PIXEL = 5.0
PIXEL_FRACTION = 0.01
# Equal up to rounding where neither side has any noise.
EXACT = 1e-9


def chi_square_p(counts) -> float:
    """The p-value of Pearson's statistic for ``counts`` (any shape) that should be equal,
    by the Wilson-Hilferty approximation of the chi-square distribution (good to a few per
    cent of p at the 63 degrees of freedom used here, far finer than the threshold needs)."""
    observed = np.asarray(counts, dtype=np.float64).ravel()
    total = observed.sum()
    if observed.size < 2 or total <= 0:
        return 0.0
    expected = total / observed.size
    statistic = float(np.sum((observed - expected) ** 2) / expected)
    k = observed.size - 1
    z = ((statistic / k) ** (1.0 / 3.0) - (1.0 - 2.0 / (9.0 * k))) / float(np.sqrt(2.0 / (9.0 * k)))
    return 0.5 * math.erfc(z / float(np.sqrt(2.0)))


def worst_cell(counts) -> tuple:
    """(index, observed, expected) of the cell furthest from the expected count."""
    observed = np.asarray(counts, dtype=np.float64)
    expected = observed.sum() / observed.size
    index = np.unravel_index(np.argmax(np.abs(observed - expected)), observed.shape)
    return tuple(int(i) for i in index), int(observed[index]), expected


def mean_z(total: float, squares: float, count: int, truth: float) -> tuple:
    """(mean, standard error, z) of ``count`` samples given their sum and sum of squares,
    against ``truth``; z is 0 or infinity where the samples have no spread, and infinity where
    a sum is not a finite number (a NaN sample makes both NaN, and NaN is beyond no limit) or
    there are no samples."""
    if not (math.isfinite(total) and math.isfinite(squares)) or count < 1:
        return math.nan, math.nan, math.inf
    mean = total / count
    variance = max(squares / count - mean * mean, 0.0) * count / max(count - 1, 1)
    error = float(np.sqrt(variance / count))
    if error <= EXACT * max(1.0, abs(truth)):
        z = 0.0 if abs(mean - truth) <= EXACT * max(1.0, abs(truth)) else math.inf
    else:
        z = (mean - truth) / error
    return mean, error, z


def image_z(mean, variance, count: int, truth, truth_variance=None, truth_count: int = 1):
    """Per pixel channel, z = (mean - truth) / sqrt(variance / count + truth_variance /
    truth_count) for an image of per-pixel means and sample variances against a truth (exact:
    no variance) or a reference estimate; and per channel the z of the whole image's sum.
    Where neither side has any spread, z is 0 if the two agree to rounding, else infinity.

    Against a reference, a pixel's sample variance is at least the reference's per-sample
    variance (``truth_variance``, from far more samples): path tracing's samples are heavy
    tailed, and 64 of them often miss the rare bright paths, which makes both their mean and
    their variance small. Without this floor a correct image has 2-5 % of its pixel channels
    beyond 5 standard errors; with it none were in 40 renders (docs/grading.md)."""
    mean = np.asarray(mean, dtype=np.float64)
    truth = np.broadcast_to(np.asarray(truth, dtype=np.float64), mean.shape)
    variance = np.asarray(variance, dtype=np.float64)
    if truth_variance is not None:
        variance = np.maximum(variance, np.asarray(truth_variance, dtype=np.float64))
    noise = variance / count
    if truth_variance is not None:
        noise = noise + np.asarray(truth_variance, dtype=np.float64) / truth_count
    difference = mean - truth
    exact = noise <= (EXACT * np.maximum(1.0, np.abs(truth))) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        z = np.where(exact, np.where(np.abs(difference) <= EXACT * np.maximum(1.0, np.abs(truth)), 0.0, np.inf),
                     difference / np.sqrt(noise))
        axes = tuple(range(mean.ndim - 1))
        total_noise = noise.sum(axis=axes)
        whole = np.where(total_noise > 0, difference.sum(axis=axes) / np.sqrt(total_noise),
                         np.where(np.abs(difference).max(axis=axes) <= EXACT, 0.0, np.inf))
    return z, whole
