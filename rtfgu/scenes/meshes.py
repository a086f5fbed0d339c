"""Scenes of triangle meshes (02562 worksheets 5-6, Suffern ch. 23): the Utah teapot under a
directional light, the Stanford bunny, and the Cornell box, with its two blocks or with a
mirror and a glass sphere.

The shipped meshes (rtfgu/meshes/README.md) are placed as the worksheets' files are: the
teapot scaled by 0.2 and standing on y = 0 (6.4 wide, 3.15 high, as worksheet 5's), the
bunny scaled and moved onto the Stanford scan's bounding box (the npm package's copy is 10
units high), the Cornell box in its measured millimetres.

The Cornell box's light is its emissive ceiling quad (Ke in cornell_box.mtl): an AreaLight
per triangle. The ray-cast scenes see each as a point at its centre (worksheet 5's first
approximation, rtfgu/lights/area_light.py); the path-traced ones sample points of it.

The ray-cast scenes' surfaces are the course's Matte (ka 0.1, kd 0.9); a path-traced
scene's are ``PATH_MATTE`` (kd 1: the albedo is the colour; no ambient term: the light
reflected between the surfaces is what the path tracer computes).
"""
from __future__ import annotations

import math

from ..lazy_import import numpy as np

from ..cameras import PinholeCamera
from ..float3 import Float3, normalize
from ..lights import AmbientOccluder, AreaLight, Directional, PointLight
from ..materials import Material, Matte, Reflective, Transparent, dielectric
from ..obj import load_obj, mesh_path
from ..sampling import Jittered
from ..sampling.sampler import sampler_of
from ..scene import Scene
from ..shapes import Plane, Sphere
from ..shapes.mesh import Mesh
from ..textures import ImageTexture
from ..tracers import AreaLighting, GlobalTrace, PathTrace
from .registry import homework
from .textures import texture_path

BACKGROUND = Float3(0.1, 0.3, 0.6)
# The Stanford bunny's bounding box (bun_zipper.ply), where the npm copy is moved to.
STANFORD_BUNNY_MIN = (-0.0946899, 0.0329874, -0.0618736)
STANFORD_BUNNY_MAX = (0.0610091, 0.187321, 0.0587997)


def _placed(mesh: Mesh, scale: float, offset) -> Mesh:
    return Mesh(mesh.vertices * scale + np.asarray(offset, dtype=float), mesh.faces, mesh.colors,
                normals=mesh.normals, material=mesh.materials, uvs=mesh.uvs)


def teapot_mesh(material: Material | None = None) -> Mesh:
    """The Utah teapot scaled by 0.2, standing on y = 0."""
    mesh = load_obj(mesh_path("teapot.obj"), material=material, default_color=(0.9, 0.9, 0.9))
    return _placed(mesh, 0.2, (0.0, -0.2 * mesh.vertices[:, 1].min(), 0.0))


def bunny_mesh(material: Material | None = None) -> Mesh:
    """The bunny on the Stanford scan's bounding box (one scale, the box's centre)."""
    mesh = load_obj(mesh_path("bunny.obj"), material=material, default_color=(0.9, 0.9, 0.9))
    lo, hi = mesh.vertices.min(axis=0), mesh.vertices.max(axis=0)
    box_lo, box_hi = np.array(STANFORD_BUNNY_MIN), np.array(STANFORD_BUNNY_MAX)
    scale = float(np.mean((box_hi - box_lo) / (hi - lo)))
    offset = (box_lo + box_hi) / 2 - scale * (lo + hi) / 2
    return _placed(mesh, scale, offset)


MM = 0.001   # the Cornell box's millimetres, in metres


def path_matte() -> Matte:
    """A path-traced scene's diffuse surface: kd 1 (the albedo is the colour), no ambient term."""
    return Matte(ka=0.0, kd=1.0)


def cornell_box_mesh(blocks: bool = True, material: Material | None = None) -> Mesh:
    """The Cornell box (cornell_box.obj) in metres, every face ``material`` (the course's
    Matte if None); without ``blocks``, the two blocks' 20 faces are left out (every vertex of
    a block face is inside the room, away from walls, floor and ceiling)."""
    mesh = load_obj(mesh_path("cornell_box.obj"), material=Matte() if material is None else material)
    if blocks:
        return _placed(mesh, MM, (0.0, 0.0, 0.0))
    v = mesh.vertices[mesh.faces]                       # (faces, 3 vertices, xyz), in mm
    inside = ((v[..., 0] > 50) & (v[..., 0] < 500) & (v[..., 2] > 50) & (v[..., 2] < 500)
              & (v[..., 1] < 400)).all(axis=1)
    block = inside & ~(v[..., 1] == 0).all(axis=1)
    keep = ~block
    return Mesh(mesh.vertices * MM, mesh.faces[keep], mesh.colors[keep],
                material=[m for m, k in zip(mesh.materials, keep) if k])


