"""The flat scene layout shared by the numba kernels and the WGSL program.

One module owns the memory layout: dtypes, shape-kind ids, camera-kind ids, shader ids,
and the order of the fields in every row. ``compile_scene`` turns a lecture-layer ``Scene``
into these arrays after validating it, so bad input never reaches a kernel.

Every row is a whole number of 4-component vectors, so the same arrays upload to WGSL
``array<vec4f, N>`` buffers unchanged (16-byte stride in float32).

    camera      (4, 4)   ORTHOGRAPHIC: [left, right, bottom, top], [hither, yon, tmin, 0], 0, 0
                         PINHOLE:      [eye, d], [b1, aspect], [b2, 0], [v, 0]
    planes      (P, 8)   [point, 0], [normal, 0]             (the normal as given, not normalised)
    triangles   (T, 16)  [v0, 0], [e0, 0], [e1, 0], [n, 0]   (e0 = v1 - v0, e1 = v2 - v0, n = e0 x e1)
    spheres     (S, 4)   [center, radius]
    *_index     (P|T|S,) int32: the shape's place in Scene.shapes, which is also its material row
    materials   (N, 16)  [color, 0], [specular, shininess], [emission, ior], [0, 0, 0, 0]
    shaders     (N,)     int32 shader id (rtfgu.material: BASE_COLOR, LAMBERTIAN, ...)
    lights      (L, 8)   [position, 0], [intensity, 0]
    background  (4,)     [rgb, 0]
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .cameras import OrthographicCamera, PinholeCamera
from .material import SHADER_NAMES
from .ray import RAY_EPSILON
from .shapes import Plane, Sphere, Triangle

# Shape kinds and camera kinds, closed lists dispatched by id (as PBRT's tagged shapes).
PLANE = 0
TRIANGLE = 1
SPHERE = 2
SHAPE_KINDS = {PLANE: "plane", TRIANGLE: "triangle", SPHERE: "sphere"}

ORTHOGRAPHIC = 0
PINHOLE = 1
CAMERA_KINDS = {ORTHOGRAPHIC: "orthographic", PINHOLE: "pinhole"}

SHADER_IDS = {name: shader_id for shader_id, name in SHADER_NAMES.items()}

DTYPES = {"float64": np.float64, "float32": np.float32}

# Row widths in floats (each a multiple of 4: whole vec4s).
CAMERA_ROWS = 4
PLANE_WIDTH = 8
TRIANGLE_WIDTH = 16
SPHERE_WIDTH = 4
MATERIAL_WIDTH = 16
LIGHT_WIDTH = 8

# Column offsets inside a row, named so that kernels and WGSL never use bare numbers.
MAT_COLOR = 0
MAT_SPECULAR = 4
MAT_SHININESS = 7
MAT_EMISSION = 8
MAT_IOR = 11
LIGHT_POSITION = 0
LIGHT_INTENSITY = 4
TRI_V0 = 0
TRI_E0 = 4
TRI_E1 = 8
TRI_N = 12
PLANE_POINT = 0
PLANE_NORMAL = 4
SPHERE_CENTER = 0
SPHERE_RADIUS = 3
# The camera block (CAMERA_ROWS x 4 floats, read as one flat row of 16).
ORTHO_LEFT = 0
ORTHO_RIGHT = 1
ORTHO_BOTTOM = 2
ORTHO_TOP = 3
ORTHO_HITHER = 4
ORTHO_YON = 5
ORTHO_TMIN = 6
PINHOLE_EYE = 0
PINHOLE_D = 3
PINHOLE_B1 = 4
PINHOLE_ASPECT = 7
PINHOLE_B2 = 8
PINHOLE_V = 12
CAMERA_WIDTH = CAMERA_ROWS * 4

# Every row as a record: name -> (row width, ((field, components, column offset), ...)).
# Components 3 is a vector, 1 a scalar. The WGSL structs are generated from these records
# (rtfgu/wgsl/structs.py), so a field moved here moves in the shader too.
RECORDS = {
    "Plane": (PLANE_WIDTH, (("point", 3, PLANE_POINT), ("normal", 3, PLANE_NORMAL))),
    "Triangle": (TRIANGLE_WIDTH, (("v0", 3, TRI_V0), ("e0", 3, TRI_E0), ("e1", 3, TRI_E1),
                                  ("n", 3, TRI_N))),
    "Sphere": (SPHERE_WIDTH, (("center", 3, SPHERE_CENTER), ("radius", 1, SPHERE_RADIUS))),
    "Material": (MATERIAL_WIDTH, (("color", 3, MAT_COLOR), ("specular", 3, MAT_SPECULAR),
                                  ("shininess", 1, MAT_SHININESS), ("emission", 3, MAT_EMISSION),
                                  ("ior", 1, MAT_IOR))),
    "PointLight": (LIGHT_WIDTH, (("position", 3, LIGHT_POSITION),
                                 ("intensity", 3, LIGHT_INTENSITY))),
    "OrthographicCamera": (CAMERA_WIDTH, (("left", 1, ORTHO_LEFT), ("right", 1, ORTHO_RIGHT),
                                          ("bottom", 1, ORTHO_BOTTOM), ("top", 1, ORTHO_TOP),
                                          ("hither", 1, ORTHO_HITHER), ("yon", 1, ORTHO_YON),
                                          ("tmin", 1, ORTHO_TMIN))),
    "PinholeCamera": (CAMERA_WIDTH, (("eye", 3, PINHOLE_EYE), ("d", 1, PINHOLE_D),
                                     ("b1", 3, PINHOLE_B1), ("aspect", 1, PINHOLE_ASPECT),
                                     ("b2", 3, PINHOLE_B2), ("v", 3, PINHOLE_V))),
}

# A far-away tmax for APIs that cannot hold infinity (WGSL has no inf literal).
FAR = 1.0e30


@dataclass
class FlatScene:
    """A scene as flat arrays, in one float dtype. ``features`` names what the scene uses
    (shape kinds, shader names, "lights", "shadows", "ray_direction") so that a path can
    leave out what a scene does not need."""

    dtype: type
    camera_kind: int
    camera: np.ndarray
    planes: np.ndarray
    plane_index: np.ndarray
    triangles: np.ndarray
    triangle_index: np.ndarray
    spheres: np.ndarray
    sphere_index: np.ndarray
    materials: np.ndarray
    shaders: np.ndarray
    lights: np.ndarray
    background: np.ndarray
    shadows: bool
    show_ray_direction: bool
    features: frozenset = field(default_factory=frozenset)


def _vec(v) -> list:
    return [v.x, v.y, v.z]


def compile_camera(camera) -> tuple[int, np.ndarray]:
    rows = np.zeros((CAMERA_ROWS, 4), dtype=np.float64)
    if isinstance(camera, OrthographicCamera):
        rows[0] = [camera.left, camera.right, camera.bottom, camera.top]
        yon = camera.yon if math.isfinite(camera.yon) else FAR
        # gen_ray's ray: origin z = hither, tmin = 0.00001, tmax = yon - hither
        rows[1] = [camera.hither, yon, RAY_EPSILON, 0.0]
        return ORTHOGRAPHIC, rows
    if isinstance(camera, PinholeCamera):
        rows[0] = _vec(camera.eye) + [camera.d]
        rows[1] = _vec(camera.b1) + [camera.aspect]
        rows[2] = _vec(camera.b2) + [0.0]
        rows[3] = _vec(camera.v) + [0.0]
        return PINHOLE, rows
    raise ValueError("Scene.camera: the flat layout knows OrthographicCamera and PinholeCamera, "
                     "got %s" % type(camera).__name__)


def compile_scene(scene, precision: str = "float64") -> FlatScene:
    """Validate ``scene`` and lay it out in ``precision`` ("float64" or "float32")."""
    if precision not in DTYPES:
        raise ValueError("precision must be one of %s, got %r" % (", ".join(DTYPES), precision))
    dtype = DTYPES[precision]
    scene.validate()
    camera_kind, camera = compile_camera(scene.camera)

    planes, plane_index = [], []
    triangles, triangle_index = [], []
    spheres, sphere_index = [], []
    materials, shaders = [], []
    features = {CAMERA_KINDS[camera_kind]}
    for i, shape in enumerate(scene.shapes):
        if isinstance(shape, Plane):
            planes.append(_vec(shape.point) + [0.0] + _vec(shape.normal) + [0.0])
            plane_index.append(i)
            features.add("plane")
        elif isinstance(shape, Triangle):
            triangles.append(_vec(shape.v0) + [0.0] + _vec(shape.e0) + [0.0]
                             + _vec(shape.e1) + [0.0] + _vec(shape.n) + [0.0])
            triangle_index.append(i)
            features.add("triangle")
        elif isinstance(shape, Sphere):
            spheres.append(_vec(shape.center) + [shape.radius])
            sphere_index.append(i)
            features.add("sphere")
        else:
            raise ValueError("Scene.shapes[%d]: the flat layout knows Plane, Triangle and Sphere, "
                             "got %s" % (i, type(shape).__name__))
        m = shape.material
        materials.append(_vec(shape.color) + [0.0] + _vec(m.specular) + [m.shininess]
                         + _vec(m.emission) + [m.ior] + [0.0, 0.0, 0.0, 0.0])
        shaders.append(m.shader)
        features.add(SHADER_NAMES[m.shader])

    lights = [_vec(light.position) + [0.0] + _vec(light.intensity) + [0.0] for light in scene.lights]
    if lights:
        features.add("lights")
    if scene.shadows and lights:
        features.add("shadows")
    if scene.show_ray_direction:
        features.add("ray_direction")

    def table(rows, width):
        return np.array(rows, dtype=dtype).reshape(len(rows), width)

    def index(rows):
        return np.array(rows, dtype=np.int32)

    flat = FlatScene(
        dtype=dtype,
        camera_kind=camera_kind,
        camera=camera.astype(dtype),
        planes=table(planes, PLANE_WIDTH), plane_index=index(plane_index),
        triangles=table(triangles, TRIANGLE_WIDTH), triangle_index=index(triangle_index),
        spheres=table(spheres, SPHERE_WIDTH), sphere_index=index(sphere_index),
        materials=table(materials, MATERIAL_WIDTH), shaders=index(shaders),
        lights=table(lights, LIGHT_WIDTH),
        background=np.array(_vec(scene.background) + [0.0], dtype=dtype),
        shadows=bool(scene.shadows),
        show_ray_direction=bool(scene.show_ray_direction),
        features=frozenset(features),
    )
    for name in ("camera", "planes", "triangles", "spheres", "materials", "lights", "background"):
        if not np.all(np.isfinite(getattr(flat, name))):
            raise ValueError("Scene: %s is not finite in %s (a value overflows the precision)"
                             % (name, precision))
    return flat
