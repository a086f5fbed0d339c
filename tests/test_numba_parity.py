"""The numba path against the lecture layer on every homework scene.

float64: the kernels do the lecture's operations in the lecture's order, so the images agree
to 1e-9 per channel before gamma and are identical after ``to_8bit``. A scene with a
sampler is rendered at 4 samples per pixel: the random stream picks the same samples.
float32: at least 99.9 % of the 8-bit channels are within 1/255 of the reference, and every
channel further off lies on a silhouette. A pixel is on a silhouette when its 3x3
neighbourhood in the reference contains a different *path signature*: the sequence of
nearest shapes along the pixel's path together with the shapes that block its shadow rays.
So a silhouette is an edge of a shape seen from the eye, through a mirror or a refraction,
or from a light (a shadow edge): there the two precisions may rightly pick different shapes.
"""
from __future__ import annotations

import numpy as np
import pytest

from benchmark_scripts import benchmark_script
from rtfgu.image import to_8bit
from rtfgu.renderer import lens_sample, pixel_sampler, render, trace
from rtfgu.sampling import concentric_map
from rtfgu.scenes import SCENES

SIZE = 40  # the longer side; the other keeps the homework's aspect
SAMPLED_SPP = 4


def spp_of(name):
    """The scene's test_spp if it has one (a path-traced scene), else 4 for a scene with a
    sampler, None (its one centre sample) for the others."""
    if SCENES[name].test_spp:
        return SCENES[name].test_spp
    return SAMPLED_SPP if SCENES[name]().sampler is not None else None


def test_size(name):
    w, h = SCENES[name].size
    scale = min(SIZE, SCENES[name].test_side or SIZE) / max(w, h)
    return max(1, round(w * scale)), max(1, round(h * scale))


test_size.__test__ = False


def reference_signatures(scene, width, height, spp=None):
    """The path signature of every pixel, from the lecture layer itself: each shape's
    intersect_p and the scene's intersect are wrapped to log which shape a closest-hit query
    ends on and which shape stops a shadow ray (in_shadow returns at its first hit). With a
    sampler, a pixel's signature is that of all its samples' paths."""
    log = []
    for i, shape in enumerate(scene.shapes):
        def logged(ray, _inner=shape.intersect_p, _i=i):
            hit = _inner(ray)
            if hit:
                log.append(("hit", _i))
            return hit
        shape.intersect_p = logged
    inner_intersect = scene.intersect

    def intersect(ray, hit):
        start = len(log)
        found = inner_intersect(ray, hit)
        nearest = log[-1][1] if len(log) > start else None
        del log[start:]
        log.append(("nearest", nearest))
        return found
    scene.intersect = intersect

    sampler = pixel_sampler(scene, spp)
    signatures = np.empty((height, width), dtype=object)
    for iy in range(height):
        for ix in range(width):
            pixel = (height - 1 - iy) * width + ix
            log.clear()
            for s in range(1 if sampler is None else sampler.num_samples):
                sp = (0.5, 0.5) if sampler is None else sampler.sample_unit_square(pixel, s)
                sx = 2 * (ix + sp[0]) / width - 1
                sy = 2 * (iy + sp[1]) / height - 1
                # the sample's own random numbers (seed 0, as render's): a stochastic
                # tracer follows the path the image took
                if scene.camera.uses_lens:
                    lens = concentric_map(*lens_sample(sampler, pixel, s, 0))
                    trace(scene, scene.camera.gen_ray(sx, sy, lens), (pixel, s, 0))
                else:
                    trace(scene, scene.camera.gen_ray(sx, sy), (pixel, s, 0))
            signatures[height - 1 - iy, ix] = tuple(log)
    return signatures


def silhouette_mask(signatures):
    """True where the 3x3 neighbourhood holds a signature different from the pixel's."""
    height, width = signatures.shape
    mask = np.zeros((height, width), dtype=bool)
    for y in range(height):
        for x in range(width):
            own = signatures[y, x]
            for dy in (-1, 0, 1):
                for dx in (-1, 0, 1):
                    yy, xx = y + dy, x + dx
                    if 0 <= yy < height and 0 <= xx < width and signatures[yy, xx] != own:
                        mask[y, x] = True
    return mask


_references = {}


def reference(name):
    if name not in _references:
        width, height = test_size(name)
        _references[name] = render(SCENES[name](), width, height, backend="reference",
                                   spp=spp_of(name))
    return _references[name]


