"""Scene: a camera and a number of shapes (lecture 01, "Scene"), plus the 02562 additions a
shaded image needs: lights, a background colour, whether shadow rays are cast, and which
tracer turns a ray into a colour."""
from __future__ import annotations

from .cameras.camera import Camera
from .float3 import Float3, as_float3
from .ray import Ray
from .shading import HitInfo


class Scene:
    def __init__(self, camera: Camera | None = None):
        self.camera = camera
        self.shapes = []
        self.lights = []
        self.background = Float3(0.0)
        # 02562 week 2 renders diffuse shading first without, then with, shadow rays.
        self.shadows = True
        # 02562 week 1's first image: every pixel shows its eye ray's direction, d * 0.5 + 0.5.
        self.show_ray_direction = False
        # Suffern's view-plane sampler (ch. 5): the points of each pixel that rays go through.
        # None: one ray through each pixel's centre. render(..., spp=N) overrides its count.
        self.sampler = None
        # How a pixel's ray becomes a colour: None is the 02562 ray-cast loop
        # (rtfgu.renderer.trace); Suffern's PathTrace (rtfgu.path_trace) traces paths.
        self.tracer = None
        # What a ray that leaves the scene sees: None is ``background`` from every direction;
        # an EnvironmentLight (rtfgu.environment_light) its image.
        self.environment = None

    def background_radiance(self, direction: Float3) -> Float3:
        """What a ray leaving the scene along ``direction`` sees: the environment's radiance
        there, or the background colour."""
        if self.environment is None:
            return self.background
        return self.environment.radiance(direction)

    def intersect(self, ray: Ray, hit: HitInfo) -> bool:
        """``intersect_scene``: the slide's inner loop over the shapes; each hit shrinks
        ray.tmax, so the last shape that reports a hit is the nearest one."""
        hit_shape = None
        for shape in self.shapes:
            if shape.intersect_p(ray):
                hit_shape = shape
        if hit_shape is not None:
            hit.has_hit = True
            hit.dist = ray.tmax
            hit.position = ray(ray.tmax)
            hit.normal = hit_shape.normal_at(hit.position)
            color = hit_shape.color
            texture = hit_shape.material.texture
            if texture is not None:      # the texture's colour at the hit replaces the shape's
                color = texture.color_at(*hit_shape.texcoord(hit.position))
            hit.set_material(color, hit_shape.material)
        return hit.has_hit

    def validate(self) -> None:
        """Raise a ValueError naming the field if this scene cannot be rendered."""
        from .cameras.camera import Camera as _Camera
        from .registry import LIGHTS
        from .sampling.sampler import Sampler
        from .shapes.shape import Shape

        if not isinstance(self.camera, _Camera):
            raise ValueError("Scene.camera must be a Camera, got %r" % (self.camera,))
        for i, shape in enumerate(self.shapes):
            if not isinstance(shape, Shape):
                raise ValueError("Scene.shapes[%d] must be a Shape, got %r" % (i, shape))
        for i, light in enumerate(self.lights):
            if not isinstance(light, tuple(kind.cls for kind in LIGHTS)):
                raise ValueError("Scene.lights[%d] must be one of %s, got %r"
                                 % (i, ", ".join(kind.record for kind in LIGHTS), light))
        if self.sampler is not None and not isinstance(self.sampler, Sampler):
            raise ValueError("Scene.sampler must be a Sampler or None, got %r" % (self.sampler,))
        self.background = as_float3(self.background, "Scene.background")
        if self.environment is not None:
            from .environment_light import EnvironmentLight
            if not isinstance(self.environment, EnvironmentLight):
                raise ValueError("Scene.environment must be None or an EnvironmentLight, got %r"
                                 % (self.environment,))
        if self.tracer is None:
            for i, light in enumerate(self.lights):
                kind = next(k for k in LIGHTS if isinstance(light, k.cls))
                if not kind.ray_cast:
                    raise ValueError("Scene.lights[%d]: a %s samples directions, which the ray-cast loop does "
                                     "not; render with scene.tracer = PathTrace(...) (max_depth=1 for its "
                                     "image alone)" % (i, kind.record))
        if self.tracer is not None:
            from .path_trace import PathTrace
            if not isinstance(self.tracer, PathTrace):
                raise ValueError("Scene.tracer must be None (ray casting) or a PathTrace, got %r"
                                 % (self.tracer,))
            self.tracer.validate(self)
