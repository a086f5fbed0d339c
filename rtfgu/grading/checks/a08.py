"""a08: bounding boxes and the BVH (Suffern ch. 19, "Bounding Boxes", and ch. 22; Williams et
al. 2005's slab test, widened as in PBRT-v4 section 6.1.2; PBRT-v4 section 7.3's traversal).
The probes are in rtfgu/grading/probes/a08.py (visible) and a08_hidden.py; the box hints
compare with the known mistakes of rtfgu.grading.mistakes.slab, the BVH hints compare the
student's hit with the reference hit, and the traversal test judges what the traversal costs
(shape and box tests per ray, counted in the child) against the reference traversal of the
same tree, and whether it skips every node its own box test rejects."""
from __future__ import annotations

import math

from . import Check, known_mistake_hint, register

BOX = ("accelerators/bbox.py",)

NO_SWAP = ("with a negative direction component the ray meets p1[a] before p0[a], so t_near = (p0[a] - o[a]) / w[a] "
           "is the larger of the two: swap t_near and t_far when t_near > t_far")
IGNORES_TMAX = ("your box test looks beyond ray.tmax: start with t1 = ray.tmax, not infinity, so that a box the ray "
                "enters after tmax is a miss (math.inf)")
IGNORES_TMIN = ("start with t0 = ray.tmin: a ray that starts inside the box enters it at tmin, and a box behind the "
                "ray (every t < tmin) is a miss")
EXIT = ("you returned where the ray leaves the box; BBox.hit returns where it enters, t0, the largest of tmin and "
        "the t_near of the three axes")
ZERO = ("where a direction component is 0 the ray never crosses that slab: it is inside it for every t when "
        "p0[a] <= o[a] <= p1[a] and the box is missed otherwise; do not skip the axis without looking at o[a]")
OPEN = ("the box and [tmin, tmax] are closed: a ray along a face, through an edge or a corner, or with tmax "
        "exactly where it enters, hits; return math.inf only when t0 > t1 (not >=), or o[a] < p0[a] or o[a] > p1[a]")
NO_WIDEN = ("this ray touches the box exactly, where it enters one slab and leaves another, and rounding puts t_near a "
            "hair after t_far: multiply t_far by WIDEN (1 + 2 gamma_3, PBRT-v4 section 6.1.2) before comparing")

BOX_HINTS = (("no_swap", NO_SWAP), ("ignores_tmax", IGNORES_TMAX), ("ignores_tmin", IGNORES_TMIN), ("exit", EXIT),
             ("zero_skipped", ZERO), ("open_box", OPEN), ("no_widen", NO_WIDEN))


def _same(got, want) -> bool:
    if not isinstance(got, (int, float)) or isinstance(got, bool) or not isinstance(want, (int, float)):
        return False
    if math.isinf(want) or math.isinf(got):
        return got == want
    return abs(got - want) <= 1e-9 + 1e-6 * abs(want)


def hint_box(inputs, want, got):
    """Names the known mistake (rtfgu.grading.mistakes.slab) whose t the student's is."""
    if not _same(got.get("ray.tmin"), inputs["tmin"]) or not _same(got.get("ray.tmax"), inputs["tmax"]):
        return "BBox.hit must not change the ray: it only says where the ray enters the box"
    return known_mistake_hint(BOX_HINTS, inputs, want, got, "t", _same)


def hint_traversal(inputs, want, got):
    """Compares the student's hit (shape number, t) with the reference hit."""
    shape, t = got.get("shape"), got.get("ray.tmax")
    best, best_t = want["shape"], want["ray.tmax"]
    if not isinstance(shape, int) or not isinstance(t, float):
        return None
    if best >= 0 and shape >= 0 and t > best_t:
        return ("your hit (shape %d at t = %.6g) is not the nearest (shape %d at t = %.6g), so the node that holds "
                "the nearest was never visited: either the traversal stopped at the first hit found (keep taking nodes "
                "off the stack until it is empty, and skip only a node whose box the ray enters beyond ray.tmax) or "
                "BBox.hit missed that node's box (its own tests say whether)" % (shape, t, best, best_t))
    if best >= 0 and shape > best and t == best_t:
        return ("shapes %d and %d are both hit at t = %.6g, and the earlier one, %d, wins (the scene's loop keeps the "
                "first of equal hits): a shape with a smaller number than the best so far must be tested with "
                "ray.tmax raised to math.nextafter(ray.tmax, math.inf), so that an equal t counts, and tmax put "
                "back if it misses" % (best, shape, t, best))
    if best >= 0 and shape < 0:
        return ("your traversal found nothing, but the ray hits shape %d at t = %.6g: it skipped a node that the ray "
                "enters before ray.tmax (check BBox.hit and the test that skips a node) or did not test every "
                "shape of a leaf, self.order[first:first + count]" % (best, best_t))
    if best < 0 and shape < 0 and t != best_t:
        return "on a miss BVH.intersect must leave ray.tmax as it was"
    if best >= 0 and shape >= 0 and t < best_t:
        return ("your t is less than the nearest hit's: a shape tested with ray.tmax raised (the tie rule) must get "
                "the old tmax back when it misses, and ray.tmin is the start of every shape's test")
    return None