def cornell_lights(scene: Scene) -> list:
    """An AreaLight for every emitting shape of ``scene`` (the ceiling quad's two triangles)."""
    return [AreaLight(shape) for shape in scene.shapes
            if max(shape.material.emission.x, shape.material.emission.y, shape.material.emission.z) > 0]


def _cornell_scene(mesh: Mesh) -> Scene:
    camera = PinholeCamera(Float3(277.0, 275.0, -570.0) * MM, Float3(277.0, 275.0, 0.0) * MM,
                           Float3(0.0, 1.0, 0.0), d=1.0)
    scene = Scene(camera)
    scene.background = Float3(0.0)
    scene.shapes += mesh.triangles()
    scene.lights += cornell_lights(scene)
    return scene


def _cornell_spheres(scene: Scene) -> Scene:
    scene.shapes.append(Sphere(Float3(420.0, 90.0, 370.0) * MM, 90.0 * MM, Float3(0.0), Reflective()))
    scene.shapes.append(Sphere(Float3(130.0, 90.0, 250.0) * MM, 90.0 * MM, Float3(0.0), Transparent(ior=1.5)))
    return scene


@homework(800, 450, test_side=24)
def teapot() -> Scene:
    """Worksheet 5: the Utah teapot on a floor under a directional light."""
    camera = PinholeCamera(Float3(0.15, 1.5, 10.0), Float3(0.15, 1.5, 0.0), Float3(0.0, 1.0, 0.0),
                           d=2.5, aspect=800 / 450)
    scene = Scene(camera)
    scene.background = BACKGROUND
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.1, 0.7, 0.0), Matte()))
    scene.shapes.append(teapot_mesh(Matte()))          # the mesh itself: its faces, in order
    # Worksheet 5's light travels along normalize(-1, -1, -1): toward it is the opposite.
    scene.lights.append(Directional(-normalize(Float3(-1.0, -1.0, -1.0)), Float3(math.pi)))
    return scene


@homework(512, 512, test_side=16)
def bunny() -> Scene:
    """Worksheet 6: the Stanford bunny under a directional light."""
    camera = PinholeCamera(Float3(-0.02, 0.11, 0.6), Float3(-0.02, 0.11, 0.0), Float3(0.0, 1.0, 0.0), d=3.5)
    scene = Scene(camera)
    scene.background = BACKGROUND
    scene.shapes.append(bunny_mesh(Matte()))
    scene.lights.append(Directional(-normalize(Float3(-1.0, -1.0, -1.0)), Float3(math.pi)))
    return scene


@homework(512, 384, test_side=24)
def suffern_29_uv_mesh() -> Scene:
    """Suffern ch. 29, texturing a triangle mesh by its vertices' (u, v): the globe of
    rtfgu/meshes (an OBJ file's ``vt``, smooth-shaded) with worksheet 3's tiles, bilinear and
    repeated twice around, beside the same mesh without its uvs, whose faces each show the
    texture's corner by their barycentric (beta, gamma)."""
    camera = PinholeCamera(Float3(0.0, 1.6, 5.0), Float3(0.0, 0.9, 0.0), Float3(0.0, 1.0, 0.0),
                           d=1.6, aspect=512 / 384)
    scene = Scene(camera)
    scene.background = BACKGROUND
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.7, 0.7, 0.6), Matte()))
    tiles = ImageTexture(texture_path("tiles16.png"), filter="bilinear", address="repeat")
    globe = load_obj(mesh_path("globe.obj"), material=Matte(cd=tiles))
    scene.shapes.append(_placed(Mesh(globe.vertices, globe.faces, globe.colors, normals=globe.normals,
                                     material=globe.materials, uvs=globe.uvs * (2.0, 1.0)),
                                0.9, (-1.0, 0.9, 0.0)))
    plain = Mesh(globe.vertices, globe.faces, globe.colors, normals=globe.normals, material=globe.materials)
    scene.shapes.append(_placed(plain, 0.6, (1.3, 0.6, 0.3)))
    scene.lights.append(PointLight(Float3(3.0, 5.0, 4.0), Float3(40.0)))
    return scene


@homework(512, 512)
def cornell_box_blocks() -> Scene:
    """Worksheet 5: the Cornell box with its two blocks, lit from its ceiling light."""
    return _cornell_scene(cornell_box_mesh(blocks=True))


