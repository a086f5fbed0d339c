"""read_hdr (rtfgu/lights/rgbe.py) and EnvironmentLight's choice of reader: Radiance pictures
written here byte by byte (flat, old-style repeats and new-style run-length encoding, pixels
exactly representable in RGBE) and by another program (imagecodecs, tests/data/rgbe/) read to
the exact values, and bad input names the file and the line or the scanline."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from rtfgu import EnvironmentLight, Float3
from rtfgu.lights import read_exr, read_hdr
from rtfgu.scenes.environment import SKY

DATA = Path(__file__).resolve().parent / "data" / "rgbe"
HEADER = b"#?RADIANCE\n# a comment\nFORMAT=32-bit_rle_rgbe\n\n"


def value(mantissa: int, exponent: int) -> float:
    """The RGBE value of one channel, mantissa * 2^(e - 136), 0 for e = 0."""
    return 0.0 if exponent == 0 else mantissa * 2.0 ** (exponent - 136)


def decoded(rgbe: np.ndarray) -> np.ndarray:
    return np.array([[[value(int(p[c]), int(p[3])) for c in range(3)] for p in row] for row in rgbe])


def rle_channel(values: bytes) -> bytes:
    """Radiance's new-style runs of one channel of a scanline: a value repeated 3 or more
    times as 128 + n, value (n <= 127); the rest as n, n values (n <= 128)."""
    out, i = bytearray(), 0
    while i < len(values):
        j = i
        while j < len(values) and values[j] == values[i] and j - i < 127:
            j += 1
        if j - i >= 3:
            out += bytes((128 + j - i, values[i]))
            i = j
            continue
        k = i
        while k < len(values) and k - i < 128 and not (k + 2 < len(values) and values[k] == values[k + 1] == values[k + 2]):
            k += 1
        out += bytes((k - i,)) + bytes(values[i:k])
        i = k
    return bytes(out)


def scanlines(rgbe: np.ndarray, encoding: str) -> bytes:
    if encoding == "flat":
        return rgbe.astype(np.uint8).tobytes()
    width = rgbe.shape[1]
    return b"".join(bytes((2, 2, width >> 8, width & 255)) + b"".join(rle_channel(bytes(row[:, c])) for c in range(4))
                    for row in rgbe.astype(np.uint8))


def write_hdr(folder, rgbe, encoding="flat", header=HEADER, name="image.hdr") -> Path:
    path = folder / name
    path.write_bytes(header + b"-Y %d +X %d\n" % rgbe.shape[:2] + scanlines(rgbe, encoding))
    return path


def random_rgbe(height: int, width: int, seed: int) -> np.ndarray:
    """Normalised RGBE pixels (the largest mantissa >= 128), with runs, black pixels (e = 0)
    and exponents from 100 to 160."""
    rng = np.random.default_rng(seed)
    rgbe = rng.integers(0, 256, (height, width, 4))
    rgbe[..., 0] = rng.integers(128, 256, (height, width))
    rgbe[..., 3] = rng.integers(100, 161, (height, width))
    rgbe[:, : width // 3] = rgbe[:, :1]                           # a run in every channel
    rgbe[:, -5:, 3] = 0                                           # black
    return rgbe.astype(np.uint8)


# --- what is read -----------------------------------------------------------------------

def test_a_hand_written_run_length_encoded_scanline(tmp_path):
    """One scanline of 8 pixels written out byte by byte, e = 129 (a value is mantissa / 128):
    red a run of 8 times 128, green 8 literals, blue 4 literals and a run of 4, e a run."""
    path = tmp_path / "one.hdr"
    path.write_bytes(HEADER + b"-Y 1 +X 8\n" + bytes((2, 2, 0, 8)) + bytes((136, 128))
                     + bytes((8, 0, 64, 128, 192, 0, 64, 128, 192)) + bytes((4, 128, 128, 128, 128, 132, 255))
                     + bytes((136, 129)))
    expected = [[(1.0, (0, 0.5, 1.0, 1.5)[k % 4], 1.0 if k < 4 else 255 / 128) for k in range(8)]]
    assert read_hdr(path).tolist() == [[list(p) for p in expected[0]]]


@pytest.mark.parametrize("encoding,height,width", [("flat", 3, 5), ("flat", 1, 1), ("flat", 4, 8), ("flat", 2, 300),
                                                   ("rle", 4, 8), ("rle", 2, 300)])
def test_flat_and_run_length_encoded_files_read_to_the_exact_values(tmp_path, encoding, height, width):
    rgbe = random_rgbe(height, width, seed=height * 1000 + width)
    image = read_hdr(write_hdr(tmp_path, rgbe, encoding))
    assert image.dtype == np.float32 and image.shape == (height, width, 3)
    assert np.array_equal(image, decoded(rgbe))
    assert (image[:, -min(5, width):] == 0).all()                # e = 0 is black, whatever the mantissas


def test_old_style_repeats_grow_by_eight_bits_when_they_follow_each_other(tmp_path):
    """(1, 1, 1, n) repeats the pixel before n << s times, s = 0, 8, 16 ... for consecutive
    repeats: 1 + 43 + (1 << 8) = 300 pixels."""
    pixels = bytes((128, 64, 32, 130)) + bytes((1, 1, 1, 43)) + bytes((1, 1, 1, 1))
    second = bytes((255, 0, 128, 129)) * 2 + bytes((1, 1, 1, 200)) + bytes((1, 1, 1, 0)) + bytes((64, 64, 192, 136)) * 98
    path = tmp_path / "old.hdr"
    path.write_bytes(HEADER + b"-Y 2 +X 300\n" + pixels + second)
    image = read_hdr(path)
    assert (image[0] == (2.0, 1.0, 0.5)).all()
    assert (image[1, :202] == (255 / 128, 0, 1.0)).all() and (image[1, 202:] == (64, 64, 192)).all()


def test_exposure_and_colorcorr_divide_the_pixels(tmp_path):
    """Radiance: EXPOSURE and COLORCORR say by how much the pixels were multiplied, and
    accumulate: the radiance is the pixel divided by their product."""
    rgbe = np.array([[(128, 128, 128, 130), (255, 192, 64, 130)]])      # (2, 2, 2), (255 / 64, 3, 1)
    header = b"#?RGBE\nEXPOSURE=2\nEXPOSURE= 4.0\nCOLORCORR=1 0.5 0.25\nFORMAT=32-bit_rle_rgbe\n\n"
    image = read_hdr(write_hdr(tmp_path, rgbe, header=header))
    assert image.tolist() == [[[0.25, 0.5, 1.0], [255 / 512, 0.75, 0.5]]]


@pytest.mark.parametrize("resolution", ["-Y 2 +X 3", "+Y 2 +X 3", "-Y 2 -X 3", "+Y 2 -X 3",
                                        "+X 3 -Y 2", "+X 3 +Y 2", "-X 3 -Y 2", "-X 3 +Y 2"])
def test_every_orientation_gives_row_0_at_the_top(tmp_path, resolution):
    """The scanlines are written in the order the resolution line says (Radiance's
    "Picture file format": the first axis is the slow one, - is decreasing): the image
    read is the one written, row 0 at the top, column 0 at the left."""
    rgbe = np.zeros((2, 3, 4), dtype=np.uint8)
    rgbe[..., 0] = np.arange(6).reshape(2, 3) * 16 + 128
    rgbe[..., 3] = 136
    stored = rgbe
    signs = {axis: sign for sign, axis in zip(resolution[0::5], resolution[1::5])}
    if signs["Y"] == "+":
        stored = stored[::-1]
    if signs["X"] == "-":
        stored = stored[:, ::-1]
    if resolution[1] == "X":
        stored = stored.transpose(1, 0, 2)
    path = tmp_path / "turned.hdr"
    path.write_bytes(HEADER + resolution.encode() + b"\n" + np.ascontiguousarray(stored).tobytes())
    assert np.array_equal(read_hdr(path), decoded(rgbe))


@pytest.mark.parametrize("name", ["rle_300x6", "flat_5x3"])
def test_files_written_by_imagecodecs_read_as_imagecodecs_reads_them(name):
    """tests/data/rgbe/ (tools/make_rgbe_test_files.py): read_hdr gives the values that
    imagecodecs' own decoder gives, and they are the floats written to RGBE's precision
    (each channel within 1/128 of the pixel's largest)."""
    expected = np.load(DATA / "expected.npz")
    image = read_hdr(DATA / ("imagecodecs_%s.hdr" % name))
    assert np.array_equal(image, expected[name + "_decoded"])
    written = expected[name + "_written"]
    assert image.shape == written.shape and (image > 0).any()
    assert (np.abs(image - written) <= written.max(axis=2, keepdims=True) / 128).all()


# --- EnvironmentLight ---------------------------------------------------------------------

def test_environment_light_reads_hdr_and_exr_by_suffix(tmp_path):
    rgbe = random_rgbe(4, 8, seed=5)
    for name in ("sky.hdr", "SKY.HDR", "sky.pic"):
        light = EnvironmentLight(write_hdr(tmp_path, rgbe, "rle", name=name), scale=2.0)
        assert np.array_equal(light.texels, 2.0 * decoded(rgbe))
    c = light.radiance(Float3(0.0, 1.0, 0.0))                     # straight up: the top row
    assert (c.x, c.y, c.z) in {tuple(t) for t in light.texels[0]}
    assert np.array_equal(EnvironmentLight(SKY).texels, read_exr(SKY).astype(np.float64))
    (tmp_path / "sky.png").write_bytes(b"")
    with pytest.raises(ValueError, match=r"EnvironmentLight.image .*sky.png: unknown image suffix '.png': it "
                                         r"reads .exr \(OpenEXR\) and .hdr or .pic \(Radiance RGBE\)"):
        EnvironmentLight(tmp_path / "sky.png")


# --- bad input ------------------------------------------------------------------------------

GOOD = random_rgbe(2, 10, seed=7)
GOOD_RLE = scanlines(GOOD, "rle")
FIRST_RLE = len(scanlines(GOOD[:1], "rle"))


@pytest.mark.parametrize("data,words", [
    (b"RADIANCE\n\n-Y 2 +X 10\n" + GOOD.tobytes(), r"line 1: not a Radiance picture: the first line is 'RADIANCE'"),
    (b"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 10\n", r"line 2: FORMAT=32-bit_rle_xyze: only 32-bit_rle_rgbe is read "
                                                           r"\(XYZE pixels are CIE XYZ, not RGB\)"),
    (b"#?RADIANCE\nSOFTWARE=x\nEXPOSURE=-1\n\n-Y 2 +X 10\n", r"line 3: EXPOSURE= must be one number > 0, got '-1'"),
    (b"#?RADIANCE\nEXPOSURE=bright\n\n-Y 2 +X 10\n", r"line 2: EXPOSURE= must be one number > 0, got 'bright'"),
    (b"#?RADIANCE\nCOLORCORR=1 1\n\n-Y 2 +X 10\n", r"line 2: COLORCORR= must be three numbers > 0, got '1 1'"),
    (b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n-Y 2 +X 10\n", r"the header never ends \(no blank line"),
    (HEADER + b"-Y 2 -Y 10\n" + GOOD.tobytes(), r"line 5: bad resolution line '-Y 2 -Y 10': expected '-Y height \+X width'"),
    (HEADER + b"Y 2 X 10\n" + GOOD.tobytes(), r"line 5: bad resolution line 'Y 2 X 10'"),
    (HEADER + b"-Y 2 +X ten\n" + GOOD.tobytes(), r"line 5: bad resolution line '-Y 2 \+X ten'"),
    (HEADER + b"-Y 2 +X 10", r"line 5: bad resolution line"),
    (HEADER + b"-Y 0 +X 10\n", r"line 5: the image is empty"),
    (HEADER + b"-Y 2 +X 10\n" + GOOD.tobytes()[:-3], r"scanline 1 \(byte %d\): truncated" % (len(HEADER) + 11 + 40)),
    (HEADER + b"-Y 2 +X 10\n" + GOOD_RLE[:-1], r"scanline 1 \(byte %d\): truncated" % (len(HEADER) + 11 + FIRST_RLE)),
    (HEADER + b"-Y 2 +X 10\n" + GOOD_RLE[:FIRST_RLE], r"scanline 1 \(byte %d\): truncated" % (len(HEADER) + 11 + FIRST_RLE)),
    (HEADER + b"-Y 2 +X 10\n" + bytes((2, 2, 0, 9)) + GOOD_RLE[4:], r"scanline 0 \(byte %d\): run-length encoded for a "
                                                                    r"width of 9, the image is 10 wide" % (len(HEADER) + 11)),
    (HEADER + b"-Y 1 +X 10\n" + bytes((2, 2, 0, 10, 0)), r"scanline 0 \(byte %d\), channel 0: a run of length 0 at byte %d"
                                                          % (len(HEADER) + 11, len(HEADER) + 15)),
    (HEADER + b"-Y 1 +X 10\n" + bytes((2, 2, 0, 10, 136, 7, 131, 7)), r"channel 0: a run of 3 at byte %d runs past the "
                                                                      r"scanline's 10 pixels" % (len(HEADER) + 17)),
    (HEADER + b"-Y 1 +X 10\n" + bytes((2, 2, 0, 10, 8, 1, 2, 3, 4, 5, 6, 7, 8, 9)), r"channel 0: a run of 9 at byte"),
    (HEADER + b"-Y 1 +X 3\n" + bytes((1, 1, 1, 3)), r"scanline 0 \(byte %d\): a repeat of 3 pixels at byte %d with no pixel "
                                                   r"before it" % (len(HEADER) + 10, len(HEADER) + 10)),
    (HEADER + b"-Y 1 +X 3\n" + bytes((128, 128, 128, 128, 1, 1, 1, 3)), r"a repeat of 3 pixels at byte %d runs past the "
                                                                       r"scanline's 3 pixels" % (len(HEADER) + 14)),
])
def test_bad_input_names_the_file_and_what_is_wrong(tmp_path, data, words):
    path = tmp_path / "bad.hdr"
    path.write_bytes(data)
    for read in (read_hdr, EnvironmentLight):
        with pytest.raises(ValueError, match=words) as error:
            read(path)
        assert str(error.value).startswith("read_hdr: %s" % path), (read, str(error.value))


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises(ValueError, match="read_hdr: no such file .*missing.hdr"):
        EnvironmentLight(tmp_path / "missing.hdr")
