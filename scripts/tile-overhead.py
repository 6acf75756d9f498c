#!/usr/bin/env python3
"""CPU time of a render split into N tiles (`--tile I/N`, each a process) against the
same render whole, for several option sets; checks that the merge equals the whole.

Usage: scripts/tile-overhead.py [--durer target/release/durer] [--tiles 16]
       [--size 640x480] [SCENE]
Prints one line per option set: whole CPU s, summed tile CPU s, ratio, merge equal.
"""
import argparse, os, resource, subprocess, sys, tempfile

def cpu_of(argv):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(argv, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)

def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--durer", default="target/release/durer")
    parser.add_argument("--tiles", type=int, default=16)
    parser.add_argument("--size", default="640x480")
    parser.add_argument("scene", nargs="?", default="examples/showcase.pov")
    args = parser.parse_args()
    width, height = args.size.split("x")
    size = ["--width", width, "--height", height, "-q", "--threads", "1"]
    option_sets = [["-A"], ["+A0.3", "+AM2"], ["+A0.3", "+AM1"]]
    with tempfile.TemporaryDirectory() as folder:
        print(f"{args.scene} {args.size}, {args.tiles} tiles, 1 thread per process")
        print(f"{'options':16} {'whole s':>8} {'tiles s':>8} {'ratio':>6}  merged == whole")
        for options in option_sets:
            whole = os.path.join(folder, "whole.png")
            whole_cpu = cpu_of([args.durer, "render", args.scene, *size, *options, "-o", whole])
            tiles_cpu = 0.0
            names = []
            for index in range(args.tiles):
                base = os.path.join(folder, f"t{index}")
                tiles_cpu += cpu_of([args.durer, "render", args.scene, *size, *options,
                                     "--tile", f"{index}/{args.tiles}", "-o", base])
                names.append(base + ".tile.png")
            merged = os.path.join(folder, "merged.png")
            tiles_cpu += cpu_of([args.durer, "merge", merged, *names])
            same = open(whole, "rb").read() == open(merged, "rb").read()
            print(f"{' '.join(options):16} {whole_cpu:8.2f} {tiles_cpu:8.2f} "
                  f"{tiles_cpu / whole_cpu:6.2f}  {same}")
            if not same:
                sys.exit(1)

main()
