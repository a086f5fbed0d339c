"""read_hdr: a Radiance picture (``.hdr``, ``.pic``: Greg Ward's RGBE format, Graphics Gems II,
"Real Pixels", 1991; the format of the environment maps of 02562 worksheet 9) as linear
radiance for ``EnvironmentLight``.

A file is a text header, a resolution line and the scanlines:

    #?RADIANCE                  (the first line: "#?" and the name of the program)
    FORMAT=32-bit_rle_rgbe      (optional, and the only format read: XYZE is refused)
    EXPOSURE=2.0                (optional, any number of them; also COLORCORR=r g b)
                                (a blank line ends the header)
    -Y 512 +X 1024              (the resolution: here 512 scanlines of 1024 pixels, top first)

Each pixel is four bytes, a mantissa per channel and a shared exponent e: the channel's value
is ``mantissa * 2^(e - 136)`` (= (mantissa / 256) 2^(e - 128)), and e = 0 is black. A scanline
of 8 to 32767 pixels may be run-length encoded the new way (Radiance's ``freadcolrs``): the
bytes 2, 2, width / 256, width % 256, then each of the four channels in turn as runs, a byte
c > 128 followed by one value repeated c - 128 times, or c <= 128 followed by c values. A
scanline that does not start with 2, 2 is flat (four bytes a pixel), where a pixel 1, 1, 1, n
repeats the pixel before it n << s times, s growing by 8 for each such pixel in a row (the
old encoding, ``oldreadcolrs``). Radiance's rules on what a file means are followed:
EXPOSURE and COLORCORR say by how much the pixels were multiplied, so the radiance is the
pixel divided by their product; the resolution line may name its axes in any of the eight
orders and directions (``-Y h +X w`` is the usual one) and the image is turned to have row 0
at the top and column 0 at the left.

The reader is rtfgu's own, a short one in Python and numpy: the dependencies rtfgu
already has do not read RGBE (Pillow, OpenEXR, trimesh), and the libraries that do are large
for one format (OpenCV, imagecodecs) or need a native library at run time (imageio's
FreeImage plugin). Bad input is a ValueError naming the file and, in the header, the line,
in the pixels, the scanline and its byte offset: a first line without ``#?``, a format other
than RGBE, an EXPOSURE or COLORCORR that is not a positive number, a header without the
blank line that ends it, a bad resolution line, a scanline whose run-length width is not the
image's, a run of length 0 or past the end of its scanline, and a file cut short.
"""
from __future__ import annotations

import math
import os
import re

from ..lazy_import import numpy as np

RGBE_FORMAT = "32-bit_rle_rgbe"
RESOLUTION = re.compile(r"([-+])([XY]) (\d+) ([-+])([XY]) (\d+)")
# The widths a new-style run-length encoded scanline may have (Radiance's MINELEN, MAXELEN).
MIN_RLE_WIDTH, MAX_RLE_WIDTH = 8, 0x7FFF


