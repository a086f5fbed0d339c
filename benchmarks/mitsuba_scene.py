"""Mitsuba 3 as a peer of rtfgu's path tracer: an rtfgu lecture-layer Scene (rtfgu/scene.py)
converted into a Mitsuba 3 scene dict, and rendered to a mean image with its per-pixel
standard error.

    to_mitsuba(scene, width, height, spp, seed=0, max_depth=None) -> dict for mi.load_dict
    render_mitsuba(scene, width, height, spp, passes=16, max_depth=None,
                   variant="scalar_rgb") -> (mean, stderr)

Mitsuba is imported inside the functions only (it is in the ``bench`` extra, never a
runtime dependency of rtfgu).

The mapping (Mitsuba 3 plugin reference, https://mitsuba.readthedocs.io/en/stable/src/plugin_reference.html):

  PinholeCamera   ``perspective``, fov_axis "y", fov = 2 atan(0.5 / d) (the rtfgu ray through
                  (sx, sy) is normalize(b1 sx aspect / 2 + b2 sy / 2 + v d)), to_world
                  look_at(eye, lookat, up): film column 0 on the image's left, row 0 at the
                  top, as rtfgu's (each pixel centre's ray agrees with
                  PinholeCamera.gen_ray to float32 precision).
                  The camera's aspect must equal width / height (Mitsuba's pixels are
                  square; a sensor's to_world may not scale).
  film            ``hdrfilm`` width x height, ``box`` filter (a sample counts in the pixel it
                  falls in, as rtfgu's samples over the pixel square), linear RGB float32.
  sampler         ``independent`` (spp, seed).
  integrator      ``path``, max_depth (None -> -1, unbounded with Russian roulette),
                  hide_emitters False. Mitsuba's max_depth counts the eye too: 1 shows
                  emitters only, 2 adds direct light; rtfgu's PathTrace(max_depth=k) is
                  Mitsuba's max_depth = k + 1.
  MeshTriangle    the faces present in scene.shapes, grouped per (mesh, material, colour),
                  each group one ``mi.Mesh`` from arrays (vertex normals if the mesh has
                  them, flat otherwise). Face winding is kept: Mitsuba's geometric normal
                  is (v1 - v0) x (v2 - v0), rtfgu's too.
  Triangle        a one-face mi.Mesh.   Sphere  ``sphere`` (center, radius).
  Rectangle       a two-face mi.Mesh over p0, p0 + a, p0 + a + b, p0 + b, facing a x b.
  Disk            ``disk`` with to_world = frame of the normal scaled by the radius.
  Plane           a square mi.Mesh of half side PLANE_EXTENT x the scene's radius, centred at
                  the scene's centre projected onto the plane, facing the plane's normal.
  material        Matte -> ``twosided`` ``diffuse``, reflectance = its albedo kd cd (cd the
                  shape's colour where None; PathTrace adds no ambient term, and shades a
                  face seen from behind as its front);
                  a mirror Reflective -> ``twosided`` ``conductor`` material "none"
                  (reflectance 1);
                  Dielectric (clear) -> ``dielectric`` int_ior = ior, ext_ior = 1;
                  Emissive -> ``diffuse`` reflectance 0.
                  Other materials (Material, Phong, Transparent, GlossyReflector) and
                  textures: ValueError.
  emission        a shape with material.emission != 0 gets an ``area`` emitter, radiance =
                  emission, from its front only (the side of its geometric normal), as
                  rtfgu's PathTrace.
  lights          PointLight (the 02562 light, inverse_square) -> ``point`` (position,
                  intensity); an AreaLight is the emission of its shape, converted with the
                  shape (its shape must be in scene.shapes). Other light kinds, and a light
                  that casts no shadows: ValueError.
  background      ``constant`` emitter, radiance = scene.background, if nonzero.

Differences that stay: Mitsuba's ``dielectric`` splits light by the Fresnel equations where
rtfgu's transparent shader refracts all of it; Mitsuba computes in float32.
"""
from __future__ import annotations

