"""PNG decoding and the image comparison metric shared by durer's scripts.

Standard library only. The decoder reads every PNG that POV-Ray or durer can
plausibly write: bit depths 1/2/4/8/16, greyscale, RGB, palette, grey+alpha and
RGBA, all five scanline filters, and Adam7 interlacing. Pixels come back as RGB
in the 0..255 scale (16-bit samples are divided by 257, so they stay floats);
alpha is dropped because POV-Ray writes opaque images unless asked otherwise.

The metric (the same definition as tests/integration/reference_images.rs):

* a pixel is *over* when any channel differs by more than 24/255;
* an image *matches* when at most 2% of pixels are over (the tolerance);
* an image is *close* when the means of 4x4 pixel blocks (per channel) differ
  by at most 6/255 on average over all blocks and channels.
"""

import struct
import zlib

PIXEL_THRESHOLD = 24.0  # per-channel difference, in 0..255 units
MATCH_FRACTION = 0.02  # fraction of pixels allowed over the threshold
BLOCK_SIZE = 4
CLOSE_BLOCK_DIFF = 6.0  # mean absolute 4x4-block difference, in 0..255 units

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"

# Samples per pixel for each PNG colour type.
CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}

# Adam7 passes: (x start, y start, x step, y step).
ADAM7 = [
    (0, 0, 8, 8),
    (4, 0, 8, 8),
    (0, 4, 4, 8),
    (2, 0, 4, 4),
    (0, 2, 2, 4),
    (1, 0, 2, 2),
    (0, 1, 1, 2),
]


class PngError(Exception):
    """The file is not a PNG this decoder understands."""


class Image:
    """An RGB image: `pixels` is a flat list [r, g, b, r, g, b, ...] in 0..255."""

    def __init__(self, width, height, pixels):
        self.width = width
        self.height = height
        self.pixels = pixels

    def pixel(self, x, y):
        i = 3 * (y * self.width + x)
        return tuple(self.pixels[i : i + 3])


def _paeth(a, b, c):
    p = a + b - c
    pa = abs(p - a)
    pb = abs(p - b)
    pc = abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    if pb <= pc:
        return b
    return c


def _unfilter(data, offset, rows, row_bytes, bpp):
    """Undo the per-scanline filters of one (sub)image; returns rows and the new offset."""
    out = []
    prev = bytearray(row_bytes)
    for _ in range(rows):
        if offset + 1 + row_bytes > len(data):
            raise PngError("image data is truncated")
        kind = data[offset]
        row = bytearray(data[offset + 1 : offset + 1 + row_bytes])
        offset += 1 + row_bytes
        if kind == 0:
            pass
        elif kind == 1:  # Sub
            for i in range(bpp, row_bytes):
                row[i] = (row[i] + row[i - bpp]) & 0xFF
        elif kind == 2:  # Up
            for i in range(row_bytes):
                row[i] = (row[i] + prev[i]) & 0xFF
        elif kind == 3:  # Average
            for i in range(row_bytes):
                left = row[i - bpp] if i >= bpp else 0
                row[i] = (row[i] + ((left + prev[i]) >> 1)) & 0xFF
        elif kind == 4:  # Paeth
            for i in range(row_bytes):
                left = row[i - bpp] if i >= bpp else 0
                upper_left = prev[i - bpp] if i >= bpp else 0
                row[i] = (row[i] + _paeth(left, prev[i], upper_left)) & 0xFF
        else:
            raise PngError(f"unknown filter type {kind}")
        out.append(row)
        prev = row
    return out, offset


