#!/usr/bin/env python3
"""Writes the small test images of tests/reference/image_formats_*.pov in every file format
and variant POV-Ray 3.7 reads besides PNG: TGA, PPM/PGM, Radiance HDR, GIF and JPEG.

Every file is written by the plain Python encoders below (no imaging library), except the
JPEG files: JPEG needs a DCT encoder, so they are written with Pillow when it is installed
(`pip install pillow`); without it the committed JPEG files are left as they are.

All images show the same 16x16 pictures, so one scene can compare formats side by side:
- colour: red rises to the right, green rises downwards, blue is a 4x4 checker;
- grey: a smooth dome (brightest in the middle), also used for height fields;
- alpha: opaque on the left half, fading out to the right;
- palette: 16 colours, index = 4x4 blocks numbered row by row.

usage: python3 make_images.py   (writes into the folder holding this script)
"""

import math
import os
import struct
import sys

SIZE = 16
HERE = os.path.dirname(os.path.abspath(__file__))


def colour(column, row):
    """The 8-bit red, green, blue of the colour picture."""
    checker = ((column // 4) + (row // 4)) % 2
    return (16 * column + 8, 16 * row + 8, 200 if checker else 40)


def colour16(column, row):
    """The 16-bit colour picture: the 8-bit one with low bytes that only 16 bits keep."""
    return tuple(value * 256 + (column * 16 + row) % 256 for value in colour(column, row))


def dome(column, row):
    """The grey picture as a level from 0 to 1."""
    dx = (column - 7.5) / 8.0
    dy = (row - 7.5) / 8.0
    return max(0.0, 1.0 - (dx * dx + dy * dy)) * 0.85 + 0.1


def grey8(column, row):
    return round(dome(column, row) * 255)


def grey16(column, row):
    return round(dome(column, row) * 65535)


def alpha(column, row):
    return 255 if column < 8 else 255 - (column - 7) * 30


PALETTE = [
    (0, 0, 0), (255, 255, 255), (230, 40, 40), (40, 200, 60),
    (40, 80, 230), (240, 220, 40), (40, 220, 220), (220, 60, 220),
    (128, 128, 128), (255, 140, 0), (120, 60, 20), (0, 100, 0),
    (100, 0, 140), (250, 180, 190), (60, 60, 100), (180, 250, 150),
]


def palette_index(column, row):
    return (column // 4) + 4 * (row // 4)


def pixels(function):
    """`function(column, row)` for every pixel, rows from the top."""
    return [[function(column, row) for column in range(SIZE)] for row in range(SIZE)]


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as file:
        file.write(data)


# --- TGA ----------------------------------------------------------------------------------


def tga_rle_row(row_bytes, pixel_size):
    """One row as RLE packets (runs of 2 or more equal pixels, raw packets otherwise)."""
    items = [row_bytes[i:i + pixel_size] for i in range(0, len(row_bytes), pixel_size)]
    out = bytearray()
    i = 0
    while i < len(items):
        run = 1
        while i + run < len(items) and items[i + run] == items[i] and run < 128:
            run += 1
        if run >= 2:
            out.append(0x80 | (run - 1))
            out += items[i]
            i += run
            continue
        start = i
        while i < len(items) and i - start < 128:
            if i + 1 < len(items) and items[i + 1] == items[i]:
                break
            i += 1
        out.append(i - start - 1)
        for item in items[start:i]:
            out += item
    return bytes(out)


def tga(name, kind, rows, rle=False, top_first=False, colour_map=None):
    """A TGA file. `kind` is "rgb", "rgba", "grey" or "mapped"; `rows` hold per-pixel
    tuples (rgb, rgba), grey levels or palette indices."""
    image_type = {"rgb": 2, "rgba": 2, "grey": 3, "mapped": 1}[kind] + (8 if rle else 0)
    depth = {"rgb": 24, "rgba": 32, "grey": 8, "mapped": 8}[kind]
    descriptor = (8 if kind == "rgba" else 0) | (0x20 if top_first else 0)
    map_bytes = b""
    if colour_map:
        map_bytes = b"".join(bytes((b, g, r)) for r, g, b in colour_map)
    header = struct.pack(
        "<BBBHHBHHHHBB", 0, 1 if colour_map else 0, image_type, 0,
        len(colour_map or []), 24 if colour_map else 0, 0, 0, SIZE, SIZE, depth, descriptor)
    stored = rows if top_first else list(reversed(rows))
    body = bytearray()
    for row in stored:
        if kind == "rgb":
            row_bytes = b"".join(bytes((b, g, r)) for r, g, b in row)
        elif kind == "rgba":
            row_bytes = b"".join(bytes((b, g, r, a)) for r, g, b, a in row)
        else:
            row_bytes = bytes(row)
        body += tga_rle_row(row_bytes, depth // 8) if rle else row_bytes
    write(name, header + map_bytes + bytes(body))


# --- PPM / PGM ----------------------------------------------------------------------------


def netpbm(name, magic, rows, maxval):
    """A PPM (P3, P6) or PGM (P2, P5) file; `rows` hold rgb tuples or grey levels."""
    samples = []
    for row in rows:
        for value in row:
            samples.extend(value if isinstance(value, tuple) else (value,))
    header = f"{magic}\n# written by make_images.py\n{SIZE} {SIZE}\n{maxval}\n".encode()
    if magic in ("P3", "P2"):
        per_line = SIZE * (3 if magic == "P3" else 1)
        lines = [" ".join(str(s) for s in samples[i:i + per_line])
                 for i in range(0, len(samples), per_line)]
        write(name, header + ("\n".join(lines) + "\n").encode())
    else:
        code = ">H" if maxval > 255 else ">B"
        write(name, header + b"".join(struct.pack(code, s) for s in samples))


# --- Radiance HDR -------------------------------------------------------------------------


def rgbe(red, green, blue):
    """One linear colour as Radiance's shared-exponent bytes."""
    largest = max(red, green, blue)
    if largest < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(largest)
    scale = mantissa * 256.0 / largest
    return bytes((int(red * scale), int(green * scale), int(blue * scale), exponent + 128))


def hdr_colour(column, row):
    """The HDR picture: the colour picture's ramps in linear light, up to 3 in red."""
    r, g, b = colour(column, row)
    return (3.0 * r / 255.0, g / 255.0, b / 255.0 * 0.5)


def hdr_rle_row(row_bytes):
    """A row in the new run-length scheme: the four byte planes one after the other."""
    out = bytearray((2, 2, SIZE >> 8, SIZE & 255))
    for plane in range(4):
        values = [pixel[plane] for pixel in row_bytes]
        i = 0
        while i < len(values):
            run = 1
            while i + run < len(values) and values[i + run] == values[i] and run < 127:
                run += 1
            if run >= 3:
                out += bytes((128 + run, values[i]))
                i += run
                continue
            start = i
            while i < len(values) and i - start < 128:
                if i + 2 < len(values) and values[i] == values[i + 1] == values[i + 2]:
                    break
                i += 1
            out.append(i - start)
            out += bytes(values[start:i])
    return bytes(out)


def hdr(name, rle):
    header = b"#?RADIANCE\n# written by make_images.py\nFORMAT=32-bit_rle_rgbe\n\n"
    header += f"-Y {SIZE} +X {SIZE}\n".encode()
    body = bytearray()
    for row in pixels(lambda c, r: rgbe(*hdr_colour(c, r))):
        body += hdr_rle_row(row) if rle else b"".join(row)
    write(name, header + bytes(body))


# --- GIF ----------------------------------------------------------------------------------


def lzw(indices, minimum_size):
    """GIF's LZW compression of palette indices."""
    clear, end = 1 << minimum_size, (1 << minimum_size) + 1
    out = bytearray()
    bits = {"value": 0, "count": 0}

    def emit(code, size):
        bits["value"] |= code << bits["count"]
        bits["count"] += size
        while bits["count"] >= 8:
            out.append(bits["value"] & 255)
            bits["value"] >>= 8
            bits["count"] -= 8

    def fresh():
        return {(i,): i for i in range(clear)}, end + 1, minimum_size + 1

    table, next_code, size = fresh()
    emit(clear, size)
    current = ()
    for index in indices:
        extended = current + (index,)
        if extended in table:
            current = extended
            continue
        emit(table[current], size)
        if next_code < 4096:
            table[extended] = next_code
            next_code += 1
            if next_code > (1 << size) and size < 12:
                size += 1
        else:
            emit(clear, size)
            table, next_code, size = fresh()
        current = (index,)
    emit(table[current], size)
    emit(end, size)
    if bits["count"]:
        out.append(bits["value"] & 255)
    return bytes(out)


def gif(name, transparent=None, interlaced=False):
    """A 16-colour GIF89a of the palette picture, optionally with a transparent index."""
    rows = pixels(palette_index)
    if interlaced:
        order = [r for start, step in ((0, 8), (4, 8), (2, 4), (1, 2))
                 for r in range(start, SIZE, step)]
        rows = [rows[r] for r in order]
    data = bytearray(b"GIF89a")
    data += struct.pack("<HHBBB", SIZE, SIZE, 0x80 | 0x30 | 3, 0, 0)
    data += b"".join(bytes(entry) for entry in PALETTE)
    if transparent is not None:
        data += bytes((0x21, 0xF9, 4, 1, 0, 0, transparent, 0))
    data += struct.pack("<BHHHHB", 0x2C, 0, 0, SIZE, SIZE, 0x40 if interlaced else 0)
    compressed = lzw([index for row in rows for index in row], 4)
    data.append(4)
    for i in range(0, len(compressed), 255):
        block = compressed[i:i + 255]
        data.append(len(block))
        data += block
    data += b"\x00\x3b"
    write(name, bytes(data))


# --- JPEG (Pillow) ------------------------------------------------------------------------


def jpegs():
    try:
        from PIL import Image
    except ImportError:
        print("Pillow is not installed: the JPEG files are left as they are", file=sys.stderr)
        return
    picture = Image.new("RGB", (SIZE, SIZE))
    picture.putdata([colour(c, r) for r in range(SIZE) for c in range(SIZE)])
    picture.save(os.path.join(HERE, "jpeg_baseline.jpg"), quality=95, subsampling=0)
    picture.save(os.path.join(HERE, "jpeg_progressive.jpg"), quality=95, subsampling=2,
                 progressive=True)
    grey = Image.new("L", (SIZE, SIZE))
    grey.putdata([grey8(c, r) for r in range(SIZE) for c in range(SIZE)])
    grey.save(os.path.join(HERE, "jpeg_grey.jpg"), quality=95)


def main():
    rgb = pixels(colour)
    rgba = pixels(lambda c, r: colour(c, r) + (alpha(c, r),))
    grey = pixels(grey8)
    mapped = pixels(palette_index)
    tga("tga_rgb24.tga", "rgb", rgb)
    tga("tga_rgb24_top.tga", "rgb", rgb, top_first=True)
    tga("tga_rgb24_rle.tga", "rgb", rgb, rle=True)
    tga("tga_rgba32.tga", "rgba", rgba)
    tga("tga_rgba32_rle.tga", "rgba", rgba, rle=True, top_first=True)
    tga("tga_grey8.tga", "grey", grey)
    tga("tga_grey8_rle.tga", "grey", grey, rle=True)
    tga("tga_mapped8.tga", "mapped", mapped, colour_map=PALETTE)
    tga("tga_mapped8_rle.tga", "mapped", mapped, rle=True, colour_map=PALETTE)
    netpbm("ppm_p6_8.ppm", "P6", rgb, 255)
    netpbm("ppm_p6_16.ppm", "P6", pixels(colour16), 65535)
    netpbm("ppm_p3_8.ppm", "P3", rgb, 255)
    netpbm("ppm_p3_16.ppm", "P3", pixels(colour16), 65535)
    netpbm("pgm_p5_8.pgm", "P5", grey, 255)
    netpbm("pgm_p5_16.pgm", "P5", pixels(grey16), 65535)
    netpbm("pgm_p2_8.pgm", "P2", grey, 255)
    netpbm("pgm_p2_16.pgm", "P2", pixels(grey16), 65535)
    hdr("hdr_flat.hdr", rle=False)
    hdr("hdr_rle.hdr", rle=True)
    gif("gif_palette.gif")
    gif("gif_transparent.gif", transparent=5)
    gif("gif_interlaced.gif", interlaced=True)
    jpegs()


if __name__ == "__main__":
    main()
