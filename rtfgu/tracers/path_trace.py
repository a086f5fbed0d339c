"""PathTrace: progressive Monte Carlo path tracing (Suffern ch. 26, "Global Illumination";
02562 worksheet 7, "Progressive path tracing").

Every sample of a pixel is one path, and the image is the mean over the samples. At each
vertex the material's ``path_shade`` (rtfgu/materials) says what the path gains there and
how it goes on (a PathVertex): a Matte adds the light of every light source, reflected by
f_r = kd cd / pi (next-event estimation, 02562 worksheet 5: a point or directional light as
in the ray-cast tracers, an AreaLight through one point of it drawn by area, each unless
shadowed), then continues along the direction ``Lambertian.sample_f`` draws, the throughput
multiplied by f_r (n . w_i) / pdf; a GlossyReflector picks its diffuse part or its lobe; a
mirror and a refraction continue along their ray, a Dielectric by Fresnel's choice; a flat
colour ends the path showing its colour.

Russian roulette (Arvo and Kirk 1990; worksheet 7) ends paths that carry little: from the
vertex at depth ROULETTE_DEPTH on, a path whose throughput's largest component q is below 1
goes on with probability q and its throughput is divided by q (PBRT-v4's PathIntegrator:
from the second vertex, on the throughput). The estimate stays unbiased; a path of albedo-1
surfaces is never ended (no variance added to a white furnace), and the first bounce, where
most of the indirect light is, is always followed. (Earlier rtfgu ended a path at every
vertex with probability 1 - mean(kd cd), worksheet 7's first roulette: the same expectation
with more variance at the first bounces.)

Emitted light is counted where the eye sees it and after a mirror or a refraction, and not
after a diffuse bounce, whose light sources the bounce's vertex sampled already; so every
emitting shape must be an ``AreaLight``'s (``validate`` says which is not). A surface emits
from its front only (the side its normal points to). A ray that leaves the scene sees the
scene's environment (Scene.background_radiance).

The book's PathTrace samples no lights (a path finds the emitters by hitting them) and
recurses through ``path_shade``; this is the 02562 worksheet 7 path tracer, with the lights
sampled at every vertex, and its loop multiplies a throughput as the numba and WGSL kernels
do (rtfgu/kernels/path_trace.py, rtfgu/wgsl/path_trace.wgsl), so the three agree bit for
bit. The book's tracer that samples the lights at the first vertex only is GlobalTrace.

The random numbers of vertex ``depth`` are the stream's dimensions ``path_dimension(depth,
k)`` (rtfgu.sampling.random), so the numba path draws the same numbers for the same path.
A path has at most ``max_depth`` vertices.
"""
from __future__ import annotations

from ..float3 import Float3, dot
from ..sampling.random import LIGHT_U, ROULETTE, VERTEX_DIMENSIONS, path_dimension, random_float
from .tracer import Tracer, check_max_depth

# The first vertex (0 where the eye ray lands) whose continuation Russian roulette decides.
ROULETTE_DEPTH = 1

# The deepest path: vertex dimensions stay below 2^32 far beyond it.
MAX_PATH_DEPTH = 1024
# The most area lights a path samples (two dimensions each per vertex).
MAX_AREA_LIGHTS = (VERTEX_DIMENSIONS - LIGHT_U) // 2


class PathTrace(Tracer):
    samples_area_lights = True

    def __init__(self, max_depth: int = 64):
        super().__init__()
        self.max_depth = check_max_depth(max_depth, "%s.max_depth" % type(self).__name__, MAX_PATH_DEPTH)

    def samples_lights_at(self, depth: int) -> bool:
        """Whether the vertex at ``depth`` samples the lights (next-event estimation)."""
        return True

    def trace_ray(self, ray, depth: int = 0) -> Float3:
        """The radiance of one path from ``ray`` (the renderer's eye ray at depth 0)."""
        result = Float3(0.0)
        throughput = Float3(1.0)
        sees_emission = True        # the eye ray, or a ray after a mirror or a refraction
        for depth in range(depth, self.max_depth):
            if depth > ROULETTE_DEPTH:
                # Russian roulette on the throughput, for the ray from the vertex before.
                q = max(throughput.x, throughput.y, throughput.z)
                if q < 1.0:
                    pixel, sample, seed = self.stream
                    if not random_float(pixel, sample, path_dimension(depth - 1, ROULETTE), seed) < q:
                        break
                    throughput = throughput / q
            sr = self.hit(ray, depth)
            if sr is None:
                result += throughput * self.world.background_radiance(ray.direction)
                break
            if sees_emission and dot(sr.normal, ray.direction) < 0.0:
                result += throughput * sr.material.get_Le(sr)
            vertex = sr.material.path_shade(sr)
            if vertex.L is not None:
                result += throughput * vertex.L
            if vertex.ray is None:
                break
            if vertex.f is not None:
                throughput = throughput * vertex.f * vertex.scale
            ray = vertex.ray
            sees_emission = vertex.sees_emission or not self.samples_lights_at(depth)
        return result

    def validate(self, scene) -> None:
        """Raise a ValueError naming the field if ``scene`` cannot be path traced."""
        from ..lights.area_light import AreaLight
        from ..shapes.compound import Compound
        from ..shapes.mesh import Mesh

        lit = {id(light.shape) for light in scene.lights if isinstance(light, AreaLight)}
        if len(lit) > MAX_AREA_LIGHTS:
            raise ValueError("Scene.lights: %s samples at most %d area lights, got %d"
                             % (type(self).__name__, MAX_AREA_LIGHTS, len(lit)))
        for i, top in enumerate(scene.shapes):
            if isinstance(top, Mesh):
                self._validate_mesh(i, top, lit)
                continue
            for shape in top.leaves() if isinstance(top, Compound) else [top]:   # a Compound: its leaves
                where = "Scene.shapes[%d].material (%s)" % (i, type(shape.material).__name__)
                shape.material.check_path_trace(where, shape.color)
                e = shape.material.emission
                if max(e.x, e.y, e.z) > 0.0 and id(shape) not in lit:
                    raise ValueError("Scene.shapes[%d] emits (its material's emission is %r) but no AreaLight in "
                                     "Scene.lights samples it: add AreaLight(scene.shapes[%d])" % (i, e, i))

    @staticmethod
    def _validate_mesh(i: int, mesh, lit: set) -> None:
        """validate's checks for the faces of the Mesh ``Scene.shapes[i]``, once per distinct
        material and colour (Mesh.surfaces); an emitting face must be an AreaLight's shape,
        one of ``mesh.triangles()`` (made here only when a face emits)."""
        for face, material, faces in mesh.surfaces():
            where = "Scene.shapes[%d].materials[%d] (%s)" % (i, face, type(material).__name__)
            material.check_path_trace(where, mesh.color(face))
            e = material.emission
            if max(e.x, e.y, e.z) > 0.0:
                triangles = mesh.triangles()
                for k in faces:
                    if id(triangles[k]) not in lit:
                        raise ValueError("Scene.shapes[%d] (a Mesh): face %d emits (its material's emission is %r) "
                                         "but no AreaLight in Scene.lights samples it: add "
                                         "AreaLight(mesh.triangles()[%d])" % (i, k, e, k))