# The traversal test, per scene: every shape test lies in a leaf whose box the traversal tested
# for that ray and below no node its latest box test rejected; the shape tests over the
# scene's rays at most COST_FACTOR times the reference traversal's on the same tree plus
# COST_SLACK per ray, and the box tests at most BOX_FACTOR times the reference's plus
# BOX_SLACK per ray (a traversal may test a node's box once or twice, never without bound).
COST_FACTOR, COST_SLACK = 2.0, 2
BOX_FACTOR, BOX_SLACK = 2.0, 4
SKIPPED = ("tested shapes below a node whose box test had rejected it (BBox.hit gave math.inf, a miss, or a t "
           "beyond ray.tmax): a rejected node is skipped with everything under it. Test a node's box again when "
           "it is taken off the stack and skip it when the ray misses the box or enters it beyond ray.tmax (the box "
           "tests that order the children only decide which is pushed last)")
UNGUARDED = ("tested shapes of a leaf whose box it never tested: a BVH earns its keep only when the traversal "
             "tests a node's box first and visits the node only if the ray enters it before ray.tmax; testing "
             "every shape, or every node, is the cost a BVH is there to avoid")
TOO_MANY = ("skip every node whose box the ray enters beyond ray.tmax, and push the farther child first so that "
            "the nearer one is taken next: a hit found early shrinks ray.tmax and the boxes behind it are skipped")


def judge_traversal(check, got, want):
    """(fraction, lines): per scene of the traversal test, whether the student's BVH.intersect
    is led by its own box tests (no shape tested in a leaf whose box it did not test, or below
    a node it rejected) and costs about what the reference traversal of the same tree costs.
    The answers themselves are judged by the other BVH tests."""
    if "error" in got:
        return 0.0, [got["error"]]
    cases_got, cases_want = got.get("cases"), want["cases"]
    if not isinstance(cases_got, list) or len(cases_got) != len(cases_want):
        return 0.0, ["the test stopped before it tried every ray (%s)" % got.get("stopped", "no reason given")]
    scenes = []
    for g, w in zip(cases_got, cases_want):
        scene = w["in"]["scene"]
        if not scenes or scenes[-1][0] != scene:
            scenes.append((scene, []))
        scenes[-1][1].append((g, w))
    passed, lines = 0, []
    for scene, pairs in scenes:
        raised = [(w["label"], g["error"]) for g, w in pairs if "error" in g]
        if raised:
            lines.append("- the %s scene: your code raised %s on %d of its %d rays (the first: %s)"
                         % (scene, raised[0][1], len(raised), len(pairs), raised[0][0]))
            continue
        outs = [(g["out"], w["out"], w["label"]) for g, w in pairs]
        shapes = sum(int(o["shape tests"]) for o, _, _ in outs)
        boxes = sum(int(o["box tests"]) for o, _, _ in outs)
        ref_shapes = sum(r["shape tests"] for _, r, _ in outs)
        ref_boxes = sum(r["box tests"] for _, r, _ in outs)
        rays = len(outs)
        problems = []
        for key, text in (("tested in a leaf whose box was not tested", UNGUARDED),
                          ("tested below a rejected box", SKIPPED)):
            found = [(label, o[key]) for o, _, label in outs if o[key]]
            if found:
                problems.append("on %d of its %d rays your traversal %s. The first: %s, shapes %s" % (
                    len(found), rays, text, found[0][0], ", ".join(str(s) for s in found[0][1])))
        blind = [label for o, r, label in outs if r["shape"] >= 0 and o["shape tests"] == 0 and o["box tests"] == 0]
        if blind:
            problems.append("on %d rays that hit a shape your traversal tested no box and no shape (the first: %s)"
                            % (len(blind), blind[0]))
        if shapes > COST_FACTOR * ref_shapes + COST_SLACK * rays:
            problems.append("your traversal made %d shape tests over its %d rays (%.1f per ray); the reference "
                            "traversal of the same tree makes %d: %s" % (shapes, rays, shapes / rays, ref_shapes, TOO_MANY))
        if boxes > BOX_FACTOR * ref_boxes + BOX_SLACK * rays:
            problems.append("your traversal made %d box tests over its %d rays; the reference traversal makes %d: "
                            "test each node's box at most twice (to order it, and when it is taken off the stack)"
                            % (boxes, rays, ref_boxes))
        if problems:
            lines.append("- the %s scene: %s" % (scene, "\n  ".join(problems)))
        else:
            passed += 1
            lines.append("- the %s scene: %d shape and %d box tests over %d rays (the reference: %d and %d)"
                         % (scene, shapes, boxes, rays, ref_shapes, ref_boxes))
    return passed / len(scenes), lines


