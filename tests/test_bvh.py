"""The lecture layer's BVH and bounding boxes: the BVH finds exactly the hit of the scene's
loop over all shapes (the same shape, the same t to the bit, the earlier shape on a tie),
its build keeps every shape once inside boxes that contain it, the binned SAH separates
clusters, and the slab test decides the boundary cases exactly."""
from __future__ import annotations

import math
import random

import pytest

from rtfgu import Disk, Float3, Plane, Ray, Sphere, Triangle
from rtfgu.accelerators import BBox, BVH
from rtfgu.accelerators.bvh import LEAF_SIZE


def loop_hit(shapes, ray):
    """Scene.intersect's loop: the last shape that reports a hit is the nearest."""
    best = -1
    for i, shape in enumerate(shapes):
        if shape.intersect_p(ray):
            best = i
    return best


def random_shapes(rng, n):
    shapes = []
    for _ in range(n):
        c = Float3(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5))
        kind = rng.random()
        if kind < 0.4:
            shapes.append(Sphere(c, rng.uniform(0.05, 0.8), Float3(1.0)))
        elif kind < 0.85:
            d = [Float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(2)]
            shapes.append(Triangle(c, c + d[0], c + d[1], Float3(1.0)))
        else:
            n = Float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
            shapes.append(Disk(c, n, rng.uniform(0.1, 1.0), Float3(1.0)))
    return shapes


def random_ray(rng):
    o = Float3(rng.uniform(-8, 8), rng.uniform(-8, 8), rng.uniform(-8, 8))
    target = Float3(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5))
    return o, target - o


@pytest.mark.parametrize("seed", range(4))
def test_the_bvh_finds_the_hit_of_the_loop_over_all_shapes(seed):
    rng = random.Random(seed)
    shapes = random_shapes(rng, 150)
    bvh = BVH(shapes)
    hits = 0
    for _ in range(400):
        o, d = random_ray(rng)
        a, b = Ray(o, d, 0.0, math.inf), Ray(o, d, 0.0, math.inf)
        want, got = loop_hit(shapes, a), bvh.intersect(b)
        assert (got, b.tmax) == (want, a.tmax)
        hits += want >= 0
    assert hits > 100   # the rays do hit things: the comparison is not of misses alone


def test_a_ray_that_starts_inside_a_box_and_a_finite_tmax_agree_with_the_loop():
    rng = random.Random(7)
    shapes = random_shapes(rng, 60)
    bvh = BVH(shapes)
    for _ in range(300):
        o = Float3(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3))
        d = Float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
        tmin, tmax = rng.choice([(0.0, math.inf), (1e-4, 2.0), (0.5, 3.0)])
        a, b = Ray(o, d, tmin, tmax), Ray(o, d, tmin, tmax)
        assert (bvh.intersect(b), b.tmax) == (loop_hit(shapes, a), a.tmax)


def test_on_a_tie_the_earlier_shape_wins_whatever_order_the_bvh_visits():
    """Coincident copies far apart in the list land in other leaves; the hit is the first copy."""
    rng = random.Random(3)
    tri = (Float3(0.0, 0.0, 0.0), Float3(1.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0))
    for place in (0, 17, 40):
        shapes = random_shapes(rng, 40)
        copies = [Triangle(*tri, Float3(1.0)) for _ in range(3)]
        shapes.insert(place, copies[0])
        shapes += copies[1:]
        shapes += [Sphere(Float3(0.25, 0.25, 0.0), 0.5, Float3(1.0)), Sphere(Float3(0.25, 0.25, 0.0), 0.5, Float3(1.0))]
        bvh = BVH(shapes)
        for o, d in (((0.25, 0.25, 5.0), (0.0, 0.0, -1.0)), ((0.25, 0.25, -5.0), (0.0, 0.0, 1.0))):
            a, b = Ray(Float3(*o), Float3(*d), 0.0, math.inf), Ray(Float3(*o), Float3(*d), 0.0, math.inf)
            want = loop_hit(shapes, a)
            got = bvh.intersect(b)
            assert (got, b.tmax) == (want, a.tmax)
    # The tie cases are real: the loop's answer is the first of equal hits.
    shapes = [Triangle(*tri, Float3(1.0)), Triangle(*tri, Float3(1.0))]
    assert loop_hit(shapes, Ray(Float3(0.25, 0.25, 1.0), Float3(0.0, 0.0, -1.0), 0.0, math.inf)) == 0


