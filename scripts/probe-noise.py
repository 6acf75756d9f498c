#!/usr/bin/env python3
"""Measure POV-Ray 3.7's noise and turbulence and write durer's known-answer table.

Writes probe scenes whose #debug lines print noise values at seeded random points, runs
povray on them (+W1 +H1, no output file), parses stderr and writes
src/noise/known_answers.txt, the table the unit tests in src/noise/ compare against.

usage: scripts/probe-noise.py [--count N] [--output PATH]
       scripts/probe-noise.py --perlin-tables   (needs numpy; rewrites src/noise/perlin_tables.rs)

What each kind measures (one line per probe: kind generator octaves omega lambda x y z values):
  noise              f_noise_generator(x, y, z, generator)                      (functions.inc)
  vector_noise       vturbulence(2, 0.5, 1, <x, y, z>)         (one octave = the vector noise)
  turbulence         scalar turbulence, read through marble: marble's value at a point whose
                     x lies in the rising half of its ramp is 2·(x + k·turbulence), so
                     turbulence = (marble with turbulence k − marble without) / (2k)
  vector_turbulence  vturbulence(lambda, omega, octaves, <x, y, z>)
"""
import argparse
import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUTPUT = os.path.join(HERE, "..", "src", "noise", "known_answers.txt")
PERLIN_TABLES = os.path.join(HERE, "..", "src", "noise", "perlin_tables.rs")
# Turbulence amount for the marble read-out: small enough to stay on one side of the ramp.
MARBLE_TURBULENCE = 1e-4


def evaluate(expressions, declarations=""):
    """Evaluate SDL expressions (each a float or a vector) in one povray run."""
    lines = ["#version 3.7;\n", '#include "functions.inc"\n', declarations]
    for expression in expressions:
        lines.append(
            '#declare P_ = %s;\n#debug concat("PROBE ", vstr(3, P_ + <0,0,0>, " ", 0, 17), "\\n")\n'
            % expression
        )
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
        [float(v) for v in line.split()[1:]]
        for line in result.stderr.splitlines()
        if line.startswith("PROBE ")
    ]
    if len(values) != len(expressions):
        sys.exit("povray failed:\n" + result.stderr[-2000:])
    return values


def vector(point):
    return "<%r, %r, %r>" % point


def random_point(rng, spread):
    return tuple(rng.uniform(-spread, spread) for _ in range(3))


def random_shape(rng):
    return (rng.randint(1, 10), rng.choice([0.5, 0.3, 0.7, 0.65]), rng.choice([2.0, 2.5, 1.7, 3.0]))


# Generator 3 ---------------------------------------------------------------------------
# Generator 3 is gradient noise: 0.4925 + 0.795 * sum over the 8 corners of
# w(corner) * gradient(corner) . (point - corner), w the trilinear weights of the cubic ease
# curve, on a lattice shifted by PERLIN_SHIFT (where povray's values stop being one
# polynomial), with unit gradients that repeat every 2048 cells on each axis. The gradient of
# corner (x, y, z) is GRADIENTS[(Y_STAGE[(X_STAGE[x] + y) % 2048] + z) % 2048]: walking along z
# steps through GRADIENTS in order, walking along y steps through Y_STAGE, along x through
# X_STAGE. The tables below are read off gradients measured at lattice points on four lines.
PERLIN_PERIOD = 2048
PERLIN_SCALE, PERLIN_OFFSET = 0.795, 0.4925
PERLIN_SHIFT_GUESS = 0.0231572
# Offsets along one axis from a lattice point: noise along a lattice line is a quartic there.
STEPS = [0.0, 0.1, 0.25, 0.4, 0.55, 0.7, 0.85]


def lattice_gradients(np, line_axis, other, shift):
    """Gradients at the lattice points n = 0..2047 along `line_axis` (others fixed at `other`)."""
    expressions = []
    for n in range(PERLIN_PERIOD):
        corner = list(other)
        corner[line_axis] = n
        for axis in range(3):
            for step in STEPS:
                point = [c - shift for c in corner]
                point[axis] += step
                expressions.append("f_noise_generator(%r, %r, %r, 3)" % tuple(point))
    values = np.array([v[0] for v in evaluate(expressions)]).reshape(PERLIN_PERIOD, 3, len(STEPS))
    unit_noise = (values - PERLIN_OFFSET) / PERLIN_SCALE
    # Along a lattice line only two corners count; the linear coefficient is this corner's
    # gradient component.
    coefficients = np.linalg.lstsq(
        np.vander(np.array(STEPS), 5), unit_noise.reshape(-1, len(STEPS)).T, rcond=None
    )[0]
    return coefficients[3].reshape(PERLIN_PERIOD, 3)


