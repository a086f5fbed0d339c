"""Scene: a camera and a number of shapes (lecture 01, "Scene"), plus what the book's World
holds for shading (Suffern ch. 14): lights, the ambient light, a background colour, and the
tracer that turns a ray into a colour."""
from __future__ import annotations

import copy

from .cameras.camera import Camera
from .float3 import Float3, as_float3
from .hit_info import HitInfo
from .ray import Ray


class Scene:
    def __init__(self, camera: Camera | None = None):
        from .lights.ambient import Ambient
        from .tracers.whitted import Whitted

        self.camera = camera
        self.shapes = []
        self.lights = []
        self.background = Float3(0.0)
        # The book's world.ambient_ptr: Ambient() (ls 1, white) is the 02562 scene's, whose
        # 10 % ambient term is a Matte's ka = 0.1.
        self.ambient_light = Ambient()
        # 02562 week 1's first image: every pixel shows its eye ray's direction, d * 0.5 + 0.5.
        self.show_ray_direction = False
        # Suffern's view-plane sampler (ch. 5): the points of each pixel that rays go through.
        # None: one ray through each pixel's centre. render(..., spp=N) overrides its count.
        self.sampler = None
        # How a ray becomes a colour (rtfgu/tracers): Whitted() is the 02562 path loop.
        self.tracer = Whitted()
        # What a ray that leaves the scene sees: None is ``background`` from every direction;
        # an EnvironmentLight (rtfgu/lights/environment_light.py) its image.
        self.environment = None

    def with_faces(self) -> "Scene":
        """The scene as the lecture layer traces it: ``shapes`` with each ``Mesh`` replaced by
        its faces, ``mesh.triangles()`` (made on the first call, then kept by the mesh), in
        place, and each Instance of a Mesh or a Compound by an Instance of each face or leaf
        (``Instance.parts()``).
        A shallow copy that shares everything else; the scene itself when it holds no
        Mesh. The numba and WGSL paths read a Mesh's arrays instead (rtfgu.layout)."""
        from .shapes.instance import Instance
        from .shapes.mesh import Mesh

        def has_faces(shape) -> bool:
            return isinstance(shape, Mesh) or (isinstance(shape, Instance) and shape.holds_parts())

        if not any(has_faces(shape) for shape in self.shapes):
            return self
        view = copy.copy(self)
        view.shapes = []
        for shape in self.shapes:
            if isinstance(shape, Mesh):
                view.shapes += shape.triangles()
            elif has_faces(shape):
                view.shapes += shape.parts()
            else:
                view.shapes.append(shape)
        return view

    def background_radiance(self, direction: Float3) -> Float3:
        """What a ray leaving the scene along ``direction`` sees: the environment's radiance
        there, or the background colour."""
        if self.environment is None:
            return self.background
        return self.environment.radiance(direction)

    def intersect(self, ray: Ray, hit: HitInfo) -> bool:
        """``intersect_scene``: the slide's inner loop over the shapes; each hit shrinks
        ray.tmax, so the last shape that reports a hit is the nearest one. The hit records
        the shape's material and the surface's colour there (Material.color_at); for a
        Compound, those of the child hit."""
        hit_shape = None
        for shape in self.shapes:
            if shape.intersect_p(ray):
                hit_shape = shape
        if hit_shape is not None:
            # A Compound (rtfgu.shapes.compound) was hit where its child hit_object was.
            hit_shape = getattr(hit_shape, "hit_object", None) or hit_shape
            hit.has_hit = True
            hit.dist = ray.tmax
            hit.position = ray(ray.tmax)
            hit.normal = hit_shape.hit_normal(hit.position, ray.direction)
            hit.material = hit_shape.material
            hit.color = hit_shape.material.color_at(hit_shape, hit.position)
        return hit.has_hit

    def light_sample(self, light, sr) -> tuple:
        """The point (u, v) of the unit square from which ``light`` draws at ``sr``: its
        sampler's, or the scene's pair (rtfgu.sampling.sobol.pair_sample: the stream's, or
        Sobol's where the scene's sampler is a Sobol) in the path dimensions LIGHT_U + 2 j and the next,
        j the number of lights of its kind before it in ``lights``."""
        from .sampling.random import LIGHT_U, path_dimension
        from .sampling.sobol import pair_sample

        j = 0
        for other in self.lights:
            if other is light:
                break
            j += type(other) is type(light)
        dimension = path_dimension(sr.depth, LIGHT_U + 2 * j)
        if light.sampler is not None:
            return light.sampler.sample_unit_square(sr.pixel, sr.sample, sr.seed, dimension)
        return pair_sample(self.sampler, sr.pixel, sr.sample, dimension, sr.seed)

    def validate(self) -> None:
        """Raise a ValueError naming the field if this scene cannot be rendered."""
        from .lights.ambient import Ambient
        from .lights.environment_light import EnvironmentLight
        from .lights.light import Light
        from .sampling.sampler import Sampler
        from .shapes.mesh import Mesh
        from .shapes.shape import Shape
        from .tracers.tracer import Tracer

        if not isinstance(self.camera, Camera):
            raise ValueError("Scene.camera must be a Camera, got %r" % (self.camera,))
        for i, shape in enumerate(self.shapes):
            if not isinstance(shape, (Shape, Mesh)):
                raise ValueError("Scene.shapes[%d] must be a Shape or a Mesh, got %r" % (i, shape))
        for i, light in enumerate(self.lights):
            if not isinstance(light, Light) or isinstance(light, (Ambient, EnvironmentLight)):
                raise ValueError("Scene.lights[%d] must be a PointLight, Directional, AreaLight or "
                                 "AmbientOccluder, got %r (the ambient light is Scene.ambient_light, an "
                                 "environment Scene.environment)" % (i, light))
        if not isinstance(self.ambient_light, Ambient):
            raise ValueError("Scene.ambient_light must be an Ambient, got %r" % (self.ambient_light,))
        if self.sampler is not None and not isinstance(self.sampler, Sampler):
            raise ValueError("Scene.sampler must be a Sampler or None, got %r" % (self.sampler,))
        self.background = as_float3(self.background, "Scene.background")
        if self.environment is not None and not isinstance(self.environment, EnvironmentLight):
            raise ValueError("Scene.environment must be None or an EnvironmentLight, got %r"
                             % (self.environment,))
        if not isinstance(self.tracer, Tracer):
            raise ValueError("Scene.tracer must be a Tracer (RayCast, Whitted, AreaLighting, PathTrace, "
                             "GlobalTrace), got %r" % (self.tracer,))
        if not hasattr(self.tracer, "samples_lights_at"):
            for i, light in enumerate(self.lights):
                if not light.drawn_by_ray_casting:
                    raise ValueError("Scene.lights[%d]: a %s samples directions, which the %s tracer does not; "
                                     "render with scene.tracer = PathTrace(...) (max_depth=1 for its image alone)"
                                     % (i, type(light).__name__, type(self.tracer).__name__))
        self.tracer.validate(self)