def test_every_shape_is_in_one_leaf_inside_every_box_above_it():
    shapes = random_shapes(random.Random(11), 300)
    bvh = BVH(shapes)
    seen = []
    stack = [(bvh.root, [])]
    while stack:
        node, above = stack.pop()
        for box in above:
            assert box.contains(node.bbox)
        if node.is_leaf:
            for k in range(node.first, node.first + node.count):
                i = bvh.order[k]
                seen.append(i)
                assert node.bbox.contains(shapes[i].bounds())
            assert node.count <= LEAF_SIZE
        else:
            stack += [(node.left, above + [node.bbox]), (node.right, above + [node.bbox])]
    assert sorted(seen) == list(range(len(shapes)))
    assert bvh.depth() < 40


def test_the_sah_splits_two_clusters_apart_at_the_root():
    rng = random.Random(5)
    left = [Sphere(Float3(rng.uniform(-11, -9), rng.uniform(-1, 1), rng.uniform(-1, 1)), 0.1, Float3(1.0)) for _ in range(30)]
    right = [Sphere(Float3(rng.uniform(9, 11), rng.uniform(-1, 1), rng.uniform(-1, 1)), 0.1, Float3(1.0)) for _ in range(30)]
    bvh = BVH(left + right)
    sides = [set(bvh.order[n.first:n.first + n.count]) for n in (bvh.root.left, bvh.root.right)]
    assert sorted(map(sorted, sides)) == [list(range(30)), list(range(30, 60))]


def test_equal_centroids_still_split_into_small_leaves():
    same = [Sphere(Float3(0.0), 1.0 + 0.01 * i, Float3(1.0)) for i in range(20)]
    bvh = BVH(same)
    assert all(leaf.count <= LEAF_SIZE for leaf in bvh.leaves())
    ray = Ray(Float3(0.0, 0.0, 5.0), Float3(0.0, 0.0, -1.0), 0.0, math.inf)
    assert bvh.intersect(ray) == loop_hit(same, Ray(Float3(0.0, 0.0, 5.0), Float3(0.0, 0.0, -1.0), 0.0, math.inf))


def test_an_unbounded_shape_is_refused_naming_it():
    with pytest.raises(ValueError, match=r"shapes\[1\] \(Plane\)"):
        BVH([Sphere(Float3(0.0), 1.0, Float3(1.0)), Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(1.0))])
    assert Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(1.0)).bounds() is None


def test_an_empty_bvh_misses():
    ray = Ray(Float3(0.0), Float3(1.0, 0.0, 0.0), 0.0, math.inf)
    assert BVH([]).intersect(ray) == -1 and ray.tmax == math.inf


BOX = BBox(Float3(0.0, 0.0, 0.0), Float3(1.0, 2.0, 4.0))


@pytest.mark.parametrize("origin, direction, tmin, tmax, enters", [
    ((-1.0, 1.0, 1.0), (1.0, 0.0, 0.0), 0.0, math.inf, 1.0),          # straight in through x = 0
    ((0.5, 1.0, 1.0), (1.0, 0.0, 0.0), 0.0, math.inf, 0.0),           # from inside: at tmin
    ((0.0, -1.0, 1.0), (0.0, 1.0, 0.0), 0.0, math.inf, 1.0),          # along the face x = 0
    ((1.0, -1.0, 4.0), (0.0, 1.0, 0.0), 0.0, math.inf, 1.0),          # along the edge x = 1, z = 4
    ((-0.5, 1.0, 1.0), (0.0, 1.0, 0.0), 0.0, math.inf, math.inf),     # parallel to x, outside
    ((2.0, 1.0, 1.0), (1.0, 0.0, 0.0), 0.0, math.inf, math.inf),      # pointing away
    ((-1.0, 1.0, 1.0), (1.0, 0.0, 0.0), 0.0, 0.5, math.inf),          # tmax before the box
    ((-1.0, 1.0, 1.0), (1.0, 0.0, 0.0), 0.0, 1.0, 1.0),               # tmax at the box: inside
    ((-1.0, -1.0, 1.0), (1.0, 1.0, 0.0), 0.0, math.inf, 1.0),         # through the corner edge
    ((-1.0, 3.0, 1.0), (1.0, 1.0, 0.0), 0.0, math.inf, math.inf),     # past the corner
])
def test_the_slab_test_decides_faces_edges_and_parallel_rays(origin, direction, tmin, tmax, enters):
    ray = Ray(Float3(*origin), Float3(*direction), tmin, tmax)
    assert BOX.hit(ray) == enters


