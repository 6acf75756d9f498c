#!/usr/bin/env python3
"""Measure POV-Ray 3.7's `pavement` pattern: the pavings' layouts and known answers.

`tables`: for every square, triangle and hexagon paving (number_of_tiles 1-6, hexagons
1-5, every pattern) finds which lattice edges are tile borders (a border edge's midpoint
has the value 1), finds the smallest block of lattice cells the paving repeats over and
prints the SQUARE_PAVINGS, TRIANGLE_PAVINGS and HEXAGON_PAVINGS tables of
src/texture/pattern/pavement.rs. Squares: per cell, bit 0 its bottom edge, bit 1 its left edge.
Triangles: the lattice points are P(i, j) = (i + j/2, j √3/2); per point, bit 0 the edge
to P(i+1, j), bit 1 the edge to P(i, j+1), bit 2 the edge from P(i+1, j) to P(i, j+1).
Hexagons use the triangle lattice (each hexagon is the six triangles around a point).

`answers`: evaluates every paving at seeded random points under random form / exterior /
interior settings and writes src/texture/pattern/pavement_answers.txt, one line per point:
`sides tiles pattern form exterior interior x z value`; the unit tests in pavement.rs
compare against it.

Values come from `pigment { pavement .. color_map { [0 rgb 0] [1 rgb 1] } }` read through a
pigment function (.red, single precision), one povray run per paving (+W1 +H1, #debug).

usage: scripts/probe-pavement.py tables | answers [--output PATH]
"""
import argparse
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUTPUT = os.path.join(HERE, "..", "src", "texture", "pattern", "pavement_answers.txt")

# Patterns per number of tiles (manual, "Pavement Pattern"), by number of sides.
PATTERN_COUNTS = {
    3: [1, 1, 1, 3, 4, 12],
    4: [1, 1, 2, 5, 12, 35],
    6: [1, 1, 3, 7, 22],
}
# The polygons durer computes; the others are left out of the answers.
MEASURED_SIDES = [3, 4, 6]
# Height of a row of triangles.
ROW_HEIGHT = 3 ** 0.5 / 2
# Edges sampled per axis when looking for a square paving's period.
WINDOW = 36
HEXAGON_WINDOW = 80


def evaluate(spec, points):
    """The pavement's values at the (x, y, z) points, from one povray run."""
    lines = [
        "#version 3.7;\n",
        "#declare F_ = function { pigment { %s color_map { [0 rgb 0] [1 rgb 1] } } }\n"
        % spec,
    ]
    for point in points:
        lines.append('#debug concat("PROBE ", str(F_(%r, %r, %r).red, 0, 9), "\\n")\n' % point)
    handle, path = tempfile.mkstemp(suffix=".pov")
    try:
        with os.fdopen(handle, "w") as scene:
            scene.write("".join(lines))
        result = subprocess.run(
            ["povray", "-D", "+I" + path, "+W1", "+H1", "-F", "-O/dev/null"],
            capture_output=True,
            text=True,
            check=False,
        )
    finally:
        os.unlink(path)
    values = [
        float(line.split()[1])
        for line in result.stderr.splitlines()
        if line.startswith("PROBE ")
    ]
    if len(values) != len(points):
        sys.exit("povray failed on %s:\n%s" % (spec, result.stderr[-2000:]))
    return values


def spec_of(sides, tiles, pattern, form=0, exterior=0, interior=0):
    return (
        "pavement number_of_sides %d number_of_tiles %d pattern %d form %d exterior %d "
        "interior %d" % (sides, tiles, pattern, form, exterior, interior)
    )


def square_borders(tiles, pattern):
    """{(kind, x, z): is a border} for the unit edges of a WINDOW x WINDOW square of cells;
    kind 'h' is the edge from (x, z) to (x + 1, z), 'v' the edge from (x, z) to (x, z + 1)."""
    keys, points = [], []
    for z in range(WINDOW):
        for x in range(WINDOW):
            keys.append(("h", x, z))
            points.append((x + 0.5, 0.0, float(z)))
            keys.append(("v", x, z))
            points.append((float(x), 0.0, z + 0.5))
    values = evaluate(spec_of(4, tiles, pattern), points)
    return {key: value > 0.999 for key, value in zip(keys, values)}


