"""The assignments: which marked solution blocks each one asks for, and what its README says.

A block is a ``### BEGIN SOLUTION`` / ``### END SOLUTION`` region of the lecture layer (the
nbgrader convention). It is identified by the file it sits in (relative to the ``rtfgu``
package) and the function around it, so the markers in the source stay plain nbgrader
markers and this table says which assignment each belongs to and what its TODO text is.

The order is that of both courses: lecture 01 (Float3, Ray, orthographic camera, plane,
sphere) and 02562 weeks 1-3 (pinhole camera, triangle, Kepler and Lambert, shadows, Phong,
mirror, refraction), then the intersection functions again in WGSL, then 02562 worksheet 3's
texture lookup (Suffern ch. 29), then bounding boxes and the BVH (Suffern ch. 19 and 22,
02562 worksheet 6), then the diffuse bounce of the path tracer (Suffern ch. 7 and 26, 02562
worksheet 7).
"""
from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Block:
    file: str       # relative to the rtfgu package, e.g. "shapes/sphere.py"
    qualname: str   # the function around the block, e.g. "Sphere.intersect_p"
    todo: str       # what to write, in a few lines (becomes the stub's comment)
    stub: str = ""  # WGSL only: the stub's code (it names the TODO, so it does not compile)


@dataclass(frozen=True)
class Assignment:
    id: str                     # aNN_name
    title: str
    blocks: tuple
    task: str                   # README: what to do (markdown)
    formulas: str               # README: the formulas, each with the slide it comes from
    slides: tuple               # slide titles (lecture deck, slide)
    images: tuple = ()          # homework scene names (rtfgu.scenes) to hand in as PNG
    language: str = "python"
    time_limit: float = 10.0    # per test, seconds (the CLI may override it)
    extra: str = field(default="")

    @property
    def short(self) -> str:
        return self.id.split("_", 1)[0]

    @property
    def number(self) -> int:
        return int(self.short[1:])

    @property
    def files(self) -> tuple:
        """The files a student hands in, relative to the rtfgu package, in block order."""
        seen = []
        for block in self.blocks:
            if block.file not in seen:
                seen.append(block.file)
        return tuple(seen)


A01 = Assignment(
    id="a01_float3_ray",
    title="Float3 and Ray",
    blocks=(
        Block("float3.py", "Float3.__add__", "Return the componentwise sum self + o as a new Float3."),
        Block("float3.py", "Float3.__neg__", "Return the Float3 with every component negated."),
        Block("float3.py", "Float3.__sub__", "Return the componentwise difference self - o as a new Float3."),
        Block("float3.py", "Float3.__mul__",
              "o is a Float3 (multiply componentwise) or a number (scale every component);\n"
              "return a new Float3 either way."),
        Block("float3.py", "Float3.__truediv__",
              "o is a Float3 (divide componentwise) or a number: the slide computes\n"
              "inv = 1 / o once and multiplies every component by it."),
        Block("float3.py", "Float3.length_squared", "Return x*x + y*y + z*z."),
        Block("float3.py", "Float3.length", "Return the square root of length_squared()."),
        Block("float3.py", "normalize", "Return v divided by its length (a unit vector)."),
        Block("float3.py", "dot", "Return v1.x*v2.x + v1.y*v2.y + v1.z*v2.z (a number)."),
        Block("float3.py", "cross",
              "Return the Float3 (v1.y*v2.z - v1.z*v2.y, v1.z*v2.x - v1.x*v2.z, v1.x*v2.y - v1.y*v2.x)."),
        Block("ray.py", "Ray.__call__", "Return the point origin + direction * t (a new Float3)."),
    ),
    task=("Write the vector arithmetic of `Float3` (sum, difference, negation, componentwise and\n"
          "scalar products and quotients, length) and the functions `normalize`, `dot` and `cross`,\n"
          "then the point of a ray at parameter t. Every operation returns a new `Float3` and leaves\n"
          "its operands unchanged. `*` is componentwise (or by a number); the dot and cross\n"
          "products are the named functions."),
    formulas=("- a + b = (a.x + b.x, a.y + b.y, a.z + b.z); a * b componentwise; a * f = (a.x f, a.y f, a.z f)\n"
              "- a / f = a * (1 / f) (the slide computes `inv = 1.0f / x` once)\n"
              "- |a|^2 = a.x^2 + a.y^2 + a.z^2, |a| = sqrt(|a|^2), normalize(a) = a / |a|\n"
              "- a . b = a.x b.x + a.y b.y + a.z b.z\n"
              "- a x b = (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x)\n"
              "- ray: r(t) = o + t d, for tmin <= t < tmax"),
    slides=("Lecture 01: Float3 Structure (six slides)", "Lecture 01: Ray",
            "02562 week 1: Rays in theory and in practice"),
)

A02 = Assignment(
    id="a02_cameras",
    title="Cameras: orthographic and pinhole ray generation",
    blocks=(
        Block("cameras/orthographic.py", "OrthographicCamera.gen_ray",
              "Map sx, sy from [-1, 1] to [0, 1] (0.5 + s / 2), then to x in [left, right] and\n"
              "y in [bottom, top]. Return Ray(Float3(x, y, hither), Float3(0, 0, -1), 0.00001, yon - hither)."),
        Block("cameras/pinhole.py", "PinholeCamera.gen_ray",
              "u = sx * aspect * 0.5 and w = sy * 0.5 (the slide's uv); q = b1 * u + b2 * w + v * d.\n"
              "Return a Ray from a copy of the eye along normalize(q)."),
    ),
    task=("Write `gen_ray(sx, sy)` of both cameras. The renderer calls it once per pixel with the\n"
          "pixel's centre on the image plane: sx = 2 (ix + 0.5) / width - 1 and likewise sy, so\n"
          "(-1, -1) is the bottom left corner of the image and the camera must not add any offset\n"
          "of its own. The orthographic camera sends parallel rays along -z; the pinhole camera\n"
          "sends every ray from the eye through the image plane at distance d. Its basis\n"
          "v, b1, b2 is computed for you in `__init__`."),
    formulas=("- Orthographic (lecture 01, \"Orthographic Camera\"): x = left + (right - left)(0.5 + sx / 2),\n"
              "  y = bottom + (top - bottom)(0.5 + sy / 2); origin (x, y, hither), direction (0, 0, -1),\n"
              "  tmin = 0.00001, tmax = yon - hither\n"
              "- Pinhole (02562 week 1, get_camera_ray): v = normalize(lookat - eye), b1 = normalize(v x up),\n"
              "  b2 = b1 x v; q = b1 u + b2 w + v d with (u, w) = (sx * aspect * 0.5, sy * 0.5);\n"
              "  direction = normalize(q), origin = eye"),
    slides=("Lecture 01: Camera", "Lecture 01: Orthographic Camera (two slides)",
            "Lecture 01: Rendering a Scene",
            "02562 week 1: Rays in theory and in practice; main_fs (uv from coords)"),
    images=("default_ray_directions",),
)

