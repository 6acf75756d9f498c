#!/usr/bin/env python3
"""Self-tests for scripts/imagediff.py: python3 scripts/test_imagediff.py

The PNGs are built here by a deliberately naive encoder that can apply any
scanline filter and Adam7 interlacing, so every decoder path is exercised
without third-party packages.
"""

import os
import struct
import sys
import unittest
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import imagediff  # noqa: E402


def _chunk(kind, body):
    crc = zlib.crc32(kind + body) & 0xFFFFFFFF
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", crc)


def _pack_row(samples, depth):
    if depth == 8:
        return bytes(samples)
    if depth == 16:
        return struct.pack(f">{len(samples)}H", *samples)
    out = bytearray((len(samples) * depth + 7) // 8)
    per_byte = 8 // depth
    for i, s in enumerate(samples):
        out[i // per_byte] |= s << (8 - depth * (i % per_byte + 1))
    return bytes(out)


def _filter_row(kind, row, prev, bpp):
    out = bytearray(len(row))
    for i, value in enumerate(row):
        left = row[i - bpp] if i >= bpp else 0
        up = prev[i]
        upper_left = prev[i - bpp] if i >= bpp else 0
        if kind == 0:
            predictor = 0
        elif kind == 1:
            predictor = left
        elif kind == 2:
            predictor = up
        elif kind == 3:
            predictor = (left + up) >> 1
        else:
            predictor = imagediff._paeth(left, up, upper_left)
        out[i] = (value - predictor) & 0xFF
    return bytes([kind]) + bytes(out)


def encode_png(width, height, samples, color_type, depth=8, interlace=False, palette=None):
    """samples[y][x] is a tuple of channel values; filters cycle through all five types."""
    channels = imagediff.CHANNELS[color_type]
    bpp = max(1, channels * depth // 8)
    passes = imagediff.ADAM7 if interlace else [(0, 0, 1, 1)]
    raw = bytearray()
    filter_kind = 0
    for x0, y0, dx, dy in passes:
        xs = list(range(x0, width, dx))
        ys = list(range(y0, height, dy))
        if not xs or not ys:
            continue
        prev = bytes(len(_pack_row([0] * (len(xs) * channels), depth)))
        for y in ys:
            row = _pack_row([v for x in xs for v in samples[y][x]], depth)
            raw += _filter_row(filter_kind % 5, row, prev, bpp)
            filter_kind += 1
            prev = row
    header = struct.pack(">IIBBBBB", width, height, depth, color_type, 0, 0, 1 if interlace else 0)
    data = imagediff.PNG_SIGNATURE + _chunk(b"IHDR", header)
    if palette is not None:
        data += _chunk(b"PLTE", b"".join(bytes(p) for p in palette))
    # Split the image data over two IDAT chunks, as encoders may.
    compressed = zlib.compress(bytes(raw))
    half = len(compressed) // 2
    data += _chunk(b"IDAT", compressed[:half]) + _chunk(b"IDAT", compressed[half:])
    return data + _chunk(b"IEND", b"")


def pattern(width, height, x_shift=0):
    """A colourful test image as rows of (r, g, b) tuples in 0..255."""
    return [
        [
            (((x + x_shift) * 37) % 256, (y * 53) % 256, (((x + x_shift) // 4 + y // 4) % 2) * 255)
            for x in range(width)
        ]
        for y in range(height)
    ]


class DecoderTests(unittest.TestCase):
    W, H = 13, 11  # odd sizes exercise partial Adam7 passes and partial blocks

    def check(self, data, expected):
        image = imagediff.decode_png(data)
        self.assertEqual((image.width, image.height), (self.W, self.H))
        for y in range(self.H):
            for x in range(self.W):
                got = image.pixel(x, y)
                for g, e in zip(got, expected[y][x]):
                    self.assertAlmostEqual(g, e, places=6, msg=f"pixel {x},{y}")

    def test_rgb8_all_filters(self):
        rgb = pattern(self.W, self.H)
        for interlace in (False, True):
            self.check(encode_png(self.W, self.H, rgb, 2, interlace=interlace), rgb)

    def test_rgba8_drops_alpha(self):
        rgb = pattern(self.W, self.H)
        rgba = [[p + (x * 19 % 256,) for x, p in enumerate(row)] for row in rgb]
        for interlace in (False, True):
            self.check(encode_png(self.W, self.H, rgba, 6, interlace=interlace), rgb)

    def test_rgb16(self):
        rgb = pattern(self.W, self.H)
        # Odd 16-bit values that are not multiples of 257 must stay fractional.
        wide = [[tuple(v * 257 - (v > 0) for v in p) for p in row] for row in rgb]
        expected = [[tuple((v * 257 - (v > 0)) / 257 for v in p) for p in row] for row in rgb]
        for interlace in (False, True):
            self.check(encode_png(self.W, self.H, wide, 2, depth=16, interlace=interlace), expected)

    def test_rgba16(self):
        rgb = pattern(self.W, self.H)
        wide = [[tuple(v * 257 for v in p) + (65535,) for p in row] for row in rgb]
        self.check(encode_png(self.W, self.H, wide, 6, depth=16), rgb)

    def test_grey_depths(self):
        for depth in (1, 2, 4, 8, 16):
            top = (1 << depth) - 1
            grey = [[((x * 7 + y * 3) % (top + 1),) for x in range(self.W)] for y in range(self.H)]
            expected = [[(g[0] * 255 / top,) * 3 for g in row] for row in grey]
            for interlace in (False, True):
                data = encode_png(self.W, self.H, grey, 0, depth=depth, interlace=interlace)
                self.check(data, expected)

    def test_grey_alpha(self):
        grey = [[((x * 20) % 256, 255) for x in range(self.W)] for _ in range(self.H)]
        expected = [[(g[0],) * 3 for g in row] for row in grey]
        self.check(encode_png(self.W, self.H, grey, 4), expected)
        wide = [[(g[0] * 257, 65535) for g in row] for row in grey]
        self.check(encode_png(self.W, self.H, wide, 4, depth=16), expected)

    def test_palette(self):
        palette = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (9, 99, 199)]
        for depth in (2, 4, 8):
            index = [[((x + y) % 4,) for x in range(self.W)] for y in range(self.H)]
            expected = [[palette[i[0]] for i in row] for row in index]
            data = encode_png(self.W, self.H, index, 3, depth=depth, palette=palette)
            self.check(data, expected)

    def test_rejects_garbage(self):
        with self.assertRaises(imagediff.PngError):
            imagediff.decode_png(b"GIF89a not a png")


class MetricTests(unittest.TestCase):
    def image(self, rows):
        return imagediff.Image(
            len(rows[0]), len(rows), [float(v) for row in rows for p in row for v in p]
        )

    def test_identical_images_match(self):
        a = self.image(pattern(40, 30))
        result = imagediff.compare(a, a)
        self.assertEqual(result.fraction_over, 0)
        self.assertEqual(result.block_diff, 0)
        self.assertEqual(result.max_diff, 0)
        self.assertEqual(result.verdict(), "match")

    def test_shifted_image_differs(self):
        a = self.image(pattern(40, 30))
        b = self.image(pattern(40, 30, x_shift=1))
        result = imagediff.compare(a, b)
        self.assertGreater(result.fraction_over, 0.5)
        self.assertEqual(result.verdict(), "differ")

    def test_threshold_is_strict(self):
        a = self.image([[(100, 100, 100)] * 8] * 8)
        b = self.image([[(124, 100, 100)] * 8] * 8)
        c = self.image([[(100, 100, 125)] * 8] * 8)
        self.assertEqual(imagediff.compare(a, b).fraction_over, 0)
        self.assertEqual(imagediff.compare(a, c).fraction_over, 1)
        self.assertAlmostEqual(imagediff.compare(a, c).block_diff, 25 / 3)

    def test_speckle_is_close(self):
        # One pixel in each 4x4 block is off by 64: 1/16 of pixels over, block means off by 4/3.
        rows_a = [[(50, 50, 50)] * 16 for _ in range(16)]
        rows_b = [[(114, 50, 50) if x % 4 == 0 and y % 4 == 0 else (50, 50, 50)
                   for x in range(16)] for y in range(16)]
        result = imagediff.compare(self.image(rows_a), self.image(rows_b))
        self.assertAlmostEqual(result.fraction_over, 1 / 16)
        self.assertAlmostEqual(result.block_diff, 64 / 16 / 3)
        self.assertEqual(result.max_diff, 64)
        self.assertEqual(result.verdict(), "close")
        self.assertEqual(result.verdict(tolerance=0.1), "match")

    def test_size_mismatch_raises(self):
        with self.assertRaises(ValueError):
            imagediff.compare(self.image(pattern(8, 8)), self.image(pattern(8, 4)))


if __name__ == "__main__":
    unittest.main()