def triangle_borders(tiles, pattern, sides=3, window=WINDOW):
    """{(kind, i, j): is a border} for the lattice edges of a WINDOW x WINDOW block of
    lattice points; kind 'h' is the edge P(i, j)-P(i+1, j), 'r' P(i, j)-P(i, j+1) and 'l'
    P(i+1, j)-P(i, j+1). Hexagons (`sides` 6) are measured on the same lattice: each
    hexagon is the six triangles around one lattice point."""
    keys, points = [], []
    for j in range(window):
        for i in range(window):
            x, z = i + 0.5 * j, j * ROW_HEIGHT
            for kind, dx, dz in (
                ("h", 0.5, 0.0),
                ("r", 0.25, ROW_HEIGHT / 2),
                ("l", 0.75, ROW_HEIGHT / 2),
            ):
                keys.append((kind, i, j))
                points.append((x + dx, 0.0, z + dz))
    values = evaluate(spec_of(sides, tiles, pattern), points)
    return {key: value > 0.999 for key, value in zip(keys, values)}


def hexagon_borders(tiles, pattern):
    """Hexagon pavings repeat over larger blocks: a wider window."""
    return triangle_borders(tiles, pattern, sides=6, window=HEXAGON_WINDOW)


def period(borders, along_x):
    """The smallest shift along the first (or second) index that maps the sampled borders
    onto themselves."""
    window = max(key[1] for key in borders) + 1
    for shift in range(1, window // 2 + 1):
        if all(
            borders[(kind, x + shift, z) if along_x else (kind, x, z + shift)] == border
            for (kind, x, z), border in borders.items()
            if (x + shift if along_x else z + shift) < window
        ):
            return shift
    sys.exit("no period found within %d cells" % window)


def print_table(name, noun, sides, measure, bits):
    """Prints one Rust table of pavings: per paving its repeating block, one string per
    row, one digit per cell holding the border bits of the cell's edges named in `bits`."""
    print("const %s: [&[&[&str]]; %d] = [" % (name, len(PATTERN_COUNTS[sides])))
    for tiles, count in enumerate(PATTERN_COUNTS[sides], start=1):
        print("    // %d %s%s" % (tiles, noun, "" if tiles == 1 else "s"))
        print("    &[")
        for pattern in range(1, count + 1):
            borders = measure(tiles, pattern)
            width, height = period(borders, True), period(borders, False)
            rows = [
                "".join(
                    str(sum(int(borders[(kind, x, z)]) << bit for bit, kind in enumerate(bits)))
                    for x in range(width)
                )
                for z in range(height)
            ]
            print("        &[%s]," % ", ".join('"%s"' % row for row in rows))
        print("    ],")
    print("];")


def print_tables():
    print_table("SQUARE_PAVINGS", "square", 4, square_borders, "hv")
    print_table("TRIANGLE_PAVINGS", "triangle", 3, triangle_borders, "hrl")
    print_table("HEXAGON_PAVINGS", "hexagon", 6, hexagon_borders, "hrl")


def write_answers(output):
    rng = random.Random(1963)
    rows = []
    for sides in MEASURED_SIDES:
        forms = 4 if sides == 4 else 3
        for tiles, count in enumerate(PATTERN_COUNTS[sides], start=1):
            for pattern in range(1, count + 1):
                for _ in range(3):
                    settings = (rng.randrange(forms), rng.randrange(3), rng.randrange(3))
                    points = [
                        (round(rng.uniform(-12, 12), 6), 0.0, round(rng.uniform(-12, 12), 6))
                        for _ in range(8)
                    ]
                    values = evaluate(spec_of(sides, tiles, pattern, *settings), points)
                    for (x, _, z), value in zip(points, values):
                        rows.append(
                            "%d %d %d %d %d %d %r %r %.9g\n"
                            % ((sides, tiles, pattern) + settings + (x, z, value))
                        )
    with open(output, "w") as table:
        table.write(
            "# sides tiles pattern form exterior interior x z value: POV-Ray 3.7 pavement\n"
        )
        table.write("# written by scripts/probe-pavement.py answers\n")
        table.writelines(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["tables", "answers"])
    parser.add_argument("--output", default=DEFAULT_OUTPUT)
    args = parser.parse_args()
    if args.mode == "tables":
        print_tables()
    else:
        write_answers(args.output)


if __name__ == "__main__":
    main()