A03 = Assignment(
    id="a03_intersections",
    title="Ray-plane, ray-sphere and ray-triangle intersection, and the closest hit",
    blocks=(
        Block("shapes/plane.py", "Plane.intersect_p",
              "t = ((a - o) . n) / (d . n), written as on the slide with A = o . n, B = d . n,\n"
              "C = a . n. A ray parallel to the plane (B == 0) misses. Accept t only if\n"
              "tmin <= t < tmax; then set ray.tmax = t and return True, else return False."),
        Block("shapes/plane.py", "Plane.normal_at", "Return the plane's normal as a unit vector."),
        Block("shapes/sphere.py", "Sphere.intersect_p",
              "a = d . d, b = 2 (o - c) . d, c = (o - c) . (o - c) - r^2, disc = b^2 - 4ac.\n"
              "No hit if disc < 0. Otherwise try t = (-b - sqrt(disc)) / 2a, then (-b + sqrt(disc)) / 2a:\n"
              "the first with tmin <= t < tmax is the hit (set ray.tmax = t, return True)."),
        Block("shapes/sphere.py", "Sphere.normal_at",
              "Return the unit outward normal at a point on the sphere: (position - center) / radius."),
        Block("shapes/triangle.py", "Triangle.intersect_p",
              "With a = v0 - o and w = ray.direction: t = (a . n) / (w . n),\n"
              "beta = ((a x w) . e1) / (w . n), gamma = -((a x w) . e0) / (w . n).\n"
              "Hit if tmin <= t < tmax, beta >= 0, gamma >= 0 and beta + gamma <= 1: set ray.tmax = t."),
        Block("shapes/triangle.py", "Triangle.normal_at", "Return the triangle's normal n = e0 x e1 as a unit vector."),
    ),
    task=("Write `intersect_p(ray)` of the plane, the sphere and the triangle, and their\n"
          "`normal_at(position)`. `intersect_p` returns True only for a hit with\n"
          "tmin <= t < tmax, and then shrinks `ray.tmax` to t; it changes nothing on a miss. The\n"
          "scene calls it on every shape in turn, so the last shape that reports a hit is the\n"
          "closest one (hidden-surface removal, the slide's render loop). Do not assume the ray\n"
          "direction has unit length: keep `a = d . d` in the quadratic."),
    formulas=("- Plane (lecture 01, \"Ray-Plane Intersection\"): t = ((a - o) . n) / (d . n)\n"
              "- Sphere (lecture 01, \"Ray-Sphere Intersection\"): a t^2 + b t + c = 0 with a = d . d,\n"
              "  b = 2 (o - c) . d, c = (o - c) . (o - c) - r^2; the discriminant b^2 - 4ac < 0 means no hit;\n"
              "  t = (-b -+ sqrt(b^2 - 4ac)) / 2a, the least t in [tmin, tmax) wins\n"
              "- Triangle (02562, \"Ray-triangle intersection\"): e0 = v1 - v0, e1 = v2 - v0, n = e0 x e1,\n"
              "  t' = ((v0 - o) . n) / (w . n), beta = ((v0 - o) x w) . e1 / (w . n),\n"
              "  gamma = -((v0 - o) x w) . e0 / (w . n); hit if beta >= 0, gamma >= 0, beta + gamma <= 1"),
    slides=("Lecture 01: Class Shape", "Lecture 01: Plane, Ray-Plane Intersection",
            "Lecture 01: Sphere, Ray-Sphere Intersection (five slides)",
            "Lecture 01: Rendering a Scene (the closest hit)",
            "02562 week 2: Ray-plane, ray-triangle and ray-sphere intersection"),
    images=("lecture01_flat_colors", "default_flat_colors"),
)

A04 = Assignment(
    id="a04_diffuse",
    title="Diffuse shading with a point light: Kepler, Lambert and ambient",
    blocks=(
        Block("lights/point_light.py", "PointLight.get_direction",
              "Return the unit vector from the hit point sr.position toward the light: (p - x) / |p - x|."),
        Block("lights/point_light.py", "PointLight.L",
              "Kepler's inverse square law: return self.intensity / |p - x|^2 (x = sr.position)."),
        Block("brdfs/lambertian.py", "Lambertian.rho",
              "The albedo kd cd: self.surface_color(self.cd, sr) * self.kd (the surface colour is cd, or the\n"
              "shape's or texture's colour at the hit where cd is None)."),
        Block("brdfs/lambertian.py", "Lambertian.f", "f_r = kd cd / pi: self.rho(sr) divided by pi."),
        Block("materials/matte.py", "Matte.ambient",
              "Return L_e + ka cd L_a: self.get_Le(sr) + self.ambient_brdf.rho(sr, wo) * sr.scene.ambient_light.L(sr)."),
        Block("materials/matte.py", "Matte.direct_light",
              "For each light of sr.scene.lights: wi = light.get_direction(sr), L_i = light.incident(sr) (skip an\n"
              "all-zero L_i); ndotwi = n . wi with n = sr.normal; skip the light unless ndotwi > 0. If\n"
              "light.casts_shadows(), skip it when light.in_shadow(Ray(sr.position, wi), sr) (in_shadow is\n"
              "assignment 5). Otherwise L += self.f(sr, wo, wi) * L_i * ndotwi. Return L."),
    ),
    task=("Write the point light (Kepler's inverse square law), the Lambertian BRDF and the light\n"
          "loop of the Matte material: the diffusely reflected light by Lambert's cosine law plus\n"
          "the ambient term. The light's direction points from the surface toward the light and has\n"
          "unit length. A light below the surface (n . w_i <= 0) adds nothing. `Matte.shade` (given)\n"
          "is `direct_light(sr, wo, ambient(sr, wo))`; `Phong` and `PathTrace` reuse your light loop\n"
          "with their own BRDF (`self.f`)."),
    formulas=("- Kepler's inverse square law (02562, \"Kepler's inverse square law\"): L_i = I / |p - x|^2\n"
              "- Lambertian BRDF (Suffern ch. 13): f_r = kd cd / pi, albedo rho = kd cd\n"
              "- Lambert's cosine law (02562, \"Lambert's cosine law\"): L_r,d = f_r L_i (n . w_i)\n"
              "- Matte::shade (Suffern ch. 14; 02562, \"Sampling light in the shader\"):\n"
              "  L_o = L_e + ka cd L_a + sum over lights of f_r L_i (n . w_i); the 02562 scene's\n"
              "  rho_d = 0.9 and L_a = 0.1 of the colour are kd = 0.9 and ka = 0.1 under a white Ambient light"),
    slides=("02562: Kepler's inverse square law", "02562: Lambert's cosine law",
            "02562: Sampling light in the shader",
            "Suffern ch. 13-14: Lambertian (f, rho), Matte::shade, PointLight (get_direction, L)"),
    images=("default_lambertian",),
)