def read_hdr(path) -> np.ndarray:
    """The radiance of the Radiance picture ``path`` as (height, width, 3) float32, row 0 at
    the top."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise ValueError("read_hdr: no such file %s" % path)
    with open(path, "rb") as f:
        data = f.read()
    scale, axes, start, line = _read_header(data, path)
    slow, fast = axes
    rgbe = _read_scanlines(data, start, slow[2], fast[2], path)
    radiance = np.where(rgbe[..., 3:] == 0, 0.0,
                        np.ldexp(rgbe[..., :3].astype(np.float64), rgbe[..., 3:].astype(np.int32) - 136))
    if slow[1] == "X":                        # scanlines are columns: make them rows
        radiance = radiance.transpose(1, 0, 2)
    (y_sign,) = [sign for sign, axis, _ in axes if axis == "Y"]
    (x_sign,) = [sign for sign, axis, _ in axes if axis == "X"]
    if y_sign == "+":                         # +Y: the first row is the bottom one
        radiance = radiance[::-1]
    if x_sign == "-":                         # -X: the first column is the right one
        radiance = radiance[:, ::-1]
    return (radiance / scale).astype(np.float32)


def _read_header(data: bytes, path: str):
    """(the divisor per channel, the two axes (sign, "X" or "Y", size) slow one first, the
    offset of the first scanline, the number of the resolution line)."""
    def fail(number: int, what: str):
        raise ValueError("read_hdr: %s, line %d: %s" % (path, number, what))

    at, number, scale = 0, 0, np.ones(3)
    while True:
        end = data.find(b"\n", at)
        if end < 0:
            raise ValueError("read_hdr: %s: the header never ends (no blank line after it, "
                             "before the resolution line)" % path)
        text = data[at:end].decode("latin-1")
        number += 1
        at = end + 1
        if number == 1:
            if not text.startswith("#?"):
                fail(1, "not a Radiance picture: the first line is %r, not '#?RADIANCE' (or "
                        "'#?' and another program's name)" % text[:40])
            continue
        if text.strip() == "":
            break
        key, _, value = text.partition("=")
        key = key.strip()
        if key == "FORMAT" and value.strip() != RGBE_FORMAT:
            fail(number, "FORMAT=%s: only %s is read%s" % (value.strip(), RGBE_FORMAT,
                 " (XYZE pixels are CIE XYZ, not RGB)" if "xyze" in value else ""))
        elif key in ("EXPOSURE", "COLORCORR"):
            try:
                factors = [float(x) for x in value.split()]
            except ValueError:
                factors = []
            if len(factors) != (1 if key == "EXPOSURE" else 3) or \
                    not all(math.isfinite(x) and x > 0 for x in factors):
                fail(number, "%s= must be %s, got %r" % (key, "one number > 0" if key == "EXPOSURE"
                                                        else "three numbers > 0", value.strip()))
            scale = scale * np.array(factors)
    end = data.find(b"\n", at)
    text = data[at:end if end >= 0 else len(data)].decode("latin-1")
    number += 1
    match = RESOLUTION.fullmatch(text.strip())
    if end < 0 or match is None or match.group(2) == match.group(5):
        fail(number, "bad resolution line %r: expected '-Y height +X width' (or another order "
                     "of -Y/+Y and +X/-X)" % text[:40])
    axes = ((match.group(1), match.group(2), int(match.group(3))),
            (match.group(4), match.group(5), int(match.group(6))))
    if axes[0][2] == 0 or axes[1][2] == 0:
        fail(number, "the image is empty (%r)" % text.strip())
    return scale, axes, end + 1, number


def _read_scanlines(data: bytes, at: int, count: int, width: int, path: str) -> np.ndarray:
    """The (count, width, 4) RGBE bytes of the scanlines from offset ``at``."""
    out = np.empty((count, width, 4), dtype=np.uint8)
    for row in range(count):
        start = at
        head = data[at:at + 4]
        if MIN_RLE_WIDTH <= width <= MAX_RLE_WIDTH and len(head) == 4 and head[0] == 2 and head[1] == 2 \
                and head[2] < 128:
            if (head[2] << 8 | head[3]) != width:
                raise ValueError("read_hdr: %s, scanline %d (byte %d): run-length encoded for a width of "
                                 "%d, the image is %d wide" % (path, row, start, head[2] << 8 | head[3], width))
            at = _rle_scanline(data, at + 4, out[row], row, start, path)
        else:
            at = _flat_scanline(data, at, out[row], row, start, path)
    return out


def _rle_scanline(data: bytes, at: int, line: np.ndarray, row: int, start: int, path: str) -> int:
    """Radiance's new run-length encoding: each channel's runs in turn."""
    width, size = len(line), len(data)
    for channel in range(4):
        values = bytearray()
        while len(values) < width:
            if at >= size:
                _truncated(path, row, start)
            code = data[at]
            count = code - 128 if code > 128 else code        # a run of one value, or literals
            if count == 0 or len(values) + count > width:
                where = "read_hdr: %s, scanline %d (byte %d), channel %d" % (path, row, start, channel)
                if count == 0:
                    raise ValueError("%s: a run of length 0 at byte %d" % (where, at))
                raise ValueError("%s: a run of %d at byte %d runs past the scanline's %d pixels"
                                 % (where, count, at, width))
            if code > 128:
                if at + 2 > size:
                    _truncated(path, row, start)
                values += data[at + 1:at + 2] * count
                at += 2
            else:
                if at + 1 + count > size:
                    _truncated(path, row, start)
                values += data[at + 1:at + 1 + count]
                at += 1 + count
        line[:, channel] = np.frombuffer(bytes(values), dtype=np.uint8)
    return at


def _flat_scanline(data: bytes, at: int, line: np.ndarray, row: int, start: int, path: str) -> int:
    """Four bytes a pixel, where 1, 1, 1, n repeats the pixel before (the old encoding)."""
    width = len(line)
    pixels = np.frombuffer(data, dtype=np.uint8, count=min(4 * width, (len(data) - at) // 4 * 4),
                           offset=at).reshape(-1, 4)
    repeats = np.flatnonzero((pixels[:, 0] == 1) & (pixels[:, 1] == 1) & (pixels[:, 2] == 1))
    if len(repeats) == 0:
        if len(pixels) < width:
            _truncated(path, row, start)
        line[:] = pixels
        return at + 4 * width
    filled, shift = 0, 0
    while filled < width:
        if at + 4 > len(data):
            _truncated(path, row, start)
        pixel = data[at:at + 4]
        at += 4
        if pixel[0] == 1 and pixel[1] == 1 and pixel[2] == 1:
            count = pixel[3] << shift
            if filled == 0 or filled + count > width:
                raise ValueError("read_hdr: %s, scanline %d (byte %d): a repeat of %d pixels at byte %d %s"
                                 % (path, row, start, count, at - 4, "with no pixel before it" if filled == 0
                                    else "runs past the scanline's %d pixels" % width))
            line[filled:filled + count] = line[filled - 1]
            filled += count
            shift += 8
        else:
            line[filled] = np.frombuffer(pixel, dtype=np.uint8)
            filled += 1
            shift = 0
    return at


def _truncated(path: str, row: int, start: int):
    raise ValueError("read_hdr: %s, scanline %d (byte %d): truncated, the file ends inside it"
                     % (path, row, start))