def _samples(row, count, depth):
    """The first `count` samples of an unfiltered scanline, as integers."""
    if depth == 8:
        return list(row[:count])
    if depth == 16:
        return list(struct.unpack(f">{count}H", bytes(row[: 2 * count])))
    per_byte = 8 // depth
    mask = (1 << depth) - 1
    values = []
    for i in range(count):
        byte = row[i // per_byte]
        shift = 8 - depth * (i % per_byte + 1)
        values.append((byte >> shift) & mask)
    return values


def decode_png(data):
    """Decode PNG bytes into an `Image` (RGB, 0..255 floats or ints)."""
    if not data.startswith(PNG_SIGNATURE):
        raise PngError("not a PNG file (bad signature)")
    pos = len(PNG_SIGNATURE)
    header = None
    palette = None
    idat = []
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos : pos + 8])
        body = data[pos + 8 : pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"PLTE":
            palette = [tuple(body[i : i + 3]) for i in range(0, len(body) - 2, 3)]
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if header is None:
        raise PngError("missing IHDR chunk")
    width, height, depth, color_type, _compression, _filter, interlace = header
    if color_type not in CHANNELS:
        raise PngError(f"unsupported colour type {color_type}")
    if depth not in (1, 2, 4, 8, 16):
        raise PngError(f"unsupported bit depth {depth}")
    if color_type == 3 and palette is None:
        raise PngError("palette image without PLTE chunk")
    try:
        raw = zlib.decompress(b"".join(idat))
    except zlib.error as error:
        raise PngError(f"corrupt image data: {error}") from error

    channels = CHANNELS[color_type]
    bits_per_pixel = channels * depth
    bpp = max(1, bits_per_pixel // 8)
    # Scale samples to 0..255; palette indices stay as they are.
    scale = 1.0 if color_type == 3 else 255.0 / ((1 << depth) - 1)
    if depth == 8 and color_type != 3:
        scale = 1

    pixels = [0] * (3 * width * height)

    def store(x, y, s):
        i = 3 * (y * width + x)
        if color_type == 3:
            if s[0] >= len(palette):
                raise PngError("palette index out of range")
            pixels[i : i + 3] = palette[s[0]]
        elif channels <= 2:  # grey, grey+alpha
            v = s[0] * scale
            pixels[i] = pixels[i + 1] = pixels[i + 2] = v
        else:  # RGB, RGBA
            pixels[i] = s[0] * scale
            pixels[i + 1] = s[1] * scale
            pixels[i + 2] = s[2] * scale

    passes = ADAM7 if interlace == 1 else [(0, 0, 1, 1)]
    offset = 0
    for x0, y0, dx, dy in passes:
        pass_width = (width - x0 + dx - 1) // dx if width > x0 else 0
        pass_height = (height - y0 + dy - 1) // dy if height > y0 else 0
        if pass_width == 0 or pass_height == 0:
            continue
        row_bytes = (pass_width * bits_per_pixel + 7) // 8
        rows, offset = _unfilter(raw, offset, pass_height, row_bytes, bpp)
        for j, row in enumerate(rows):
            values = _samples(row, pass_width * channels, depth)
            y = y0 + j * dy
            for k in range(pass_width):
                store(x0 + k * dx, y, values[k * channels : (k + 1) * channels])
    return Image(width, height, pixels)


def read_png(path):
    """Read and decode a PNG file."""
    with open(path, "rb") as handle:
        return decode_png(handle.read())


class Comparison:
    """The metric for one pair of images."""

    def __init__(self, fraction_over, block_diff, max_diff):
        self.fraction_over = fraction_over  # fraction of pixels over the threshold
        self.block_diff = block_diff  # mean absolute 4x4-block difference, 0..255
        self.max_diff = max_diff  # largest channel difference, 0..255

    def matches(self, tolerance=MATCH_FRACTION):
        return self.fraction_over <= tolerance

    def close(self):
        return self.block_diff <= CLOSE_BLOCK_DIFF

    def verdict(self, tolerance=MATCH_FRACTION):
        if self.matches(tolerance):
            return "match"
        if self.close():
            return "close"
        return "differ"

    def __str__(self):
        return (
            f"over {PIXEL_THRESHOLD:g}/255: {100 * self.fraction_over:.2f}% of pixels, "
            f"block diff: {self.block_diff:.2f}/255, max diff: {self.max_diff:.0f}/255"
        )


def compare(a, b):
    """Compare two images of the same size; raises ValueError when sizes differ."""
    if (a.width, a.height) != (b.width, b.height):
        raise ValueError(f"size differs: {a.width}x{a.height} vs {b.width}x{b.height}")
    width, height = a.width, a.height
    pa, pb = a.pixels, b.pixels
    diffs = [abs(x - y) for x, y in zip(pa, pb)]
    over = 0
    for i in range(0, len(diffs), 3):
        if max(diffs[i], diffs[i + 1], diffs[i + 2]) > PIXEL_THRESHOLD:
            over += 1
    max_diff = max(diffs) if diffs else 0

    # Per-channel block means; blocks at the right and bottom edges may be partial.
    block_total = 0.0
    block_count = 0
    for by in range(0, height, BLOCK_SIZE):
        for bx in range(0, width, BLOCK_SIZE):
            sums = [0.0] * 6
            n = 0
            for y in range(by, min(by + BLOCK_SIZE, height)):
                base = 3 * (y * width)
                for x in range(bx, min(bx + BLOCK_SIZE, width)):
                    i = base + 3 * x
                    sums[0] += pa[i]
                    sums[1] += pa[i + 1]
                    sums[2] += pa[i + 2]
                    sums[3] += pb[i]
                    sums[4] += pb[i + 1]
                    sums[5] += pb[i + 2]
                    n += 1
            for c in range(3):
                block_total += abs(sums[c] - sums[c + 3]) / n
                block_count += 1
    pixel_count = width * height
    return Comparison(
        over / pixel_count if pixel_count else 0.0,
        block_total / block_count if block_count else 0.0,
        max_diff,
    )


def compare_files(path_a, path_b):
    """Decode two PNG files and compare them."""
    return compare(read_png(path_a), read_png(path_b))