A05 = Assignment(
    id="a05_shadows_phong_mirror_refraction",
    title="Shadows, Phong, mirror and refraction",
    blocks=(
        Block("lights/light.py", "Light.in_shadow",
              "Set ray.tmin = SPAWN_EPSILON and ray.tmax = self.distance(sr) - SPAWN_EPSILON, then return True if\n"
              "any shape of sr.scene.shapes hits the ray. The offsets keep the ray from hitting the surface it\n"
              "leaves (shadow acne) and from hitting the light's own position."),
        Block("brdfs/glossy_specular.py", "GlossySpecular.f",
              "cos_theta = n . wi, w_r = n * (2 cos_theta) - wi, cos_r = max(wo . w_r, 0); return\n"
              "self.specular * ((e + 2) / (2 pi) * cos_r^e) with e = self.exp (the normalised lobe), or\n"
              "self.specular * cos_r^e where self.normalized is False."),
        Block("brdfs/perfect_specular.py", "reflect", "Return the mirror direction -wo + 2 (n . wo) n."),
        Block("materials/reflective.py", "Reflective.shade",
              "wo = -sr.ray.direction; L = self.ambient(sr, wo), then self.direct_light(sr, wo, L) if\n"
              "self.reflects_light(). fr, wi, pdf = self.reflective_brdf.sample_f(sr, wo); trace\n"
              "Ray(sr.position, wi, SPAWN_EPSILON) with sr.scene.tracer.trace_ray(ray, sr.depth + 1) and return\n"
              "L + fr * L_r * specular_scale(|n . wi|, pdf)."),
        Block("btdfs/perfect_transmitter.py", "PerfectTransmitter.transmitted_direction",
              "cos_i = -(d . n). Entering (cos_i >= 0): eta = 1 / ior. Leaving: eta = ior, flip n and cos_i.\n"
              "sin2_t = eta^2 (1 - cos_i^2); if sin2_t > 1 return the mirror direction d + n (2 cos_i) (total\n"
              "internal reflection), else d * eta + n * (eta cos_i - sqrt(1 - sin2_t))."),
    ),
    task=("Write the shadow ray of a light, the glossy lobe of the Phong material, and the two\n"
          "directions a ray goes on in: the mirror's and the refracted one (Snell's law), and the\n"
          "Reflective material's shade, which traces its reflected ray one level deeper through the\n"
          "scene's tracer (Whitted). `Transparent.shade` (given) uses your refraction and reflection."),
    formulas=("- Shadow ray (02562 week 2): from x toward the light, t in [eps, dist - eps]\n"
              "- Phong (02562 worksheet 3): f_r = kd cd / pi + ks cs (e + 2) / (2 pi) max(w_o . w_r, 0)^e,\n"
              "  w_r = 2 (n . w_i) n - w_i (Suffern ch. 15's lobe has no (e + 2) / (2 pi))\n"
              "- Mirror (Suffern ch. 24): w_r = -w_o + 2 (n . w_o) n; L_o = Phong's + kr cr L(w_r)\n"
              "- Refraction (Snell's law, eta = n1 / n2): cos_t = sqrt(1 - eta^2 (1 - cos_i^2)),\n"
              "  t = eta d + (eta cos_i - cos_t) n; no real cos_t means total internal reflection"),
    slides=("02562: The signature of an intersection function and that of a shader (shade switch)",
            "02562: Intersecting with the scene and tracing a path",
            "02562 week 2: shadows; worksheet 3: Phong, mirror, refraction",
            "Suffern ch. 15, 24, 27: GlossySpecular, Reflective, PerfectTransmitter"),
    images=("default_lambertian_shadows", "default_phong_sphere", "default_mirror_sphere",
            "default_refractive_sphere", "default_glossy_sphere"),
)

def _wgsl_block(name, todo):
    return Block("wgsl/%s.wgsl" % name, name, todo,
                 stub="return TODO_a06_%s;  // not written yet: replace this line with your code" % name)


A06 = Assignment(
    id="a06_wgsl_intersections",
    title="The intersection functions again, in WGSL",
    language="wgsl",
    time_limit=60.0,
    blocks=(
        _wgsl_block("intersect_plane",
                    "t' = ((position - r.origin) . normal) / (r.direction . normal); a ray parallel to the\n"
                    "plane misses. On a hit with r.tmin <= t' < r.tmax set (*hit).has_hit = true,\n"
                    "dist = t', position = r.origin + r.direction * t', normal = normalize(normal);\n"
                    "return true. Otherwise return false and leave *hit alone."),
        _wgsl_block("intersect_triangle",
                    "a = v0 - r.origin, t' = (a . n) / (w . n), beta = ((a x w) . e1) / (w . n),\n"
                    "gamma = -((a x w) . e0) / (w . n). Hit if t' in [tmin, tmax), beta >= 0, gamma >= 0\n"
                    "and beta + gamma <= 1: fill *hit as for the plane (normal = normalize(n))."),
        _wgsl_block("intersect_sphere",
                    "a = w . w, b = 2 (o - c) . w, c = (o - c) . (o - c) - r^2, disc = b^2 - 4ac.\n"
                    "No hit if disc < 0; else the first of (-b - sqrt(disc)) / 2a and (-b + sqrt(disc)) / 2a\n"
                    "in [tmin, tmax): fill *hit, normal = normalize(position - center)."),
    ),
    task=("Write the three intersection functions of the WGSL ray tracer (`rtfgu/wgsl/`), with\n"
          "the slide's signatures: they take the ray by value and a pointer to the HitInfo, and on a\n"
          "hit fill `has_hit`, `dist`, `position` and `normal` and return true. `intersect_scene`\n"
          "(given) calls them and shrinks the ray's tmax. The triangle arrives as v0 and the\n"
          "precomputed e0, e1 and n of `rtfgu.layout`. The grader runs your functions on the GPU\n"
          "adapter through wgpu (on a machine without a GPU, Mesa's llvmpipe), in float32."),
    formulas=A03.formulas,
    slides=("02562: Ray-plane intersection, Ray-triangle intersection (two slides), Ray-sphere intersection",
            "02562: The signature of an intersection function and that of a shader"),
    images=("default_flat_colors",),
    extra=("Until a function is written its stub names an undefined `TODO_a06_...`, so the shader does not\n"
           "compile; the test of that function says so. Render with your WGSL: `python -m rtfgu render\n"
           "default_flat_colors --backend wgpu` from a folder where your copy of the package comes first."),
)

