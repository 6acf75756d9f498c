#!/usr/bin/env python3
"""Print the durer image metric for two PNG files.

usage: scripts/compare.py A.png B.png [--tolerance F]

Prints the fraction of pixels differing by more than 24/255 in any channel, the
mean absolute 4x4-block difference and the largest channel difference, then the
verdict: match (fraction <= tolerance, default 0.02), close (block diff <= 6/255)
or differ. Exit status: 0 match, 1 close or differ, 2 unreadable input.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import imagediff  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description="Compare two PNG images with durer's metric.")
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument(
        "--tolerance",
        type=float,
        default=imagediff.MATCH_FRACTION,
        help="fraction of pixels allowed over 24/255 for a match (default 0.02)",
    )
    args = parser.parse_args()
    try:
        a = imagediff.read_png(args.a)
        b = imagediff.read_png(args.b)
        result = imagediff.compare(a, b)
    except (OSError, imagediff.PngError, ValueError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print(f"size:            {a.width}x{a.height}")
    print(f"pixels over {imagediff.PIXEL_THRESHOLD:g}:  {100 * result.fraction_over:.3f}%")
    print(f"block diff:      {result.block_diff:.3f}/255")
    print(f"max diff:        {result.max_diff:.0f}/255")
    verdict = result.verdict(args.tolerance)
    print(f"verdict:         {verdict}")
    return 0 if verdict == "match" else 1


if __name__ == "__main__":
    sys.exit(main())
