"""The plot of docs/bench.md: speed against error (benchmarks/bench.py calls
``speed_error_plot``). Both axes are logarithmic; an error of exactly zero has no place on a
log axis, so it is drawn at a floor below the smallest non-zero error and that tick is
labelled "exact" (left) or "0" (right)."""
from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

SCENE_MARKERS = ["o", "s", "^", "D", "v", "P", "X"]
FORMULA_MARKERS = {"slide": "o", "robust": "s", "built-in": "D"}


def _floor(values, default):
    """A power of ten one decade below the smallest positive value."""
    positive = [v for v in values if v > 0 and math.isfinite(v)]
    if not positive:
        return default
    return 10.0 ** (math.floor(math.log10(min(positive))) - 1)


def _colours(labels):
    cmap = plt.get_cmap("tab10")
    return {label: cmap(i % 10) for i, label in enumerate(labels)}


def _mark_floor(ax, floor, text):
    ax.axvline(floor, color="0.8", linestyle=":", zorder=0)
    high = ax.get_xlim()[1]
    ticks = [t for t in ax.get_xticks() if floor * 2.5 < t <= high]
    ax.set_xticks([floor] + ticks)
    ax.set_xticklabels([text] + ["$10^{%d}$" % round(math.log10(t)) for t in ticks])


def speed_error_plot(rows, hard_points, title, path):
    """rows: benchmarks.bench.Row (is_path rows with times are drawn); hard_points:
    hardcases_report.speed_error_points(); writes the PNG at ``path``."""
    rows = [r for r in rows if r.is_path and r.times]
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5.6),
                                      gridspec_kw={"width_ratios": [3, 2]})

    # Left: every scene x path; colour = path, marker = scene.
    scenes = list(dict.fromkeys(r.scene for r in rows))
    labels = list(dict.fromkeys(r.label for r in rows))
    colour = _colours(labels)
    floor = _floor([r.rmse for r in rows], 1e-12)
    for r in rows:
        x = r.rmse if r.rmse > 0 else floor
        left.scatter(x, r.rays_per_s, color=colour[r.label], edgecolor="black", linewidth=0.4,
                     marker=SCENE_MARKERS[scenes.index(r.scene) % len(SCENE_MARKERS)], s=55,
                     zorder=3)
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_xlim(floor / 3, None)
    _mark_floor(left, floor, "exact")
    left.set_xlabel("RMSE against the float64 reference image (before gamma)")
    left.set_ylabel("rays per second (primary + shadow + secondary)")
    left.set_title("Scenes: speed against image error")
    left.grid(True, which="major", alpha=0.3)
    handles = [plt.Line2D([], [], linestyle="", marker="o", color=colour[label],
                          markeredgecolor="black", label=label) for label in labels]
    handles += [plt.Line2D([], [], linestyle="", marker=SCENE_MARKERS[i % len(SCENE_MARKERS)],
                           color="white", markeredgecolor="black", label=name)
                for i, name in enumerate(scenes)]
    # Below the axes, so that no point hides behind it.
    left.legend(handles=handles, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13),
                ncol=3, frameon=False)

    # Right: the hard-case batch evaluators; colour = path and precision, marker = formula.
    if hard_points:
        keys = list(dict.fromkeys("%s %s" % (p["path"], p["precision"]) for p in hard_points))
        colour = _colours(keys)
        hfloor = 0.3  # wrong decisions are counts: 0 is drawn at 0.3
        for i, p in enumerate(hard_points):
            key = "%s %s" % (p["path"], p["precision"])
            x = p["wrong"] if p["wrong"] > 0 else hfloor
            right.scatter(x, p["rays_per_second"], color=colour[key], edgecolor="black",
                          linewidth=0.4, marker=FORMULA_MARKERS.get(p["formula"], "o"), s=60,
                          zorder=3)
            right.annotate("%s %s" % (key, p["formula"]), (x, p["rays_per_second"]),
                           textcoords="offset points", fontsize=7,
                           xytext=(6, 4 if i % 2 else -11))  # neighbours' labels alternate
        right.set_xscale("log")
        right.set_yscale("log")
        right.set_xlim(hfloor / 2, max(p["wrong"] for p in hard_points) * 4 + 1)
        _mark_floor(right, hfloor, "0")
        handles = [plt.Line2D([], [], linestyle="", marker=m, color="white",
                              markeredgecolor="black", label=f)
                   for f, m in FORMULA_MARKERS.items() if f != "built-in"]
        right.legend(handles=handles, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13),
                     ncol=2, frameon=False)
    else:
        right.text(0.5, 0.5, "hard cases not measured", ha="center", va="center",
                   transform=right.transAxes)
    right.set_xlabel("wrong hit/miss decisions, all hard-case families")
    right.set_ylabel("rays per second (batch evaluator)")
    right.set_title("Hard cases: speed against wrong decisions")
    right.grid(True, which="major", alpha=0.3)

    fig.suptitle("rtfgu speed against error on %s" % title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