A07 = Assignment(
    id="a07_textures",
    title="Texture lookup: addressing (repeat, clamp) and nearest and bilinear filtering",
    blocks=(
        Block("textures/image_texture.py", "ImageTexture.texel",
              "Address the indices: \"repeat\" wraps them (i % width, j % height; Python's % by a positive\n"
              "width is never negative), \"clamp\" holds them at the edge (min(max(i, 0), width - 1), likewise j).\n"
              "Return Float3 of self.texels[j, i] (row j first: the array is (height, width, 3))."),
        Block("textures/image_texture.py", "ImageTexture.get_color",
              "Address (u, v): repeat u = u - floor(u) (likewise v); clamp u, v to [0, 1].\n"
              "To texel space: x = u * width, y = (1 - v) * height (row 0 is the top, v = 1).\n"
              "nearest: return texel(floor(x), floor(y)).\n"
              "bilinear: texel centres sit at whole numbers + 0.5, so x -= 0.5, y -= 0.5; i = floor(x),\n"
              "j = floor(y), fx = x - i, fy = y - j; mix texel(i, j) and texel(i + 1, j) by fx, likewise\n"
              "row j + 1, then the two rows by fy. texel does the addressing of i + 1 and j + 1."),
    ),
    task=("Write the lookup of an image texture: `texel(i, j)` addresses a texel, wrapping the\n"
          "indices (repeat) or holding them at the edge (clamp), and `get_color(u, v)` turns texture\n"
          "coordinates into a colour with the texture's filter: nearest (the texel that holds\n"
          "(u, v)) or bilinear (the four texels around it, weighted by distance). (u, v) = (0, 0) is\n"
          "the image's bottom-left corner and (1, 1) its top-right, while the texels are stored row 0\n"
          "at the top, as in the file: v = 1 is the top row. `self.texels` (height x width x 3),\n"
          "`self.width`, `self.height`, `self.filter` (\"nearest\" or \"bilinear\") and `self.address`\n"
          "(\"repeat\" or \"clamp\") are set for you. The shape gives (u, v) and `color_at` scales them\n"
          "(given); the shader uses the colour in place of the material's own."),
    formulas=("- Texel centres (02562 worksheet 3, texture filtering; Suffern ch. 29, \"Image Textures\"):\n"
              "  texel (i, j), column i and row j from the top, has its centre at\n"
              "  ((i + 0.5) / width, 1 - (j + 0.5) / height); (u, v) = (0, 0) is the bottom-left corner\n"
              "- Texel space: x = u * width, y = (1 - v) * height\n"
              "- Addressing (worksheet 3): repeat u' = u - floor(u), i' = i mod width (likewise v, j);\n"
              "  clamp u' = min(max(u, 0), 1), i' = min(max(i, 0), width - 1)\n"
              "- Nearest (worksheet 3; Suffern ch. 29): the texel (floor(x), floor(y))\n"
              "- Bilinear (worksheet 3): x' = x - 0.5, y' = y - 0.5, i = floor(x'), j = floor(y'),\n"
              "  fx = x' - i, fy = y' - j;\n"
              "  c = (1 - fy) ((1 - fx) t(i, j) + fx t(i + 1, j)) + fy ((1 - fx) t(i, j + 1) + fx t(i + 1, j + 1))\n"
              "- sRGB: the image file holds sRGB values; `read_texture` (given) decodes them to linear\n"
              "  (IEC 61966-2-1: c / 12.92 for c <= 0.04045, else ((c + 0.055) / 1.055)^2.4), so\n"
              "  `self.texels` are linear and the filters mix linear colours, as every colour in rtfgu"),
    slides=("02562 worksheet 3: texture mapping a plane, texture addressing (repeat, clamp-to-edge) and "
            "filtering (nearest, linear)",
            "Suffern ch. 29: Texture Mapping (\"Image Textures\", the texel of (u, v))"),
    images=("default_texture_nearest_repeat", "default_texture_nearest_clamp",
            "default_texture_bilinear_repeat", "default_texture_bilinear_clamp"),
    extra=("The images are worksheet 3's textured plane (the 02562 default scene, Lambertian with shadows,\n"
           "texture scale 0.2) with a 16 x 16 image of coloured tiles; they need assignments 1-5 (your own\n"
           "or the revealed solutions). Compare the four: nearest shows each texel as a square, bilinear\n"
           "blends them; repeat tiles the plane, clamp stretches the edge texels to the horizon."),
)

