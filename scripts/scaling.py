#!/usr/bin/env python3
"""How parse, bounding, render time and memory grow with the number of objects.

Renders benchmarks/spheres_n.pov (N spheres on a lattice, seen whole) for N from 10 thousand
up to 10 million with `--stats json`, prints a table, and draws docs/scaling.svg: each
quantity relative to its value at the smallest N, on log axes, beside the line of linear
growth (a quantity growing linearly runs parallel to it; render time, which follows the
BVH's depth, stays below it). Raises durer's `objects` and `geometry-memory` limits for the
largest counts (10 million spheres need about 7 GiB).

    scripts/scaling.py [--binary target/release/durer] [--counts 1e4,1e5,1e6,3e6,1e7]
                       [--threads 1] [--size 320x240] [--svg docs/scaling.svg]
"""

import argparse
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "benchmarks" / "spheres_n.pov"

SERIES = [
    ("parse", "parse time", "#1f77b4"),
    ("bounding", "bounding time", "#ff7f0e"),
    ("render", "render time", "#2ca02c"),
    ("memory", "peak memory", "#d62728"),
]


def measure(binary, count, threads, width, height):
    """One render's statistics: seconds per phase and peak memory."""
    command = [
        str(binary), "render", str(SCENE), "--define", f"N={count}",
        "-o", "/tmp/durer-scaling.png", "--width", str(width), "--height", str(height),
        "--threads", str(threads), "--stats", "json", "--quiet",
        "--limit", f"objects={max(count, 5_000_000)}",
        "--limit", "geometry-memory=64000000000",
    ]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        sys.exit(f"durer failed for N={count}:\n{done.stderr}")
    stats = json.loads(done.stdout.strip().splitlines()[-1]
                       if done.stdout.strip() else done.stderr.strip().splitlines()[-1])
    seconds = stats["seconds"]
    return {
        "count": count,
        "objects": stats["objects"],
        "parse": seconds["parse"],
        "bounding": seconds["bounding"],
        "render": seconds["render"],
        "memory": stats["peak_memory_bytes"],
    }


def svg_chart(rows, title):
    """A log-log chart of each quantity relative to its value at the smallest count, beside
    the line of linear growth (plain SVG, no plotting library)."""
    import math

    width, height = 720, 440
    left, right, top, bottom = 70, 200, 40, 60
    first = rows[0]
    xs = [math.log10(row["count"]) for row in rows]
    x_low, x_high = math.floor(min(xs)), math.ceil(max(xs))
    ratios = {key: [max(row[key], 1e-9) / max(first[key], 1e-9) for row in rows]
              for key, _, _ in SERIES}
    linear = [row["count"] / first["count"] for row in rows]
    every = [value for series in ratios.values() for value in series] + linear
    y_low = math.floor(math.log10(min(every)))
    y_high = math.ceil(math.log10(max(every)))

    def px(x):
        return left + (x - x_low) / max(x_high - x_low, 1e-9) * (width - left - right)

    def py(y):
        return top + (y_high - y) / max(y_high - y_low, 1e-9) * (height - top - bottom)

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'font-family="sans-serif" font-size="12">',
        f'<rect width="{width}" height="{height}" fill="white"/>',
        f'<text x="{left}" y="22" font-size="14">{title}</text>',
    ]
    for power in range(x_low, x_high + 1):
        x = px(power)
        out.append(f'<line x1="{x}" y1="{top}" x2="{x}" y2="{py(y_low)}" stroke="#ddd"/>')
        out.append(f'<text x="{x}" y="{py(y_low) + 18}" text-anchor="middle">10^{power}</text>')
    for power in range(y_low, y_high + 1):
        y = py(power)
        out.append(f'<line x1="{left}" y1="{y}" x2="{px(x_high)}" y2="{y}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{y + 4}" text-anchor="end">{10.0 ** power:g}x</text>')
    out.append(f'<text x="{(left + px(x_high)) / 2}" y="{height - 15}" '
               f'text-anchor="middle">spheres (log scale)</text>')
    out.append(f'<text x="16" y="{(top + py(y_low)) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 16 {(top + py(y_low)) / 2})">'
               f'relative to {first["count"]:,} spheres (log scale)</text>')

    def line(values, colour, dashed=False):
        points = " ".join(f"{px(x):.1f},{py(math.log10(v)):.1f}" for x, v in zip(xs, values))
        dash = ' stroke-dasharray="6,4"' if dashed else ""
        out.append(f'<polyline points="{points}" fill="none" stroke="{colour}" '
                   f'stroke-width="2"{dash}/>')

    line(linear, "#888", dashed=True)
    entries = [("linear growth (x N)", "#888", True)]
    for key, label, colour in SERIES:
        line(ratios[key], colour)
        for x, value in zip(xs, ratios[key]):
            out.append(f'<circle cx="{px(x):.1f}" cy="{py(math.log10(value)):.1f}" r="3" '
                       f'fill="{colour}"/>')
        entries.append((label, colour, False))
    for index, (label, colour, dashed) in enumerate(entries):
        ly = top + 20 + 22 * index
        dash = ' stroke-dasharray="6,4"' if dashed else ""
        out.append(f'<line x1="{width - right + 15}" y1="{ly}" x2="{width - right + 35}" '
                   f'y2="{ly}" stroke="{colour}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{width - right + 40}" y="{ly + 4}">{label}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(ROOT / "target" / "release" / "durer"))
    parser.add_argument("--counts", default="1e4,1e5,1e6,3e6,1e7")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--size", default="320x240")
    parser.add_argument("--svg", default=str(ROOT / "docs" / "scaling.svg"))
    args = parser.parse_args()
    width, height = (int(part) for part in args.size.split("x"))
    counts = [int(float(part)) for part in args.counts.split(",")]
    rows = []
    print("| spheres | parse s | bounding s | render s | peak MiB | parse µs/object | "
          "bounding µs/object | render µs/object | bytes/object |")
    print("|---|---|---|---|---|---|---|---|---|")
    for count in counts:
        row = measure(args.binary, count, args.threads, width, height)
        rows.append(row)
        print(f"| {count:,} | {row['parse']:.2f} | {row['bounding']:.2f} | "
              f"{row['render']:.3f} | {row['memory'] / 2**20:.0f} | "
              f"{row['parse'] / count * 1e6:.2f} | {row['bounding'] / count * 1e6:.2f} | "
              f"{row['render'] / count * 1e6:.3f} | {row['memory'] / count:.0f} |", flush=True)
    title = (f"durer: time and memory against the number of spheres ({args.size}, "
             f"{args.threads} thread{'s' if args.threads != 1 else ''})")
    Path(args.svg).write_text(svg_chart(rows, title))
    print(f"wrote {args.svg}")


if __name__ == "__main__":
    main()