def perlin_model(np, tables, points, shift):
    gradients, y_stage, x_stage = tables
    shifted = points + shift
    cells = np.floor(shifted).astype(np.int64)
    fractions = shifted - cells
    eased = fractions * fractions * (3 - 2 * fractions)
    total = np.zeros(len(points))
    for corner in range(8):
        offset = np.array([corner & 1, (corner >> 1) & 1, (corner >> 2) & 1])
        weight = np.prod(np.where(offset == 1, eased, 1 - eased), axis=1)
        c = cells + offset
        index = (y_stage[(x_stage[c[:, 0] % PERLIN_PERIOD] + c[:, 1]) % PERLIN_PERIOD] + c[:, 2]) % PERLIN_PERIOD
        total += weight * np.sum((fractions - offset) * gradients[index], axis=1)
    return np.clip(PERLIN_OFFSET + PERLIN_SCALE * total, 0.0, 1.0)


def perlin_tables_at(np, shift):
    """Generator 3's tables from gradients measured at lattice points assumed at `shift`."""
    gradients = lattice_gradients(np, 2, (0, 0, 0), shift)
    along_y = lattice_gradients(np, 1, (0, 0, 0), shift)
    along_x = lattice_gradients(np, 0, (0, 0, 0), shift)
    along_x_next_row = lattice_gradients(np, 0, (0, 1, 0), shift)

    def positions(measured):
        distance = np.abs(measured[:, None, :] - gradients[None, :, :]).max(axis=2)
        if distance.min(axis=1).max() > 1e-6:
            sys.exit("a measured gradient matches none along z")
        return distance.argmin(axis=1)

    y_stage = positions(along_y)
    x_positions, next_row_positions = positions(along_x), positions(along_x_next_row)
    x_stage = np.zeros(PERLIN_PERIOD, dtype=np.int64)
    for x in range(PERLIN_PERIOD):
        # The row whose first gradient (and next row's) match this column's.
        rows = [
            k for k in np.nonzero(y_stage == x_positions[x])[0]
            if y_stage[(k + 1) % PERLIN_PERIOD] == next_row_positions[x]
        ]
        if len(rows) != 1:
            sys.exit("column %d is ambiguous" % x)
        x_stage[x] = rows[0]
    return gradients, y_stage, x_stage


def refined_shift(np, tables, shift, points, measured):
    """The lattice shift near `shift` that fits the probes best (ternary search, worst error)."""
    worst = lambda s: np.abs(perlin_model(np, tables, points, s) - measured).max()
    low, high = shift - 1e-6, shift + 1e-6
    for _ in range(60):
        a, b = low + (high - low) / 3, high - (high - low) / 3
        low, high = (low, b) if worst(a) < worst(b) else (a, high)
    shift = (low + high) / 2
    return shift, worst(shift)