A08 = Assignment(
    id="a08_bvh",
    title="Bounding boxes and the BVH: the slab test and nearest-first traversal",
    blocks=(
        Block("accelerators/bbox.py", "BBox.hit",
              "The slab test. Start with t0, t1 = ray.tmin, ray.tmax. For each axis a in 0, 1, 2 (a Float3\n"
              "indexes as v[a]), with o = ray.origin[a] and w = ray.direction[a]:\n"
              "if w == 0 the ray stays in the slab for every t or for none: return math.inf when o < p0[a]\n"
              "or o > p1[a], else go on with the next axis (no division). Otherwise\n"
              "t_near = (p0[a] - o) / w, t_far = (p1[a] - o) / w, swapped when t_near > t_far (w < 0);\n"
              "t_far *= WIDEN; t0 = max(t0, t_near), t1 = min(t1, t_far); return math.inf as soon as t0 > t1.\n"
              "Return t0, where the ray enters the box. The ray is not changed."),
        Block("shapes/box.py", "Box.intersect_p",
              "Suffern's axis-aligned box (ch. 19.5, Box::hit): the slab test again, now for a shape. Start with\n"
              "t0, t1 = -inf, inf; per axis, a ray parallel to the slab (d == 0) misses if its origin is outside\n"
              "[p0, p1] on that axis and is not limited by it otherwise; else t_near and t_far are where it crosses\n"
              "the slab's planes (swapped when the direction is negative); t0 is the largest t_near, t1 the\n"
              "smallest t_far. The ray meets the box when t0 < t1: at t0, or at t1 if t0 < ray.tmin (it starts\n"
              "inside). A hit needs tmin <= t < tmax; then set ray.tmax = t and return True."),
        Block("accelerators/bvh.py", "BVH.intersect",
              "best = -1; an empty BVH (self.root is None) returns it. Keep a stack, starting with [self.root].\n"
              "Pop a node; skip it when the ray misses its box (node.bbox.hit(ray) is math.inf) or enters it\n"
              "beyond the nearest hit so far (> ray.tmax).\n"
              "Leaf: for k in node.first .. node.first + node.count - 1, shape i = self.order[k]: if best < 0\n"
              "or i > best, a hit of self.shapes[i].intersect_p(ray) makes best = i; if i < best (an earlier\n"
              "shape, which wins an equal t) raise ray.tmax to math.nextafter(ray.tmax, math.inf) first and\n"
              "put it back if the shape misses. Inner node: push the child whose box the ray enters later,\n"
              "then the nearer one (popped first). When the stack is empty, return best."),
    ),
    task=("Write the slab test of an axis-aligned bounding box, `BBox.hit(ray)`, and the traversal of\n"
          "the bounding volume hierarchy, `BVH.intersect(ray)`; the BVH's build (the binned surface area\n"
          "heuristic) is given. `BBox.hit` returns the t at which the ray enters the box within\n"
          "[tmin, tmax] (tmin itself when the ray starts inside), or `math.inf` when it misses, and\n"
          "changes nothing. The box is closed: a ray along a face or through an edge or a corner hits it.\n"
          "`BVH.intersect` returns the number of the shape hit (its place in the list the BVH was built\n"
          "from) with `ray.tmax` shrunk to its t, or -1 with `ray.tmax` as it was. It must find exactly\n"
          "what the scene's loop over all shapes finds: the least t in [tmin, tmax), and of equal ts the\n"
          "earlier shape, in whatever order the tree meets them. The first hit found is not always the\n"
          "nearest: keep going until every node that the ray enters before `ray.tmax` has been visited."),
    formulas=("- Slab test (Kay and Kajiya 1986, in the form of Williams et al. 2005, \"An Efficient and Robust\n"
              "  Ray-Box Intersection Algorithm\"; Suffern ch. 19, \"Bounding Boxes\"): along axis a the ray is in\n"
              "  the slab p0[a] <= o[a] + t w[a] <= p1[a] for t between t_near = (p0[a] - o[a]) / w[a] and\n"
              "  t_far = (p1[a] - o[a]) / w[a], swapped when w[a] < 0; it is in the box for\n"
              "  t0 = max(tmin, t_near over a) <= t <= t1 = min(tmax, t_far over a): a hit at t0 if t0 <= t1\n"
              "- w[a] = 0: the ray is in the slab for every t if p0[a] <= o[a] <= p1[a], for none otherwise\n"
              "- Widening (PBRT-v4 section 6.1.2, \"Ray-Bounds Intersections\"): t_far *= 1 + 2 gamma_3 with\n"
              "  gamma_n = n u / (1 - n u) and u = 2^-53 (`WIDEN`), so that rounding never makes the box test\n"
              "  miss a ray that exactly touches the box, or a hit the shape's own test finds\n"
              "- Traversal (Suffern ch. 22 accelerates with a grid, PBRT-v4 section 7.3 with a BVH): visit the\n"
              "  nearer child's box first and skip a node whose box the ray enters beyond the nearest hit so\n"
              "  far (t_enter > ray.tmax); the closest hit is the least t, ties to the earlier shape"),
    slides=("Suffern ch. 19: Bounding Boxes (the ray-box slab test)",
            "Suffern ch. 22: acceleration schemes (grids; why a ray need not test every object)",
            "02562 worksheet 6: bounding volume hierarchy (BVH) for triangle meshes"),
    extra=("The tests build scenes of spheres and triangles with the given `BVH(shapes)` (the build sits\n"
           "above `intersect` in `rtfgu/accelerators/bvh.py`: a node's `bbox`, `left` and `right`, a leaf's\n"
           "shapes `order[first:first + count]`) and compare your traversal with the scene's loop over all\n"
           "shapes; they need assignments 1 and 3 (your own or the revealed solutions). `BBox.hit`'s tests\n"
           "need only assignment 1. There is no image to hand in."),
)

