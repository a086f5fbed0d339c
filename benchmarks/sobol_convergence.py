"""The Sobol section of docs/sampling.md: RMSE against a high-spp reference of two scenes,
Jittered pixels with the independent random stream for every other draw (the default) vs
Burley's shuffled, scrambled Sobol pairs for every 2D draw (rtfgu.sampling.sobol), at a few
samples per pixel, numba float64, the same scene, size and seeds.

    python benchmarks/sobol_convergence.py [--size 32] [--seeds 8] [--reference-half 2025]

prints a Markdown table. A script, not a test: nothing is asserted, and no time is measured.

Scenes: ``cornell_box_area_light`` (PathTrace with one vertex: the direct light of the ceiling,
whose 2D draws are the pixel point and the light point) and ``cornell_box_progressive`` (the
box with a mirror and a glass sphere path traced to full depth: a 2D draw per bounce and per
light point at every vertex). Error: RMSE over every pixel and channel of the linear radiance,
the mean over ``--seeds`` seeds (± its standard error), against the mean of two references of ``--reference-half``
samples each (Jittered, a square number; seeds other than those measured); the reference's own RMSE is estimated as
half the RMSE between its two halves and printed with the table.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import rtfgu  # noqa: E402
from rtfgu.sampling.sampler import sampler_of  # noqa: E402
from rtfgu.scenes.meshes import cornell_box_area_light, cornell_box_progressive  # noqa: E402

SCENES = (("cornell_box_area_light", cornell_box_area_light),
          ("cornell_box_progressive", cornell_box_progressive))
SAMPLERS = (("Jittered + stream", rtfgu.Jittered), ("Sobol", rtfgu.Sobol))
SPP = (4, 16, 64)


def image(make, sampler, size: int, seed: int) -> np.ndarray:
    scene = make()
    scene.sampler = sampler
    return rtfgu.render(scene, size, size, "numba", "float64", seed=seed)


def rmse(a, b) -> float:
    return float(np.sqrt(np.mean((a - b) ** 2)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", type=int, default=32)
    parser.add_argument("--seeds", type=int, default=8)
    parser.add_argument("--reference-half", type=int, default=2025)
    args = parser.parse_args()
    half = sampler_of(rtfgu.Jittered, args.reference_half)
    print("%d x %d pixels, mean RMSE over %d seeds, numba float64; reference %d spp (Jittered)\n"
          % (args.size, args.size, args.seeds, 2 * args.reference_half))
    print("| scene | spp | " + " | ".join(name for name, _ in SAMPLERS) + " | Jittered / Sobol |")
    print("|---|---:|" + "---:|" * (len(SAMPLERS) + 1))
    notes = []
    for name, make in SCENES:
        first, second = (image(make, half, args.size, 1_000_000 + k) for k in range(2))
        reference = (first + second) / 2
        notes.append("%s: the reference's own RMSE about %.2e" % (name, rmse(first, second) / 2))
        for spp in SPP:
            errors, spreads = [], []
            for _, cls in SAMPLERS:
                sampler = sampler_of(cls, spp)
                per_seed = [rmse(image(make, sampler, args.size, seed), reference) for seed in range(args.seeds)]
                errors.append(np.mean(per_seed))
                spreads.append(np.std(per_seed, ddof=1) / np.sqrt(args.seeds))
            print("| %s | %d | %s | %.2f |" % (name, spp, " | ".join("%.4f ± %.4f" % c for c in zip(errors, spreads)),
                                               errors[0] / errors[1]))
            sys.stdout.flush()
    print()
    for note in notes:
        print(note)


if __name__ == "__main__":
    main()