def test_a_disks_box_is_tight_and_holds_its_rim():
    disk = Disk(Float3(1.0, 2.0, 3.0), Float3(0.0, 1.0, 1.0), 2.0, Float3(1.0))
    box = disk.bounds()
    assert box.p1.x - 1.0 == pytest.approx(2.0)
    assert box.p1.y - 2.0 == pytest.approx(2.0 * math.sqrt(0.5))
    n = Float3(0.0, 1.0, 1.0) * (1 / math.sqrt(2.0))
    u, v = Float3(1.0, 0.0, 0.0), Float3(0.0, n.z, -n.y)
    for k in range(64):
        a = 2 * math.pi * k / 64
        p = disk.center + u * (2.0 * math.cos(a)) + v * (2.0 * math.sin(a))
        assert box.contains(BBox(p, p))


def test_an_earlier_shape_met_later_still_wins_the_tie():
    """Two triangles in the plane z = 0 both hold the point (0.25, 0.25). Whichever the BVH
    meets first, the earlier triangle wins: met second, it is met at an equal t."""
    early = Triangle(Float3(-6.0, -1.0, 0.0), Float3(3.0, -1.0, 0.0), Float3(-6.0, 5.0, 0.0), Float3(1.0))
    late = Triangle(Float3(-0.5, 0.0, 0.0), Float3(6.0, 0.0, 0.0), Float3(-0.5, 2.0, 0.0), Float3(1.0))
    origin, direction = Float3(0.25, 0.25, 5.0), Float3(0.0, 0.0, -1.0)
    for one in (early, late):
        assert one.intersect_p(Ray(origin, direction, 0.0, math.inf))
    for shapes in ([early, late], [late, early]):
        bvh = BVH(shapes)
        for _ in range(2):
            # The order of a node's children, and of a leaf's shapes, is the build's choice.
            if bvh.root.is_leaf:
                bvh.order.reverse()
            else:
                bvh.root.left, bvh.root.right = bvh.root.right, bvh.root.left
            ray = Ray(origin, direction, 0.0, math.inf)
            assert (bvh.intersect(ray), ray.tmax) == (0, 5.0)


def test_any_order_inside_the_leaves_gives_the_loops_hit():
    rng = random.Random(9)
    shapes = random_shapes(rng, 80)
    copies = [Sphere(Float3(0.0), 1.0, Float3(1.0)) for _ in range(6)]
    shapes = copies[:3] + shapes + copies[3:]
    bvh = BVH(shapes)
    rays = [random_ray(rng) for _ in range(100)] + [(Float3(0.0, 0.0, 9.0), Float3(0.0, 0.0, -1.0))]
    for _ in range(5):
        for leaf in bvh.leaves():
            part = bvh.order[leaf.first:leaf.first + leaf.count]
            rng.shuffle(part)
            bvh.order[leaf.first:leaf.first + leaf.count] = part
        for o, d in rays:
            a, b = Ray(o, d, 0.0, math.inf), Ray(o, d, 0.0, math.inf)
            assert (bvh.intersect(b), b.tmax) == (loop_hit(shapes, a), a.tmax)


def test_the_bvh_over_the_bunny_finds_the_loops_hits():
    """A real mesh: 3674 triangles sharing edges and vertices."""
    import rtfgu
    from rtfgu.obj import mesh_path

    triangles = rtfgu.load_obj(mesh_path("bunny.obj")).triangles()
    bvh = BVH(triangles)
    assert bvh.depth() < 30
    rng = random.Random(1)
    box = bvh.root.bbox
    hits = 0
    for _ in range(60):
        o = Float3(*(rng.uniform(box.p0[a] - 0.1, box.p1[a] + 0.1) for a in range(3)))
        target = Float3(*(rng.uniform(box.p0[a], box.p1[a]) for a in range(3)))
        a, b = Ray(o, target - o, 0.0, math.inf), Ray(o, target - o, 0.0, math.inf)
        want = loop_hit(triangles, a)
        assert (bvh.intersect(b), b.tmax) == (want, a.tmax)
        hits += want >= 0
    assert hits > 20