A09 = Assignment(
    id="a09_path_tracing",
    title="Cosine-weighted hemisphere sampling and one bounce of diffuse interreflection",
    blocks=(
        Block("sampling/maps.py", "hemisphere_map",
              "Suffern's map of (x, y) in [0, 1)^2 to a direction about +z with density\n"
              "(e + 1) / (2 pi) cos^e(theta): phi = 2 pi x, cos(theta) = (1 - y)^(1 / (e + 1)),\n"
              "sin(theta) = sqrt(1 - cos^2(theta)); return Float3(sin(theta) cos(phi), sin(theta) sin(phi), cos(theta))."),
        Block("brdfs/lambertian.py", "Lambertian.sample_f",
              "Draw w_i cosine-weighted about n = sr.normal: about(n, hemisphere_map(u, v, 1.0)) turns a direction\n"
              "about +z into one about n. Its density is pdf = (n . w_i) / pi. Return (self.f(sr, wo, w_i), w_i, pdf)."),
    ),
    task=("Write the two functions that make PathTrace's diffuse bounce: Suffern's map of a point of\n"
          "the unit square to the hemisphere, with density proportional to cos^e(theta)\n"
          "(`hemisphere_map(x, y, e)`; e = 1 is the cosine-weighted hemisphere, e = 0 the uniform one,\n"
          "larger e a Phong lobe), and `Lambertian.sample_f(sr, wo, u, v)`, which draws the direction a path\n"
          "takes after a diffuse surface and says with which density it drew it. PathTrace (given)\n"
          "multiplies the path's throughput by f (n . w_i) / pdf: any density gives the right image on\n"
          "average as long as pdf is the density you drew with, and the cosine-weighted one gives the\n"
          "least noise. The tests are statistical: they draw many directions with your code and test\n"
          "their distribution (chi-square) and the mean of f (n . w_i) / pdf, and they render a sphere\n"
          "in the white furnace (exactly rho in expectation) and the Cornell box lit by a point light\n"
          "under its ceiling, with the direct light and one bounce of diffuse interreflection, and\n"
          "compare them with the truth or the reference image within the Monte Carlo error. Two tests\n"
          "hold the contract itself: hemisphere_map is Suffern's map, a function of (x, y, e) alone (the\n"
          "same point twice gives the same direction, Suffern's), and the pdf sample_f returns is the\n"
          "density of the directions it draws, tested cell by cell over the hemisphere and, for\n"
          "cosine-weighted directions, at every direction."),
    formulas=("- Hemisphere map (Suffern ch. 7, \"Mapping Samples to a Hemisphere\"): phi = 2 pi x,\n"
              "  cos(theta) = (1 - y)^(1 / (e + 1)), density (e + 1) / (2 pi) cos^e(theta) per unit solid angle;\n"
              "  e = 1: cos(theta) = sqrt(1 - y), density cos(theta) / pi\n"
              "- Lambertian BRDF (Suffern ch. 13): f_r = rho / pi\n"
              "- The Monte Carlo estimator of the reflected light (Suffern ch. 26; 02562 worksheet 7):\n"
              "  L_r = mean of f_r L_i(w_i) (n . w_i) / pdf(w_i); with pdf = (n . w_i) / pi the weight\n"
              "  f_r (n . w_i) / pdf is rho"),
    slides=("Suffern ch. 7: Mapping Samples to a Hemisphere",
            "Suffern ch. 26: Global Illumination (Lambertian::sample_f, the path tracer)",
            "02562 worksheet 7: progressive path tracing, cosine-weighted hemisphere sampling"),
    time_limit=60.0,
    extra=("The Cornell box test renders 20 x 20 pixels at 64 samples with the lecture layer in pure\n"
           "Python, about 10 s on one core; its reference is the mean of 16,384 samples per pixel from the\n"
           "course's renderer. A correct image differs from it by noise only. A correct sampler other than\n"
           "the cosine-weighted one (the uniform hemisphere with its own pdf 1 / (2 pi)) passes too, and the\n"
           "message says how much noisier it is. The tests need assignments 1-5 (your own or the revealed\n"
           "solutions). There is no image to hand in."),
)

A10 = Assignment(
    id="a10_samplers",
    title="Samplers: multi-jittered points and the concentric map to the disk",
    blocks=(
        Block("sampling/multi_jittered.py", "MultiJittered.generate_samples",
              "Append num_sets sets of n^2 = num_samples points (Suffern ch. 5, \"Multi-Jittered Sampling\"):\n"
              "start every set in the canonical arrangement, the point of grid cell (row i, column j) in\n"
              "subcell (i n + j) of x and (j n + i) of y (a subcell is 1 / num_samples wide), jittered inside\n"
              "its subcell with self.rand_float(); then shuffle x among the points of each grid column and y\n"
              "among those of each grid row, with k = self.rand_int(j, n - 1) as the book does, so that the\n"
              "points stay one per grid cell (jittered) and one per subcell column and row (n-rooks).\n"
              "self.grid_cells() gives the cells (row, column), set after set; draw every random number from\n"
              "the sampler's own stream (rand_float, rand_int), so that the seed decides the points."),
        Block("sampling/maps.py", "concentric_map",
              "Shirley and Chiu's concentric map (Suffern ch. 6, \"Mapping Samples to a Unit Disk\"): with\n"
              "(sx, sy) = (2x - 1, 2y - 1) in [-1, 1]^2, find the region (of four, split by the diagonals)\n"
              "the point is in; r is the coordinate of largest magnitude and phi/(pi/4) runs from 0 to 8\n"
              "around the square (region 1: r = sx, phi = sy/sx; region 2: r = sy, phi = 2 - sx/sy;\n"
              "region 3: r = -sx, phi = 4 + sy/sx; region 4: r = -sy, phi = 6 - sx/sy, and 0 at the centre).\n"
              "Return (r cos(phi pi/4), r sin(phi pi/4))."),
    ),
    task=("Write the sampler that most of Suffern's figures use and the map that turns its points into\n"
          "points of the unit disk, the lens of a thin-lens camera. `MultiJittered.generate_samples` makes\n"
          "Chiu, Shirley and Wang's points: one in every cell of the n x n grid (jittered) and one in every\n"
          "column and every row of the n^2 x n^2 subgrid (n-rooks), shuffled so that every set differs.\n"
          "`concentric_map(x, y)` is Shirley and Chiu's map of the unit square onto the unit disk, which\n"
          "keeps areas (uniform points stay uniform) and keeps strata together, unlike the polar map\n"
          "r = sqrt(x), phi = 2 pi y. The tests check the points' structure in every set and that the\n"
          "sets are shuffled and come from the sampler's own random stream, and the map at points whose\n"
          "images are known exactly and by the distribution of many mapped points (chi-square)."),
    formulas=("- Multi-jittered points (Suffern ch. 5): canonical x of cell (i, j) in subcell i n + j, y in\n"
              "  subcell j n + i; shuffle x within columns, y within rows\n"
              "- Concentric map (Suffern ch. 6; Shirley and Chiu 1997, \"A Low Distortion Map Between Disk and\n"
              "  Square\"): (sx, sy) = (2x - 1, 2y - 1), regions by the diagonals, r and phi as in the TODO;\n"
              "  the map preserves area, so uniform points of the square give density 1 / pi on the disk"),
    slides=("Suffern ch. 5: Sampling (Multi-Jittered Sampling, Shuffling the x- and y-Coordinates)",
            "Suffern ch. 6: Mapping Samples to a Unit Disk",
            "Suffern ch. 10: the thin-lens camera samples its lens with the concentric map"),
    extra=("There is no image test: a correct sampler whose random numbers are drawn in another order\n"
           "makes another, equally good, noisy image. To see your sampler at work, render Suffern's\n"
           "depth-of-field figure small: `rtfgu.show(rtfgu.scenes.get_scene(\"suffern_depth_of_field\")(), 128, 96,\n"
           "spp=16)` (a thin lens whose lens samples go through your concentric map). There is no image to\n"
           "hand in."),
)

