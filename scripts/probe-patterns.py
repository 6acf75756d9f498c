#!/usr/bin/env python3
"""Measure POV-Ray 3.7's noise-based pattern values and write durer's known-answer table.

For every pattern in PATTERNS, evaluates `function { pattern { SPEC } }` at seeded random
points in one povray run (+W1 +H1, values printed with #debug) and writes
src/texture/pattern/known_answers.txt, one line per point: `NAME x y z value`. The unit tests in
src/texture/pattern/noise_based.rs build the same patterns and compare.

usage: scripts/probe-patterns.py [--count N] [--output PATH] [--only NAME]
"""
import argparse
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUTPUT = os.path.join(HERE, "..", "src", "texture", "pattern", "known_answers.txt")

# Name (as the Rust tests know it) and the pattern block povray evaluates.
PATTERNS = [
    ("bozo", "bozo"),
    ("dents", "dents"),
    ("granite", "granite"),
    ("wrinkles", "wrinkles"),
    ("agate", "agate"),
    ("agate_turb", "agate agate_turb 0.4"),
    ("waves", "waves"),
    ("ripples", "ripples"),
    ("cells", "cells"),
    ("crackle", "crackle"),
    ("crackle_form_metric", "crackle form <1, 0, 0> metric 1"),
    ("crackle_metric3", "crackle form <-1, 1, 0.5> metric 3"),
    ("crackle_solid", "crackle solid offset 0.1"),
    ("crackle_offset", "crackle offset 0.3"),
    ("marble_turbulence", "marble turbulence 0.8"),
    ("wood_turbulence", "wood turbulence 0.1"),
    ("gradient_turbulence", "gradient x turbulence 0.5"),
    ("gradient_turbulence_shape", "gradient x turbulence <0.8, 0.1, 0> octaves 3 omega 0.7 lambda 3"),
    ("spiral1_turbulence", "spiral1 2 turbulence 0.3"),
    ("crackle_solid_generator1", "crackle solid noise_generator 1"),
    ("ripples_frequency_phase", "ripples frequency 3 phase 0.25"),
    ("waves_frequency_phase", "waves frequency 0.5 phase 0.7"),
]


def evaluate(spec, points):
    """The pattern's values at the points, from one povray run."""
    lines = ["#version 3.7;\n", "#declare F_ = function { pattern { %s } }\n" % spec]
    for point in points:
        lines.append(
            '#debug concat("PROBE ", str(F_(%r, %r, %r), 0, 17), "\\n")\n' % point
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
        float(line.split()[1])
        for line in result.stderr.splitlines()
        if line.startswith("PROBE ")
    ]
    if len(values) != len(points):
        sys.exit("povray failed on %s:\n%s" % (spec, result.stderr[-2000:]))
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=40)
    parser.add_argument("--output", default=DEFAULT_OUTPUT)
    parser.add_argument("--only")
    args = parser.parse_args()
    rng = random.Random(1937)
    rows = []
    for name, spec in PATTERNS:
        points = [
            tuple(round(rng.uniform(-4.0, 4.0), 6) for _ in range(3)) for _ in range(args.count)
        ]
        if args.only and name != args.only:
            continue
        for point, value in zip(points, evaluate(spec, points)):
            rows.append("%s %r %r %r %.17g\n" % ((name,) + point + (value,)))
    with open(args.output, "w") as table:
        table.write("# name x y z value: POV-Ray 3.7 function { pattern { .. } } values\n")
        table.write("# written by scripts/probe-patterns.py\n")
        table.writelines(rows)


if __name__ == "__main__":
    main()
