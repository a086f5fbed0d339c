"""Write the meshes shipped in rtfgu/meshes/ (rtfgu/meshes/README.md says what each one is).

    python tools/make_meshes.py            # needs npm (for the bunny and the teapot)
    python tools/make_meshes.py --cornell  # the Cornell box and the globe only, no network

bunny.obj and teapot.obj: the ``positions`` and ``cells`` of the npm packages ``bunny``
1.0.1 and ``teapot`` 1.0.0 (Mikola Lysenko), fetched with ``npm pack`` into a temporary
folder and written as OBJ unchanged: the numbers as the packages print them, the cells as
1-based ``f`` lines in their order and winding (counter-clockwise seen from outside). The
tarballs are not kept.

cornell_box.obj and cornell_box.mtl: the Cornell box with its two blocks, from the
measurements published by the Cornell Program of Computer Graphics ("Cornell Box Data",
https://www.graphics.cornell.edu/online/box/data.html), in mm, each quad written as the
data lists its corners. The ceiling is cut into the eight rectangles around the light
(x 213..343, z 227..332 at y = 548.8), so that light and ceiling never overlap.

globe.obj: a unit sphere of GLOBE_RINGS latitude bands and GLOBE_SEGMENTS longitudes with
texture coordinates (u the longitude over 2 pi, v the latitude from the south pole, as a
world map) and vertex normals, written ``v/vt/vn``. A position is written once: the seam's
column and the poles are one ``v`` each, with a ``vt`` per face corner there (u 0 and 1 at
the seam; at a pole, the middle of its face's longitudes), so the faces share their edges
exactly, as a textured mesh's must.
"""
from __future__ import annotations

import argparse
import json
import math
import re
import subprocess
import tarfile
import tempfile
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "rtfgu" / "meshes"

NPM_MESHES = {
    # npm package@version, the file in its tarball, the OBJ written, its header
    "bunny": ("bunny@1.0.1", "package/index.js", "bunny.obj", [
        "The Stanford bunny, as packaged in the npm package bunny 1.0.1 by Mikola Lysenko.",
        "Source of the scan: the Stanford 3D Scanning Repository, Stanford University",
        "Computer Graphics Laboratory, https://graphics.stanford.edu/data/3Dscanrep/",
        "Terms and how this file was made: rtfgu/meshes/README.md.",
    ]),
    "teapot": ("teapot@1.0.0", "package/teapot.js", "teapot.obj", [
        "The Utah teapot (Martin Newell, 1975), as tessellated in the npm package teapot",
        "1.0.0 by Mikola Lysenko (public domain).",
        "Terms and how this file was made: rtfgu/meshes/README.md.",
    ]),
}

# Cornell Box Data (Cornell Program of Computer Graphics): each quad's corners as listed there.
CORNELL_QUADS = [
    ("floor", "white", [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]),
    ("light", "light", [(343.0, 548.8, 227.0), (343.0, 548.8, 332.0), (213.0, 548.8, 332.0),
                        (213.0, 548.8, 227.0)]),
    ("back_wall", "white", [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2),
                            (556.0, 548.8, 559.2)]),
    ("right_wall", "green", [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]),
    ("left_wall", "red", [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2),
                          (556.0, 548.8, 0.0)]),
    ("short_block", "white", [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0),
                              (290.0, 165.0, 114.0)]),
    ("short_block", "white", [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0),
                              (240.0, 0.0, 272.0)]),
    ("short_block", "white", [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0),
                              (290.0, 0.0, 114.0)]),
    ("short_block", "white", [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0),
                              (130.0, 0.0, 65.0)]),
    ("short_block", "white", [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0),
                              (82.0, 0.0, 225.0)]),
    ("tall_block", "white", [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0),
                             (472.0, 330.0, 406.0)]),
    ("tall_block", "white", [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0),
                             (472.0, 0.0, 406.0)]),
    ("tall_block", "white", [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0),
                             (314.0, 0.0, 456.0)]),
    ("tall_block", "white", [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0),
                             (265.0, 0.0, 296.0)]),
    ("tall_block", "white", [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0),
                             (423.0, 0.0, 247.0)]),
]
# The ceiling, 556.0 x 559.2 at y = 548.8 facing down (corners (556, 0), (556, 559.2),
# (0, 559.2), (0, 0) in the data), as the eight rectangles of the 3 x 3 grid through the
# light's edges without the light's own: no T-junction, no overlap with the light.
CEILING_X = (0.0, 213.0, 343.0, 556.0)
CEILING_Z = (0.0, 227.0, 332.0, 559.2)
CEILING_Y = 548.8