A11 = Assignment(
    id="a11_realistic_transparency",
    title="Realistic transparency: Fresnel's reflectance and Bouguer's absorption",
    blocks=(
        Block("brdfs/fresnel_reflector.py", "fresnel_reflectance",
              "Fresnel's reflectance for unpolarised light (Suffern ch. 28; 02562 worksheet 8), arriving at\n"
              "cos_i > 0 with relative index eta = n1 / n2 (the side the light comes from over the other):\n"
              "sin^2(theta_t) = eta^2 (1 - cos_i^2); at or beyond 1 the light is totally reflected, return 1.\n"
              "Else cos_t = sqrt(1 - sin^2(theta_t)), r_perp = (eta cos_i - cos_t) / (eta cos_i + cos_t),\n"
              "r_par = (cos_i - eta cos_t) / (cos_i + eta cos_t); return the mean of r_perp^2 and r_par^2."),
        Block("materials/dielectric.py", "transmittance",
              "Bouguer's (Beer-Lambert) law: the fraction exp(-sigma_a s) of the radiance that survives a\n"
              "distance s through the medium, per channel (absorption is sigma_a, a Float3). Return a Float3."),
        Block("materials/dielectric.py", "Dielectric.shade",
              "Whitted's dielectric (Suffern ch. 28, Dielectric::shade): L = Phong.shade(self, sr), then the\n"
              "mirror ray from self.fresnel_brdf.sample_f(sr, wo) (its f is R) traced by sr.scene.tracer at\n"
              "sr.depth + 1 from sr.position (tmin SPAWN_EPSILON); under total internal reflection\n"
              "(self.fresnel_btdf.tir(sr)) return L + L_r. Else also the refracted ray of\n"
              "self.fresnel_btdf.sample_f(sr, wo) (its f is 1 - R): return L + R L_r + (1 - R) L_t. A ray that runs\n"
              "inside (against the outward normal) loses light by Bouguer's law over the distance its trace\n"
              "found (its tmax after tracing): self._through(ray, L, sr.normal) applies it."),
    ),
    task=("Write what makes glass look like glass (Suffern ch. 28, \"Realistic Transparency\"; 02562 worksheet\n"
          "8): Fresnel's reflectance, the share of light a dielectric reflects at each angle (a few per cent\n"
          "head on, all of it at grazing angles and beyond the critical angle inside), Bouguer's law of\n"
          "absorption inside the medium, and the Dielectric material that sends both the reflected and the\n"
          "refracted ray and weighs them by R and 1 - R. The tests check the reflectance against Fresnel's\n"
          "equations at angles whose values are known exactly (head on, Brewster's angle, the critical\n"
          "angle), the absorption, the rays shade sends and what it returns, and a glass sphere rendered by\n"
          "Whitted's tracer."),
    formulas=("- Fresnel's equations for unpolarised light (Suffern ch. 28; 02562 worksheet 8): with eta = n1 / n2,\n"
              "  cos_t = sqrt(1 - eta^2 (1 - cos_i^2)), r_perp = (eta cos_i - cos_t) / (eta cos_i + cos_t),\n"
              "  r_par = (cos_i - eta cos_t) / (cos_i + eta cos_t), R = (r_perp^2 + r_par^2) / 2, T = 1 - R;\n"
              "  head on R = ((1 - eta) / (1 + eta))^2, at Brewster's angle tan(theta_i) = 1 / eta r_par = 0\n"
              "- Bouguer's law (Suffern ch. 28; 02562 worksheet 8): T(s) = exp(-sigma_a s)\n"
              "- Whitted's dielectric: L = R L(w_r) + (1 - R) L(w_t), each ray attenuated inside the medium"),
    slides=("Suffern ch. 28: Realistic Transparency (FresnelReflector, FresnelTransmitter, Dielectric)",
            "02562 worksheet 8: Fresnel reflectance, Bouguer's law"),
    time_limit=20.0,
    extra=("Dielectric.shade sends two rays per hit; the numba and WGSL paths render a Dielectric with the\n"
           "path tracer only, so the image test renders with the lecture layer. The tests need assignments\n"
           "1-5 (your own or the revealed solutions). There is no image to hand in."),
)

A12 = Assignment(
    id="a12_area_lights",
    title="Area lights: sampling a shape, the geometry factor and soft shadows",
    blocks=(
        Block("shapes/triangle.py", "Triangle.sample",
              "A point of the triangle uniform by area for (u, v) uniform in [0, 1)^2 (Suffern ch. 18; Shirley,\n"
              "\"Graphics Gems III\"): the barycentric coordinates (1 - sqrt(u), v sqrt(u), (1 - v) sqrt(u)), that\n"
              "is v0 + (e0 v + e1 (1 - v)) sqrt(u). Without the square root the points crowd toward v0."),
        Block("shapes/rectangle.py", "Rectangle.sample",
              "A point of the rectangle uniform by area (Suffern ch. 18.6, Rectangle::sample): p0 + u a + v b."),
        Block("lights/area_light.py", "AreaLight.get_direction",
              "Suffern's AreaLight::get_direction: with (u, v) the point of the unit square drawn (given), keep\n"
              "the shape's point there and its unit normal, (self.sample_point, self.light_normal) =\n"
              "self.geometry.sample_with_normal(u, v), and return the unit vector from sr.position toward\n"
              "the point (the point's normal if the point lit is the point drawn, at distance 0)."),
        Block("lights/area_light.py", "AreaLight.G",
              "The geometry factor (Suffern ch. 18, AreaLight::G): cos(theta_l) / d^2, with d the distance from\n"
              "sr.position to self.sample_point and cos(theta_l) = -n_l . w_i (self._cos_l(sr)) the cosine at\n"
              "the light; 0 where the light is seen from behind (cos(theta_l) <= 0) or at d = 0."),
        Block("lights/area_light.py", "AreaLight.pdf",
              "The density of the point drawn, per unit area of the shape (Suffern ch. 18, AreaLight::pdf):\n"
              "a point uniform by area has the density 1 / A (self.area)."),
        Block("lights/area_light.py", "AreaLight.incident",
              "L G / pdf in the order the numba and WGSL paths compute it: with to_light = sample_point -\n"
              "sr.position, dist its length and cos_l = -n_l . to_light / dist, return\n"
              "emission * (area * cos_l / (dist * dist)); Float3(0) where dist is not > 0 or cos_l is not > 0."),
        Block("tracers/area_lighting.py", "AreaLighting.shade",
              "Suffern's AreaLighting::trace_ray calls the material's area_light_shade at a hit (where Whitted\n"
              "calls shade): return it."),
    ),
    task=("Make soft shadows (Suffern ch. 18, \"Area Lights\"; 02562 worksheets 5 and 7). An area light is a\n"
          "shape that emits: each shading point draws one point of it, uniform by area, and the light it\n"
          "receives from that point, L_e G / pdf with G = cos(theta_l) / d^2 and pdf = 1 / A, is an estimate\n"
          "whose average over a pixel's samples is the light of the whole shape. Write the two shapes'\n"
          "`sample`, the light's `get_direction`, `G`, `pdf` and `incident`, and the tracer that asks the\n"
          "materials for their area-light shading. The tests check the points drawn (exactly at chosen\n"
          "(u, v), and uniform by area over many: chi-square), the direction, G, pdf and L G / pdf at\n"
          "chosen points against their exact values, the tracer's call, and Suffern's figure 18 scene\n"
          "rendered by the lecture layer with AreaLighting."),
    formulas=("- A point uniform by area (Suffern ch. 18; Shirley 1992): triangle v0 + (e0 v + e1 (1 - v)) sqrt(u),\n"
              "  rectangle p0 + u a + v b; the density 1 / A\n"
              "- The geometry factor (Suffern ch. 18, AreaLight::G): G = cos(theta_l) / d^2, cos(theta_l) = -n_l . w_i\n"
              "- The estimate of the direct light: L_e G / pdf = L_e A cos(theta_l) / d^2, 0 from behind"),
    slides=("Suffern ch. 18: Area Lights (AreaLight, Rectangle::sample, AreaLighting)",
            "02562 worksheet 5: area lights as point lights at their centre; worksheet 7: sampling the light"),
    time_limit=20.0,
    extra=("Under RayCast and Whitted an area light stays worksheet 5's point light at the shape's centre\n"
           "(not your code); AreaLighting, PathTrace and GlobalTrace draw points with it. The tests need\n"
           "assignments 1-4 (your own or the revealed solutions). There is no image to hand in."),
)