import math

import numpy as np

# A Plane becomes a square this many times the scene's radius in half side.
PLANE_EXTENT = 1e3
DEFAULT_VARIANT = "scalar_rgb"


def _mitsuba(variant: str | None = None):
    """The mitsuba module with ``variant`` set (None: keep the current one, DEFAULT_VARIANT
    if none is set)."""
    import mitsuba as mi
    if variant is not None:
        mi.set_variant(variant)
    elif mi.variant() is None:
        mi.set_variant(DEFAULT_VARIANT)
    return mi


def _xyz(v) -> list:
    return [float(v.x), float(v.y), float(v.z)] if hasattr(v, "x") else [float(c) for c in v]


def _rgb(v) -> dict:
    return {"type": "rgb", "value": _xyz(v)}


def _nonzero(v) -> bool:
    return any(c != 0.0 for c in _xyz(v))


def _surface_colour(color, material):
    """The colour of a material on a shape of colour ``color``: its cd, or the shape's."""
    from rtfgu.float3 import Float3
    return material.cd if isinstance(material.cd, Float3) else color


def _bsdf(color, material) -> dict:
    """The Mitsuba BSDF dict of an rtfgu material on a shape of colour ``color``."""
    from rtfgu import materials as rm
    if material.texture is not None:
        raise ValueError("to_mitsuba: textured materials are not converted (%r)" % (material,))
    shader = material.shader
    if shader == rm.LAMBERTIAN:
        albedo = [material.kd * c for c in _xyz(_surface_colour(color, material))]
        return {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": _rgb(albedo)}}
    if shader == rm.MIRROR:
        return {"type": "twosided", "bsdf": {"type": "conductor", "material": "none"}}
    if shader == rm.DIELECTRIC:
        if _nonzero(material.absorption):
            raise ValueError("to_mitsuba: an absorbing dielectric needs a Mitsuba medium, not converted (%r)"
                             % (material,))
        # Mitsuba's dielectric reflects by Fresnel's law as rtfgu's Dielectric does under PathTrace.
        return {"type": "dielectric", "int_ior": float(material.ior), "ext_ior": 1.0}
    if shader == rm.EMISSIVE:
        return {"type": "diffuse", "reflectance": _rgb((0.0, 0.0, 0.0))}
    name = rm.SHADER_NAMES.get(shader, shader)
    raise ValueError("to_mitsuba: %r (shader %r) has no Mitsuba counterpart here (Matte, a mirror Reflective, "
                     "Dielectric, Emissive only; a Transparent refracts without Fresnel's reflection)"
                     % (material, name))


def _emitter(material) -> dict | None:
    if _nonzero(material.emission):
        return {"type": "area", "radiance": _rgb(material.emission)}
    return None


def _material_key(color, material) -> tuple:
    return (tuple(_xyz(_surface_colour(color, material))), material.shader, material.kd,
            tuple(_xyz(material.specular)), material.shininess, material.ior, tuple(_xyz(material.emission)),
            tuple(_xyz(material.absorption)), id(material.texture))


def _mesh(mi, name: str, vertices, faces, normals, bsdf: dict, emitter: dict | None):
    """A mi.Mesh from (n, 3) vertices, (m, 3) faces and optional (n, 3) vertex normals,
    with its BSDF and emitter given as plugin dicts."""
    props = mi.Properties()
    props["bsdf"] = mi.load_dict(bsdf)
    if emitter is not None:
        props["emitter"] = mi.load_dict(emitter)
    vertices = np.ascontiguousarray(vertices, dtype=np.float32)
    faces = np.ascontiguousarray(faces, dtype=np.uint32)
    mesh = mi.Mesh(name, len(vertices), len(faces), props=props,
                   has_vertex_normals=normals is not None, has_vertex_texcoords=False)
    params = mi.traverse(mesh)
    # The buffers' own types: mi.Float / mi.UInt32 (flat arrays) in every variant.
    params["vertex_positions"] = type(params["vertex_positions"])(vertices.ravel())
    params["faces"] = type(params["faces"])(faces.ravel())
    if normals is not None:
        params["vertex_normals"] = type(params["vertex_normals"])(
            np.ascontiguousarray(normals, dtype=np.float32).ravel())
    params.update()
    return mesh


def _frame(normal) -> tuple:
    """Unit n and unit t1, t2 with t1 x t2 = n."""
    n = np.asarray(_xyz(normal), dtype=np.float64)
    n /= np.linalg.norm(n)
    a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    t1 = np.cross(a, n)
    t1 /= np.linalg.norm(t1)
    t2 = np.cross(n, t1)
    return n, t1, t2


def _scene_sphere(scene) -> tuple:
    """(centre, radius) of the box around the camera and every bounded shape."""
    from rtfgu.shapes import Disk, Rectangle, Sphere
    from rtfgu.shapes.mesh import MeshTriangle
    from rtfgu.shapes.triangle import Triangle
    points = [_xyz(scene.camera.eye), _xyz(scene.camera.lookat)]
    for shape in scene.shapes:
        if isinstance(shape, (Sphere, Disk)):
            c, r = np.array(_xyz(shape.center)), shape.radius
            points += [c - r, c + r]
        elif isinstance(shape, MeshTriangle):
            points += list(shape.mesh.vertices[[shape.index0, shape.index1, shape.index2]])
        elif isinstance(shape, Triangle):
            points += [_xyz(shape.v0), _xyz(shape.v1), _xyz(shape.v2)]
        elif isinstance(shape, Rectangle):
            points += _rectangle_corners(shape)
    points = np.array(points, dtype=np.float64)
    lo, hi = points.min(axis=0), points.max(axis=0)
    return (lo + hi) / 2, max(float(np.linalg.norm(hi - lo)) / 2, 1e-3)


def _rectangle_corners(shape) -> list:
    """p0, p0 + a, p0 + a + b, p0 + b: the rectangle's corners, counterclockwise about a x b."""
    p0, a, b = (np.array(_xyz(v)) for v in (shape.p0, shape.a, shape.b))
    return [p0, p0 + a, p0 + a + b, p0 + b]


def to_mitsuba(scene, width: int, height: int, spp: int, seed: int = 0, max_depth=None) -> dict:
    """The Mitsuba 3 scene dict (for mi.load_dict) of the rtfgu lecture-layer ``scene`` seen
    by its PinholeCamera on a width x height film with ``spp`` samples per pixel.

    Meshes are built as mi.Mesh objects of the current variant (``mi.set_variant`` first;
    DEFAULT_VARIANT is set if none is), so load the dict in that variant. Anything that has
    no counterpart (see the module docstring) is a ValueError naming it."""
    from rtfgu.cameras import PinholeCamera
    from rtfgu.lights import AreaLight, PointLight
    from rtfgu.shapes import Disk, Plane, Rectangle, Sphere
    from rtfgu.shapes.mesh import MeshTriangle
    from rtfgu.shapes.triangle import Triangle

    mi = _mitsuba()
    scene.validate()
    for name, value in (("width", width), ("height", height), ("spp", spp)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
            raise ValueError("to_mitsuba: %s must be an integer >= 1, got %r" % (name, value))
    camera = scene.camera
    if type(camera) is not PinholeCamera:
        raise ValueError("to_mitsuba: only PinholeCamera is converted, got %s" % type(camera).__name__)
    if not math.isclose(camera.aspect, width / height, rel_tol=1e-6):
        raise ValueError("to_mitsuba: PinholeCamera.aspect %r differs from width / height = %r "
                         "(Mitsuba's pixels are square)" % (camera.aspect, width / height))
    if scene.show_ray_direction:
        raise ValueError("to_mitsuba: Scene.show_ray_direction has no Mitsuba counterpart")
    for i, light in enumerate(scene.lights):
        if not light.casts_shadows():
            raise ValueError("to_mitsuba: scene.lights[%d] casts no shadows (set_shadows(False)), which has no "
                             "Mitsuba counterpart" % i)
    if max_depth is None:
        max_depth = -1
    if isinstance(max_depth, bool) or not isinstance(max_depth, (int, np.integer)) or max_depth < -1:
        raise ValueError("to_mitsuba: max_depth must be None, -1 or an integer >= 0, got %r" % (max_depth,))

    center, radius = _scene_sphere(scene)
    out = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": int(max_depth), "hide_emitters": False},
        "sensor": {
            "type": "perspective",
            "fov_axis": "y",
            "fov": math.degrees(2.0 * math.atan(0.5 / camera.d)),
            "to_world": mi.ScalarTransform4f().look_at(origin=_xyz(camera.eye),
                                                       target=_xyz(camera.lookat),
                                                       up=_xyz(camera.up)),
            "near_clip": 1e-3 * radius,
            "far_clip": 10.0 * PLANE_EXTENT * radius,
            "sampler": {"type": "independent", "sample_count": int(spp), "seed": int(seed)},
            "film": {"type": "hdrfilm", "width": int(width), "height": int(height),
                     "rfilter": {"type": "box"}, "pixel_format": "rgb",
                     "component_format": "float32"},
        },
    }

    groups = {}          # (id(mesh), material key) -> [mesh, color, material, [faces]]
    count = 0
    for i, shape in enumerate(scene.shapes):
        if isinstance(shape, MeshTriangle):
            key = (id(shape.mesh), _material_key(shape.color, shape.material))
            groups.setdefault(key, [shape.mesh, shape.color, shape.material, []])[3].append(shape.face)
            continue
        bsdf, emitter = _bsdf(shape.color, shape.material), _emitter(shape.material)
        if isinstance(shape, Sphere):
            entry = {"type": "sphere", "center": _xyz(shape.center), "radius": float(shape.radius),
                     "bsdf": bsdf}
            if emitter is not None:
                entry["emitter"] = emitter
        elif isinstance(shape, Disk):
            n, t1, t2 = _frame(shape.normal)
            m = np.eye(4)
            m[:3, 0], m[:3, 1], m[:3, 2] = t1 * shape.radius, t2 * shape.radius, n * shape.radius
            m[:3, 3] = _xyz(shape.center)
            entry = {"type": "disk", "to_world": mi.ScalarTransform4f(m.tolist()), "bsdf": bsdf}
            if emitter is not None:
                entry["emitter"] = emitter
        elif isinstance(shape, Triangle):
            entry = _mesh(mi, "triangle_%d" % i, [_xyz(shape.v0), _xyz(shape.v1), _xyz(shape.v2)],
                          [[0, 1, 2]], None, bsdf, emitter)
        elif isinstance(shape, Rectangle):
            entry = _mesh(mi, "rectangle_%d" % i, _rectangle_corners(shape), [[0, 1, 2], [0, 2, 3]], None,
                          bsdf, emitter)
        elif isinstance(shape, Plane):
            n, t1, t2 = _frame(shape.normal)
            p = np.array(_xyz(shape.point))
            c = center - np.dot(center - p, n) * n
            s = PLANE_EXTENT * radius
            corners = [c - s * t1 - s * t2, c + s * t1 - s * t2, c + s * t1 + s * t2, c - s * t1 + s * t2]
            entry = _mesh(mi, "plane_%d" % i, corners, [[0, 1, 2], [0, 2, 3]], None, bsdf, emitter)
        else:
            raise ValueError("to_mitsuba: scene.shapes[%d] is a %s, which is not converted"
                             % (i, type(shape).__name__))
        out["shape_%04d" % count] = entry
        count += 1

    for (_, _), (mesh, color, material, faces) in groups.items():
        tri = mesh.faces[np.asarray(faces, dtype=np.int64)]
        used, local = np.unique(tri, return_inverse=True)
        normals = None if mesh.normals is None else mesh.normals[used]
        out["shape_%04d" % count] = _mesh(mi, "mesh_%d" % count, mesh.vertices[used],
                                          local.reshape(tri.shape), normals,
                                          _bsdf(color, material), _emitter(material))
        count += 1

    shape_ids = {id(shape) for shape in scene.shapes}
    for i, light in enumerate(scene.lights):
        if type(light) is AreaLight:
            if id(light.shape) not in shape_ids:
                raise ValueError("to_mitsuba: scene.lights[%d] is an AreaLight whose shape is not in "
                                 "scene.shapes" % i)
            continue                     # its shape's emission is the area emitter
        if type(light) is not PointLight:
            raise ValueError("to_mitsuba: scene.lights[%d] is a %s; only PointLight and AreaLight "
                             "are converted" % (i, type(light).__name__))
        if not light.inverse_square:
            raise ValueError("to_mitsuba: scene.lights[%d] is the book's PointLight (inverse_square = False), "
                             "which Mitsuba's point light is not" % i)
        out["light_%04d" % i] = {"type": "point", "position": _xyz(light.position),
                                 "intensity": _rgb(light.intensity)}
    if _nonzero(scene.background):
        out["background"] = {"type": "constant", "radiance": _rgb(scene.background)}
    return out


def render_mitsuba(scene, width: int, height: int, spp: int, passes: int = 16, max_depth=None,
                   variant: str = DEFAULT_VARIANT, progress=None) -> tuple:
    """(mean, stderr): float64 arrays (height, width, 3), row 0 at the top, linear radiance
    (no gamma, no tone mapping). ``passes`` (>= 2, dividing spp) independent renders of
    spp / passes samples each, with seeds 0 .. passes - 1; mean is their mean and stderr
    their per-pixel sample standard deviation (ddof 1) / sqrt(passes), the standard error
    of the mean. ``progress(done, passes)`` is called after each pass if given.

    variant: the Mitsuba variant. "scalar_rgb" (the default) renders on all cores through
    Mitsuba's own thread pool. "llvm_ad_rgb" is about twice as fast but needs a libLLVM
    newer than Debian 12's libLLVM 15, on which its path tracing kernel aborts the process
    (LLVM "Cannot select: fminimum"); with libLLVM 19 (DRJIT_LIBLLVM_PATH) it works."""
    if isinstance(passes, bool) or not isinstance(passes, (int, np.integer)) or passes < 2:
        raise ValueError("render_mitsuba: passes must be an integer >= 2, got %r" % (passes,))
    if isinstance(spp, bool) or not isinstance(spp, (int, np.integer)) or spp < passes or spp % passes:
        raise ValueError("render_mitsuba: spp must be a multiple of passes (%d), got %r" % (passes, spp))
    mi = _mitsuba(variant)
    per_pass = int(spp) // int(passes)
    mscene = mi.load_dict(to_mitsuba(scene, width, height, per_pass, seed=0, max_depth=max_depth))
    # Welford's running mean and sum of squared deviations, per pixel, in float64.
    mean = np.zeros((height, width, 3), dtype=np.float64)
    m2 = np.zeros_like(mean)
    for k in range(passes):
        image = np.array(mi.render(mscene, spp=per_pass, seed=k), dtype=np.float64)
        if image.shape != mean.shape:
            raise ValueError("render_mitsuba: Mitsuba returned shape %s, not %s" % (image.shape, mean.shape))
        delta = image - mean
        mean += delta / (k + 1)
        m2 += delta * (image - mean)
        if progress is not None:
            progress(k + 1, passes)
    stderr = np.sqrt(m2 / (passes - 1) / passes)
    if not (np.all(np.isfinite(mean)) and np.all(np.isfinite(stderr))):
        raise ValueError("render_mitsuba: Mitsuba produced non-finite pixels")
    return mean, stderr
