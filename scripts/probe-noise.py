#!/usr/bin/env python3
"""Measure POV-Ray 3.7's noise and turbulence and write durer's known-answer table.

Writes probe scenes whose #debug lines print noise values at seeded random points, runs
povray on them (+W1 +H1, no output file), parses stderr and writes
src/noise/known_answers.txt, the table the unit tests in src/noise/ compare against.

usage: scripts/probe-noise.py [--count N] [--output PATH]

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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=60, help="probes per kind and generator")
    parser.add_argument("--output", default=DEFAULT_OUTPUT)
    arguments = parser.parse_args()
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