def hint_box_shape(inputs, want, got):
    """The box shape: from inside the ray leaves at t1; otherwise a03's interval hints."""
    from .a03 import _interval_hint

    o, p0, p1 = inputs["o"], (-1.0, -0.5, -2.0), (1.0, 0.5, -1.0)
    inside = all(p0[a] < o[a] < p1[a] for a in range(3))
    if inside and want["returned"] is True and got.get("returned") is not True:
        return ("this ray starts inside the box: t0 < tmin, so it meets the box where it leaves, at t1 (the "
                "smallest t_far)")
    return _interval_hint(inputs, want, got)


register("a08_bvh", [
    Check("BBox.hit: rays that enter the box, and where", 1, ("a08", "observe_box_enter"),
          hint=hint_box, known="slab", needs=BOX),
    Check("BBox.hit: negative direction components (t_near and t_far swap)", 1, ("a08", "observe_box_negative"),
          hint=hint_box, known="slab", needs=BOX),
    Check("BBox.hit: misses and the ray's interval [tmin, tmax]", 1, ("a08", "observe_box_interval"),
          hint=hint_box, known="slab", needs=BOX),
    Check("BBox.hit: direction components of 0 (a ray parallel to a slab)", 1, ("a08", "observe_box_zero"),
          hint=hint_box, known="slab", needs=BOX),
    Check("BVH.intersect: the nearest shape of a scene and its t", 2, ("a08", "observe_bvh_nearest"),
          hint=hint_traversal),
    Check("BVH.intersect: misses leave ray.tmax alone; tmin and tmax; an empty BVH", 1,
          ("a08", "observe_bvh_misses_and_interval"), hint=hint_traversal),
    Check("BVH.intersect: the nearest hit, not the first one found", 2, ("a08", "observe_bvh_nearest_not_first"),
          hint=hint_traversal),
    Check("BVH.intersect: two shapes hit at the same t: the earlier wins, in any visiting order", 1,
          ("a08", "observe_bvh_tie"), hint=hint_traversal),
    # ### BEGIN HIDDEN
    Check("BBox.hit: faces, edges, corners, and boxes of zero thickness", 1,
          ("a08_hidden", "observe_box_edges_and_flat"), visibility="hidden", hint=hint_box, known="slab", needs=BOX),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("BBox.hit: from the box's boundary, and where rounding decides (t_far widened)", 1,
          ("a08_hidden", "observe_box_boundary_and_rounding"), visibility="hidden", hint=hint_box, known="slab",
          needs=BOX),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("BVH.intersect: copies far apart in the list: the first copy wins, in any visiting order", 1,
          ("a08_hidden", "observe_bvh_ties"), visibility="hidden", hint=hint_traversal),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("BVH.intersect: a random scene of 120 shapes, 150 rays", 1, ("a08_hidden", "observe_bvh_random"),
          visibility="hidden", hint=hint_traversal),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("BVH.intersect: the traversal is led by its box tests, at about the reference tree's cost", 2,
          ("a08_hidden", "observe_traversal"), visibility="hidden", judge=judge_traversal),
    # ### END HIDDEN
    Check("Box.intersect_p: Suffern's box, hit from outside and from inside, misses and the interval", 2,
          ("a08", "observe_box"), hint=hint_box_shape, needs=("shapes/box.py",)),
])