# The RGB reflectances and the light's radiance of Mitsuba 3's Cornell box
# (mitsuba.cornell_box()), Mitsuba's RGB for the measured spectra of the Cornell data.
CORNELL_MATERIALS = {
    "white": ((0.885809, 0.698859, 0.666422), None),
    "red": ((0.570068, 0.0430135, 0.0443706), None),
    "green": ((0.105421, 0.37798, 0.076425), None),
    "light": ((0.885809, 0.698859, 0.666422), (18.387, 13.9873, 6.75357)),
}


def number(x: float) -> str:
    return repr(float(x)).removesuffix(".0") if float(x).is_integer() else repr(float(x))


def npm_arrays(spec: str, member: str) -> tuple:
    """(positions, cells) of the CommonJS file ``member`` of the npm package ``spec``."""
    with tempfile.TemporaryDirectory() as tmp:
        done = subprocess.run(["npm", "pack", spec, "--silent"], cwd=tmp, capture_output=True,
                              text=True, check=True)
        tarball = Path(tmp) / done.stdout.strip().splitlines()[-1]
        with tarfile.open(tarball) as archive:
            source = archive.extractfile(member).read().decode()
    positions = json.loads(re.search(r"exports\.positions=(\[.*?\]\])", source).group(1))
    cells = json.loads(re.search(r"exports\.cells=(\[.*?\]\])", source).group(1))
    return positions, cells


def write_npm_mesh(name: str) -> None:
    spec, member, filename, header = NPM_MESHES[name]
    positions, cells = npm_arrays(spec, member)
    lines = ["# " + h for h in header]
    lines.append("# %d vertices, %d triangles" % (len(positions), len(cells)))
    lines += ["v %s" % " ".join(number(x) for x in p) for p in positions]
    lines += ["f %s" % " ".join(str(i + 1) for i in c) for c in cells]
    (OUT / filename).write_text("\n".join(lines) + "\n")


def cornell_faces() -> list:
    """(group, material, corners) of every face of the box, the ceiling's eight included."""
    faces = list(CORNELL_QUADS)
    for i in range(3):
        for k in range(3):
            if (i, k) == (1, 1):
                continue        # the light's rectangle
            x0, x1 = CEILING_X[3 - i - 1], CEILING_X[3 - i]
            z0, z1 = CEILING_Z[k], CEILING_Z[k + 1]
            # the data's order (556, 0) -> (556, 559.2) -> (0, 559.2) -> (0, 0): facing down
            faces.append(("ceiling", "white", [(x1, CEILING_Y, z0), (x1, CEILING_Y, z1),
                                               (x0, CEILING_Y, z1), (x0, CEILING_Y, z0)]))
    return faces