def measure_perlin_tables():
    import numpy as np

    rng = random.Random(7)
    probes = [random_point(rng, 20.0) for _ in range(1500)]
    points = np.array(probes)
    measured = np.array([v[0] for v in evaluate(["f_noise_generator(%r, %r, %r, 3)" % p for p in probes])])
    # Gradients read at slightly wrong lattice points are slightly wrong: alternate measuring
    # the tables and refining the shift until both settle.
    shift = PERLIN_SHIFT_GUESS
    for _ in range(3):
        tables = perlin_tables_at(np, shift)
        shift, worst = refined_shift(np, tables, shift, points, measured)
        print("lattice shift %.12f, worst error on %d probes %.2e" % (shift, len(points), worst))
    gradients, y_stage, x_stage = tables

    with open(PERLIN_TABLES, "w") as out:
        out.write("//! Generator 3's tables, measured from POV-Ray 3.7 by `scripts/probe-noise.py\n")
        out.write("//! --perlin-tables` (do not edit by hand); see `perlin.rs` for how they are used.\n\n")
        out.write("/// Where generator 3's lattice cells start: cell boundaries lie at integers minus this.\n")
        out.write("pub(super) const LATTICE_SHIFT: f64 = %.12f;\n\n" % shift)
        out.write("/// The unit gradients, in the order they follow one another along z.\n")
        out.write("#[rustfmt::skip]\npub(super) static GRADIENTS: [[f64; 3]; %d] = [\n" % PERLIN_PERIOD)
        for g in gradients:
            out.write("    [%.9f, %.9f, %.9f],\n" % tuple(g))
        out.write("];\n\n")
        for name, table, doc in (
            ("Y_STAGE", y_stage, "Position in `GRADIENTS` of each row (y) of the z = 0 plane's column 0."),
            ("X_STAGE", x_stage, "Row in `Y_STAGE` where each column (x) starts."),
        ):
            out.write("/// %s\n#[rustfmt::skip]\npub(super) static %s: [u16; %d] = [\n" % (doc, name, PERLIN_PERIOD))
            for i in range(0, PERLIN_PERIOD, 16):
                out.write("    " + ", ".join(str(int(v)) for v in table[i:i + 16]) + ",\n")
            out.write("];\n\n")
    print("wrote " + os.path.normpath(PERLIN_TABLES))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=60, help="probes per kind and generator")
    parser.add_argument("--output", default=DEFAULT_OUTPUT)
    parser.add_argument("--perlin-tables", action="store_true", help="measure generator 3's tables")
    arguments = parser.parse_args()
    if arguments.perlin_tables:
        measure_perlin_tables()
        return
    rng = random.Random(20260101)
    rows = []

    # Scalar noise for every generator, including lattice points and far-away points.
    for generator in (1, 2, 3):
        points = [random_point(rng, 40.0) for _ in range(arguments.count)]
        points += [(3.0, -2.0, 7.0), (-10000.5, 0.25, 1.5), (123456.75, -0.5, 2.25)]
        values = evaluate(["f_noise_generator(%r, %r, %r, %d)" % (*p, generator) for p in points])
        rows += [("noise", generator, 0, 0, 0, p, v[:1]) for p, v in zip(points, values)]

    # Vector noise (independent of the generator).
    points = [random_point(rng, 40.0) for _ in range(arguments.count)]
    values = evaluate(["vturbulence(2, 0.5, 1, %s)" % vector(p) for p in points])
    rows += [("vector_noise", 2, 0, 0, 0, p, v) for p, v in zip(points, values)]

    # Scalar turbulence through marble, with x in the rising half of marble's ramp.
    for generator in (1, 2, 3):
        probes = []
        for _ in range(arguments.count):
            x, y, z = random_point(rng, 20.0)
            x = math.floor(x) + rng.uniform(0.05, 0.45)
            probes.append(((x, y, z), random_shape(rng)))
        declarations = "".join(
            "#declare T%d_ = function { pattern { marble turbulence %r octaves %d omega %r "
            "lambda %r noise_generator %d } }\n" % (i, MARBLE_TURBULENCE, *shape, generator)
            for i, (_, shape) in enumerate(probes)
        )
        declarations += "#declare M_ = function { pattern { marble } }\n"
        values = evaluate(
            ["(T%d_(%r, %r, %r) - M_(%r, %r, %r))" % (i, *p, *p) for i, (p, _) in enumerate(probes)],
            declarations,
        )
        for (point, shape), value in zip(probes, values):
            turbulence = value[0] / (2.0 * MARBLE_TURBULENCE)
            rows.append(("turbulence", generator, *shape, point, [turbulence]))

    # Vector turbulence through vturbulence.
    probes = [(random_point(rng, 20.0), random_shape(rng)) for _ in range(arguments.count)]
    values = evaluate(
        ["vturbulence(%r, %r, %d, %s)" % (lam, omega, octaves, vector(p)) for p, (octaves, omega, lam) in probes]
    )
    rows += [("vector_turbulence", 2, *s, p, v) for (p, s), v in zip(probes, values)]

    with open(arguments.output, "w") as table:
        table.write("# Measured with scripts/probe-noise.py from POV-Ray 3.7; do not edit by hand.\n")
        table.write("# kind generator octaves omega lambda x y z value(s)\n")
        for kind, generator, octaves, omega, lam, point, value in rows:
            numbers = " ".join(repr(float(v)) for v in (*point, *value))
            table.write("%s %d %d %r %r %s\n" % (kind, generator, octaves, omega, lam, numbers))
    print("wrote %d probes to %s" % (len(rows), os.path.normpath(arguments.output)))


if __name__ == "__main__":
    main()
