#!/usr/bin/env python3
"""Times durer against POV-Ray on the same scenes and settings, in one run.

For each scene: render with durer and with povray at the same size and thread count,
several times, and print the best wall time and peak memory of each and their ratios
(durer / povray; below 1 means durer is faster or smaller).

    scripts/bench.py [--width 640] [--height 480] [--threads 2] [--runs 3] [SCENE ...]

Default scenes: examples/*.pov. durer is target/release/durer (build it first with
`cargo build --release`). POV-Ray is run with +WT<threads>, no anti-aliasing, and its
include folder on the library path.
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
POVRAY_INCLUDE = "/usr/share/povray-3.7/include"


def run(command, cwd):
    """Runs a command; returns (seconds, peak resident KiB, exit code)."""
    start = time.perf_counter()
    process = subprocess.Popen(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.perf_counter() - start
    process.stderr.close()
    return seconds, usage.ru_maxrss, os.waitstatus_to_exitcode(status)


def best_of(command, cwd, runs):
    results = [run(command, cwd) for _ in range(runs)]
    failed = [r for r in results if r[2] != 0]
    if failed:
        return None
    return min(r[0] for r in results), max(r[1] for r in results)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--durer", default=str(ROOT / "target" / "release" / "durer"))
    args = parser.parse_args()
    scenes = [Path(s).resolve() for s in args.scenes] or sorted((ROOT / "examples").glob("*.pov"))
    if not Path(args.durer).exists():
        sys.exit(f"{args.durer} not found: run `cargo build --release` first")
    print(f"{args.width}x{args.height}, {args.threads} threads, best of {args.runs}")
    print(f"{'scene':<28} {'durer s':>9} {'povray s':>9} {'time ratio':>10} {'durer MiB':>10} {'povray MiB':>10} {'mem ratio':>9}")
    with tempfile.TemporaryDirectory() as scratch:
        for scene in scenes:
            out = Path(scratch) / (scene.stem + ".png")
            durer = [args.durer, "render", str(scene), "-o", str(out), "--width", str(args.width),
                     "--height", str(args.height), "--threads", str(args.threads), "--quiet",
                     "-L", POVRAY_INCLUDE]
            povray = ["povray", "-D", "-GA", f"+I{scene}", f"+O{out}", f"+W{args.width}",
                      f"+H{args.height}", f"+WT{args.threads}", f"+L{POVRAY_INCLUDE}", f"+L{scene.parent}"]
            d = best_of(durer, scene.parent, args.runs)
            p = best_of(povray, scene.parent, args.runs)
            if d is None or p is None:
                print(f"{scene.name:<28} {'failed' if d is None else 'ok':>9} {'failed' if p is None else 'ok':>9}")
                continue
            print(f"{scene.name:<28} {d[0]:>9.3f} {p[0]:>9.3f} {d[0] / p[0]:>10.2f} "
                  f"{d[1] / 1024:>10.1f} {p[1] / 1024:>10.1f} {d[1] / p[1]:>9.2f}")


if __name__ == "__main__":
    main()