@pytest.mark.parametrize("formula", ["slide", "robust"])
@pytest.mark.parametrize("name", list(SCENES))
def test_float64_matches_reference(name, formula):
    """Both sphere formulas: the slide's (the reference's own) and Ray Tracing Gems ch. 7,
    whose roots differ from the slide's in the last bits only, in float64."""
    width, height = test_size(name)
    ref = reference(name)
    image = render(SCENES[name](), width, height, backend="numba", precision="float64",
                   formula=formula, spp=spp_of(name))
    assert image.shape == ref.shape
    assert np.abs(image - ref).max() <= 1e-9
    assert np.array_equal(to_8bit(image), to_8bit(ref))


@pytest.mark.parametrize("name", list(SCENES))
def test_float32_matches_reference_off_silhouettes(name):
    width, height = test_size(name)
    ref = reference(name)
    image = render(SCENES[name](), width, height, backend="numba", precision="float32",
                   spp=spp_of(name))
    diff = np.abs(to_8bit(image).astype(int) - to_8bit(ref).astype(int))
    far = diff > 1
    assert far.mean() <= 0.001, "%d of %d channels differ by more than 1/255" % (far.sum(), far.size)
    if far.any():
        on_edge = silhouette_mask(reference_signatures(SCENES[name](), width, height, spp_of(name)))
        off = np.argwhere(far.any(axis=2) & ~on_edge)
        assert len(off) == 0, "pixels off by more than 1/255 away from any silhouette: %s" % off[:10]


def test_silhouette_mask_marks_the_edge_of_a_sphere():
    """The signature map of the lecture-01 scene changes exactly along the shapes' outlines."""
    name = "lecture01_flat_colors"
    width, height = test_size(name)
    signatures = reference_signatures(SCENES[name](), width, height)
    mask = silhouette_mask(signatures)
    # Nearest-shape ids as the image shows them: each flat colour is one shape.
    ref8 = to_8bit(reference(name))
    colours = {tuple(c) for c in ref8.reshape(-1, 3)}
    assert len({s for s in signatures.ravel()}) == len(colours)
    assert 0 < mask.mean() < 0.5
    # Every pixel whose 4-neighbour has another colour is on the mask.
    edge = np.zeros(mask.shape, dtype=bool)
    edge[:, :-1] |= np.any(ref8[:, :-1] != ref8[:, 1:], axis=2)
    edge[:-1, :] |= np.any(ref8[:-1, :] != ref8[1:, :], axis=2)
    assert mask[edge].all()


def test_float32_runs_in_float32():
    """The ray-direction image in float32 is what numpy computes in float32 with the
    lecture's operations (PinholeCamera.gen_ray, normalize as v * (1 / |v|), d * 0.5 + 0.5),
    bit for bit, and it differs from the float64 image."""
    name = "default_ray_directions"
    scene = SCENES[name]()
    width, height = 24, 24
    image32 = render(scene, width, height, backend="numba", precision="float32")
    image64 = render(scene, width, height, backend="numba", precision="float64")
    f = np.float32
    cam = scene.camera
    ix = np.arange(width, dtype=f)[None, :]
    iy = np.arange(height, dtype=f)[:, None]
    sx = f(2) * (ix + f(0.5)) / f(width) - f(1)
    sy = f(2) * (iy + f(0.5)) / f(height) - f(1)
    u = sx * f(cam.aspect) * f(0.5)
    w = sy * f(0.5)
    q = [(f(b1) * u + f(b2) * w) + f(v) * f(cam.d)
         for b1, b2, v in zip(cam.b1, cam.b2, cam.v)]
    q = [np.broadcast_to(c, (height, width)) for c in q]
    inv = f(1) / np.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2])
    expected = np.stack([c * inv * f(0.5) + f(0.5) for c in q], axis=2)[::-1]
    assert expected.dtype == np.float32
    assert np.array_equal(image32, expected.astype(np.float64))
    assert not np.array_equal(image32, image64)
    assert np.abs(image32 - image64).max() < 1e-6


def _benchmark_scene(name):
    """A scene of benchmarks/scenes.py."""
    return getattr(benchmark_script("scenes"), name)()


def test_tile_culling_loses_no_sphere():
    """64 overlapping spheres: each tile of primary rays tests only the spheres in its cone
    (rtfgu.kernels.culling), and the image is still the lecture layer's: bit for bit with
    the slide formula, within 1e-9 and the same 8-bit colours with the robust one."""
    scene = _benchmark_scene("random_spheres_64")
    width = height = 48
    ref = render(scene, width, height, backend="reference")
    assert len({tuple(c) for c in to_8bit(ref).reshape(-1, 3)}) > 20  # many spheres show
    slide = render(scene, width, height, backend="numba", precision="float64", formula="slide")
    assert np.array_equal(slide, ref)
    robust = render(scene, width, height, backend="numba", precision="float64", formula="robust")
    assert np.abs(robust - ref).max() <= 1e-9
    assert np.array_equal(to_8bit(robust), to_8bit(ref))
