"""a07: texture lookup (02562 worksheet 3, texture addressing and filtering; Suffern ch. 29,
"Image Textures"). The probes are in rtfgu/grading/probes/a07.py (visible) and a07_hidden.py;
the hints compare with the known mistakes of rtfgu.grading.mistakes.texture."""
from __future__ import annotations

from . import Check, image_check, known_mistake_hint, register

FLIP = ("your colour is that of the texture upside down: (u, v) = (0, 0) is the bottom-left corner and "
        "v = 1 the top row, row 0 of self.texels, so the row coordinate is y = (1 - v) * height, not v * height")
CLAMP_WRAPS = ("under clamp your lookup wraps around to the opposite edge: clamp holds the edge texel, "
               "min(max(i, 0), width - 1) and likewise j, after clamping u and v to [0, 1]")
REPEAT_CLAMPS = ("under repeat the texture repeats: wrap u and v (u - floor(u)) and the texel indices "
                 "(i % width, j % height) instead of clamping them")
HALF_TEXEL = ("your bilinear colour is the one without the half-texel shift: texel centres sit at whole numbers "
              "+ 0.5 in texel space, so subtract 0.5 from x = u * width and y = (1 - v) * height before "
              "floor() and the weights")
ROUNDS = ("your nearest texel is the one whose corner, not whose centre, is nearest: texel i covers "
          "i <= x < i + 1, so take floor(x), not round(x)")

LOOKUP_HINTS = (("v_not_flipped", FLIP), ("no_half_texel_shift", HALF_TEXEL), ("clamp_wraps", CLAMP_WRAPS),
                ("clamp_is_repeat", CLAMP_WRAPS), ("repeat_clamps", REPEAT_CLAMPS), ("nearest_rounds", ROUNDS))


def _same(got, want) -> bool:
    return (isinstance(got, list) and isinstance(want, list) and len(got) == len(want) == 3
            and all(isinstance(g, (int, float)) and abs(g - w) <= 1e-9 + 1e-6 * abs(w) for g, w in zip(got, want)))


def hint_lookup(inputs, want, got):
    """Names the known mistake (rtfgu.grading.mistakes.texture) whose colour the student's is."""
    return known_mistake_hint(LOOKUP_HINTS, inputs, want, got, "color", _same)


def hint_texel(inputs, want, got):
    known = inputs.get("known") or {}
    color = got.get("color")
    if "other_address" in known and not _same(known["other_address"], want["color"]) \
            and _same(color, known["other_address"]):
        return CLAMP_WRAPS if inputs.get("address") == "clamp" else REPEAT_CLAMPS
    if "row_from_bottom" in known and not _same(known["row_from_bottom"], want["color"]) \
            and _same(color, known["row_from_bottom"]):
        return ("texel(i, j) counts rows from the top, as the array stores them: row j is self.texels[j]. "
                "The flip of v belongs in get_color, y = (1 - v) * height")
    return None


def _texture_check(name, weight, probe, hint, **options) -> Check:
    """A test whose hint compares with the known mistakes of rtfgu.grading.mistakes.texture."""
    return Check(name, weight, probe, hint=hint, known="texture", **options)


register("a07_textures", [
    _texture_check("ImageTexture.texel: repeat wraps the column and row indices", 1,
                   ("a07", "observe_texel_repeat"), hint_texel),
    _texture_check("ImageTexture.texel: clamp holds the edge texel", 1, ("a07", "observe_texel_clamp"), hint_texel),
    _texture_check("get_color, nearest: the texel that holds (u, v); v = 1 is the top row", 2,
                   ("a07", "observe_nearest"), hint_lookup),
    _texture_check("get_color, bilinear: a texel at its centre, the mean halfway between centres", 2,
                   ("a07", "observe_bilinear"), hint_lookup),
    _texture_check("get_color, repeat: u and v below 0 and above 1 wrap around", 1, ("a07", "observe_repeat"),
                   hint_lookup),
    _texture_check("get_color, clamp: outside [0, 1] and near the edges, the edge texels", 1,
                   ("a07", "observe_clamp"), hint_lookup),
    image_check("image: worksheet 3's plane, nearest and repeat", 1, "default_texture_nearest_repeat",
                size=(64, 64)),
    image_check("image: worksheet 3's plane, bilinear and clamp", 1, "default_texture_bilinear_clamp",
                size=(64, 64)),
    # ### BEGIN HIDDEN
    _texture_check("get_color, bilinear under repeat across the seams at u = 0 and v = 0", 1,
                   ("a07_hidden", "observe_seam"), hint_lookup, visibility="hidden"),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    _texture_check("get_color of a 1 x 1 texture and of a texture taller than wide", 1,
                   ("a07_hidden", "observe_one_texel_and_tall"), hint_lookup, visibility="hidden"),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    image_check("image: worksheet 3's plane, nearest and clamp", 1, "default_texture_nearest_clamp", size=(64, 64),
                visibility="hidden"),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    image_check("image: worksheet 3's plane, bilinear and repeat", 1, "default_texture_bilinear_repeat",
                size=(64, 64), visibility="hidden"),
    # ### END HIDDEN
])