A13 = Assignment(
    id="a13_instancing",
    title="Instancing: affine transformations and the inverse-transformed ray",
    blocks=(
        Block("matrix.py", "Matrix.transform_point",
              "The point p (w = 1) through the matrix (Suffern ch. 20, Matrix * Point3D): row i of the result is\n"
              "m[i][0] p.x + m[i][1] p.y + m[i][2] p.z + m[i][3], each sum taken left to right. Return a Float3."),
        Block("matrix.py", "Matrix.transform_vector",
              "The vector v (w = 0) through the matrix (Matrix * Vector3D): as transform_point without the\n"
              "translation m[i][3]: a direction does not move."),
        Block("matrix.py", "Matrix.transform_normal",
              "The normal n through this matrix's transpose (ch. 20.5, Matrix * Normal; the matrix is an\n"
              "inverse): row i of the result is m[0][i] n.x + m[1][i] n.y + m[2][i] n.z. Not normalised."),
        Block("shapes/instance.py", "Instance._compose",
              "Compose one more transformation after those before (ch. 21): the forward matrix becomes\n"
              "forward * self.forward_matrix, the inverse self.inv_matrix * inverse (the inverse of a product\n"
              "is the product of the inverses in the other order). Return self, so that calls chain."),
        Block("shapes/instance.py", "Instance.object_ray",
              "The ray in the object's space (ch. 21.1): the origin through self.inv_matrix as a point, the\n"
              "direction as a vector, NOT normalised (so the object's t is the world ray's t), the same tmin and\n"
              "tmax. Return a new Ray."),
        Block("shapes/instance.py", "Instance.normal_at",
              "The object's normal_at at the object-space point (position through self.inv_matrix), through\n"
              "self.inv_matrix.transform_normal, normalised."),
        Block("shapes/instance.py", "Instance.hit_normal",
              "As normal_at, with the object's hit_normal at the object-space point and the object-space\n"
              "direction (the direction through self.inv_matrix as a vector), so that a normal that turns\n"
              "toward the ray turns toward it here too."),
    ),
    task=("Place shapes with affine transformations (Suffern ch. 20, \"Affine Transformations\"; ch. 21,\n"
          "\"Instancing\"). A `Matrix` transforms points, vectors and normals, each its own way; an `Instance`\n"
          "keeps the inverse of its transformation, composed call after call, and intersects its object with\n"
          "the ray brought into the object's space: an ellipsoid is a unit sphere seen through a scale, a\n"
          "turned box a box seen through a rotation. The tests check the three products on chosen matrices,\n"
          "the composed matrices of chains of calls (the order matters), the object-space ray, the hits and\n"
          "normals of transformed shapes against their exact values, and Suffern's figure 21 scene rendered\n"
          "by the lecture layer."),
    formulas=("- A point (w = 1), a vector (w = 0): M p and M v; a normal: (M^-1)^T n (Suffern ch. 20.5)\n"
              "- Composition (ch. 21): M = T_k ... T_1, M^-1 = T_1^-1 ... T_k^-1\n"
              "- The inverse-transformed ray (ch. 21.1): o' = M^-1 o, d' = M^-1 d, not normalised: o + t d hits\n"
              "  the instance where o' + t d' hits the object, for the same t"),
    slides=("Suffern ch. 20: Affine Transformations (Matrix, transforming points, vectors and normals)",
            "Suffern ch. 21: Instancing (Instance, the inverse-transformed ray, the transformed normal)"),
    time_limit=20.0,
    extra=("The tests need assignments 1-3 (your own or the revealed solutions): the instances hold\n"
           "lecture 01's and Suffern's shapes. The numba and WGSL paths transform the ray their own way\n"
           "(rtfgu/kernels/instance.py, intersect_instance.wgsl), which a release ships once a13 is revealed.\n"
           "There is no image to hand in."),
)

PYTHON_ASSIGNMENTS = (A01, A02, A03, A04, A05, A07, A08, A09, A10, A11, A12, A13)
ASSIGNMENTS = {a.id: a for a in (A01, A02, A03, A04, A05, A06, A07, A08, A09, A10, A11, A12, A13)}


def register(assignment: Assignment) -> None:
    ASSIGNMENTS[assignment.id] = assignment


def get_assignment(name: str) -> Assignment:
    """By full id (a03_intersections) or short id (a03); a ValueError listing the ids if unknown."""
    for a in ASSIGNMENTS.values():
        if name in (a.id, a.short):
            return a
    raise ValueError("unknown assignment %r; known assignments: %s" % (name, ", ".join(ASSIGNMENTS)))


def block_table() -> dict:
    """(file, qualname) -> (assignment, block) for every block of every assignment."""
    table = {}
    for a in ASSIGNMENTS.values():
        for b in a.blocks:
            key = (b.file, b.qualname)
            if key in table:
                raise ValueError("block %s:%s is claimed by %s and %s" % (b.file, b.qualname, table[key][0].id, a.id))
            table[key] = (a, b)
    return table