@homework(512, 512)
def cornell_box_spheres() -> Scene:
    """Worksheet 6: the Cornell box with a mirror sphere and a glass sphere (ior 1.5)."""
    return _cornell_spheres(_cornell_scene(cornell_box_mesh(blocks=False)))


# Path-traced scenes: the samples per pixel of ``make render`` (under a minute each on two
# cores with the numba path, docs/path_tracing.md) and of the tests.
AREA_LIGHT_SPP = 256
PROGRESSIVE_SPP = 484   # 22 x 22 (Jittered)
TEST_SPP = 4


@homework(512, 512, test_side=16, test_spp=TEST_SPP)
def cornell_box_area_light() -> Scene:
    """Worksheet 5: the Cornell box with its blocks lit by its ceiling as an area light: the
    direct light only (PathTrace with one vertex), soft shadows."""
    scene = _cornell_scene(cornell_box_mesh(blocks=True, material=path_matte()))
    scene.tracer = PathTrace(max_depth=1)
    scene.sampler = sampler_of(Jittered, AREA_LIGHT_SPP)
    return scene


@homework(512, 512, test_side=16, test_spp=TEST_SPP)
def cornell_box_progressive() -> Scene:
    """Worksheet 7: the Cornell box with a mirror and a glass sphere, path traced: the
    light of the ceiling reflected any number of times (progressive rendering)."""
    scene = _cornell_spheres(_cornell_scene(cornell_box_mesh(blocks=False, material=path_matte())))
    scene.tracer = PathTrace()
    scene.sampler = sampler_of(Jittered, PROGRESSIVE_SPP)
    return scene


@homework(512, 512, test_side=16, test_spp=TEST_SPP)
def suffern_18_area_lighting() -> Scene:
    """Suffern ch. 18: the Cornell box with its blocks under its ceiling lamp, ray cast by
    AreaLighting: every sample of a pixel draws its own point of the lamp, so the blocks cast
    soft shadows without path tracing (cornell_box_blocks sees the lamp as a point at its
    centre: hard shadows)."""
    scene = _cornell_scene(cornell_box_mesh(blocks=True))
    scene.tracer = AreaLighting()
    scene.sampler = sampler_of(Jittered, AREA_LIGHT_SPP)
    return scene


@homework(512, 512, test_side=16, test_spp=TEST_SPP)
def suffern_26_global_trace() -> Scene:
    """Suffern ch. 26: the box of cornell_box_progressive traced by GlobalTrace, which samples
    the lights at the first vertex only and counts the ceiling's light where later bounces hit
    it: the same mean as PathTrace's image beside it, more noise at the same samples."""
    scene = cornell_box_progressive()
    scene.tracer = GlobalTrace()
    return scene


# Worksheet 8's glass: ior 1.5, absorbing sigma_a per metre (a green tint: a ray through the
# sphere's 0.18 m diameter keeps exp(-0.18 sigma_a) = (0.70, 0.91, 0.76)).
GLASS_ABSORPTION = (2.0, 0.5, 1.5)


@homework(512, 512, test_side=16, test_spp=TEST_SPP)
def cornell_box_fresnel() -> Scene:
    """Worksheet 8: the Cornell box with a mirror sphere and an absorbing glass sphere that
    reflects by Fresnel's law, path traced: the caustic under the glass."""
    scene = _cornell_scene(cornell_box_mesh(blocks=False, material=path_matte()))
    scene.shapes.append(Sphere(Float3(420.0, 90.0, 370.0) * MM, 90.0 * MM, Float3(0.0), Reflective()))
    scene.shapes.append(Sphere(Float3(130.0, 90.0, 250.0) * MM, 90.0 * MM, Float3(0.0),
                               dielectric(1.5, GLASS_ABSORPTION)))
    scene.tracer = PathTrace()
    scene.sampler = sampler_of(Jittered, PROGRESSIVE_SPP)
    return scene


AMBIENT_OCCLUSION_SPP = 256


@homework(512, 512, test_side=16, test_spp=TEST_SPP)
def cornell_box_ambient_occlusion() -> Scene:
    """Suffern ch. 17: the Cornell box with its blocks, all a white 0.8, lit only by an
    AmbientOccluder (PathTrace with one vertex): how open each point's hemisphere is."""
    mesh = cornell_box_mesh(blocks=True)
    scene = _cornell_scene(Mesh(mesh.vertices, mesh.faces, (0.8, 0.8, 0.8), material=path_matte()))
    scene.lights = [AmbientOccluder(1.0)]
    scene.tracer = PathTrace(max_depth=1)
    scene.sampler = sampler_of(Jittered, AMBIENT_OCCLUSION_SPP)
    return scene