def write_cornell_box() -> None:
    faces = cornell_faces()
    vertices, index = [], {}
    for _, _, corners in faces:
        for c in corners:
            if c not in index:
                index[c] = len(vertices) + 1
                vertices.append(c)
    lines = [
        "# The Cornell box with its two blocks, in mm: the measurements of the Cornell Program",
        "# of Computer Graphics, \"Cornell Box Data\", https://www.graphics.cornell.edu/online/box/data.html",
        "# Each quad is listed with the data's corners in the data's order; the ceiling is cut",
        "# into the eight rectangles around the light. Camera in the data: position",
        "# (278, 273, -800), looking along +z, up +y, focal length 35 mm, film 25 x 25 mm.",
        "# Materials (cornell_box.mtl): Mitsuba 3's RGB for the measured spectra.",
        "# Terms and how this file was made: rtfgu/meshes/README.md.",
        "mtllib cornell_box.mtl",
    ]
    lines += ["v %s" % " ".join(number(x) for x in v) for v in vertices]
    group = material = None
    for name, mat, corners in faces:
        if name != group:
            lines.append("g " + name)
            group = name
        if mat != material:
            lines.append("usemtl " + mat)
            material = mat
        lines.append("f %s" % " ".join(str(index[c]) for c in corners))
    (OUT / "cornell_box.obj").write_text("\n".join(lines) + "\n")
    mtl = ["# The Cornell box's materials: Kd the RGB reflectance, Ke the light's radiance,",
           "# as Mitsuba 3's mitsuba.cornell_box() gives them. rtfgu/meshes/README.md."]
    for name, (kd, ke) in CORNELL_MATERIALS.items():
        mtl += ["newmtl " + name, "Kd %s" % " ".join(number(x) for x in kd)]
        if ke is not None:
            mtl.append("Ke %s" % " ".join(number(x) for x in ke))
    (OUT / "cornell_box.mtl").write_text("\n".join(mtl) + "\n")


GLOBE_RINGS, GLOBE_SEGMENTS = 12, 24


def write_globe() -> None:
    rings, segments = GLOBE_RINGS, GLOBE_SEGMENTS
    positions = [(0.0, -1.0, 0.0)]                  # the south pole, then the rings, then the north
    for i in range(1, rings):
        theta = math.pi * i / rings                 # the angle from the south pole
        y, r = -math.cos(theta), math.sin(theta)
        positions += [(r * math.cos(2 * math.pi * j / segments), y, -r * math.sin(2 * math.pi * j / segments))
                      for j in range(segments)]
    positions.append((0.0, 1.0, 0.0))
    north = len(positions) - 1

    def v(i: int, j: int) -> int:
        """The 0-based vertex of ring i (0: south pole, rings: north pole), longitude j."""
        return 0 if i == 0 else north if i == rings else 1 + (i - 1) * segments + j % segments

    uvs, uv_index = [], {}

    def vt(u: float, w: float) -> int:
        if (u, w) not in uv_index:
            uv_index[u, w] = len(uvs)
            uvs.append((u, w))
        return uv_index[u, w]

    faces = []
    for i in range(rings):
        for j in range(segments):
            u0, u1, w0, w1 = j / segments, (j + 1) / segments, i / rings, (i + 1) / rings
            c00, c01 = (v(i, j), vt(u0, w0)), (v(i, j + 1), vt(u1, w0))
            c10, c11 = (v(i + 1, j), vt(u0, w1)), (v(i + 1, j + 1), vt(u1, w1))
            if i == 0:
                faces.append(((0, vt((u0 + u1) / 2, 0.0)), c11, c10))
            elif i == rings - 1:
                faces.append((c00, c01, (north, vt((u0 + u1) / 2, 1.0))))
            else:
                faces += [(c00, c01, c11), (c00, c11, c10)]
    lines = ["# A unit sphere with texture coordinates and normals (tools/make_meshes.py, write_globe).",
             "# %d latitude bands, %d longitudes; u = longitude / 2 pi, v = latitude from the south pole."
             % (rings, segments)]
    lines += ["v %s %s %s" % tuple(number(x) for x in p) for p in positions]
    lines += ["vt %s %s" % (number(u), number(w)) for u, w in uvs]
    lines += ["vn %s %s %s" % tuple(number(x) for x in p) for p in positions]
    lines += ["f " + " ".join("%d/%d/%d" % (p + 1, t + 1, p + 1) for p, t in face) for face in faces]
    (OUT / "globe.obj").write_text("\n".join(lines) + "\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cornell", action="store_true", help="write the Cornell box only")
    args = parser.parse_args()
    OUT.mkdir(exist_ok=True)
    write_cornell_box()
    write_globe()
    if not args.cornell:
        for name in NPM_MESHES:
            write_npm_mesh(name)


if __name__ == "__main__":
    main()
