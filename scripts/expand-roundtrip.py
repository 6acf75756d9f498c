#!/usr/bin/env python3
"""Round-trip every corpus scene through `durer expand` and compare the renders.

usage: scripts/expand-roundtrip.py [--set corpus|examples] [--corpus FILE] [--durer PATH]
                                   [--jobs N] [--timeout S] [--filter SUBSTR]
                                   [--report FILE]

For each scene that POV-Ray renders (the sets and folders of scripts/conformance.py), in a
fresh copy of its folder:

    durer expand scene.pov -o flat.pov -L <include>       the flat SDL
    povray  scene.pov  vs  povray  flat.pov                must match (conformance metric)
    durer render scene.pov  vs  durer render flat.pov      must be byte-identical PNGs

and the flat file must hold no directive but `#version` and `#declare`. POV-Ray's renders
of the originals come from conformance.py's cache. Prints one line per scene that is not a
full pass and a summary; --report writes the table as Markdown. Standard library only.
"""

import argparse
import concurrent.futures
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import conformance as c  # noqa: E402
import imagediff  # noqa: E402

DIRECTIVE = re.compile(r"^\s*#\s*([a-z_]+)", re.MULTILINE)


def round_trip(entry, durer, timeout):
    """Returns (verdict, povray verdict, durer identical, size, note)."""
    if not entry.renders:
        return "skip", "", "", 0, "list: does not render in POV-Ray"
    reference, _, note = c.povray_render(entry, timeout)
    if reference is None:
        return "skip", "", "", 0, note
    folder = c.fresh_copy(entry, "expand")
    try:
        scene = os.path.basename(entry.source)
        code, stderr, _ = c.run_command(
            [durer, "expand", scene, "-o", "flat.pov", "-L", c.INCLUDE, "--quiet",
             "--width", str(c.WIDTH), "--height", str(c.HEIGHT)], folder, timeout)
        if code != 0:
            return "error", "", "", 0, "expand " + c.describe_failure(code, stderr, timeout)
        flat = os.path.join(folder, "flat.pov")
        with open(flat, encoding="utf-8", errors="replace") as handle:
            text = handle.read()
        size = len(text.encode())
        directives = sorted(set(DIRECTIVE.findall(text)) - {"version", "declare"})
        notes = [f"directives left: {', '.join(directives)}"] if directives else []
        code, stderr, _ = c.run_command(
            c.povray_command("flat.pov", "povray-flat.png", folder), folder, timeout)
        flat_png = os.path.join(folder, "povray-flat.png")
        if code != 0 or not os.path.exists(flat_png):
            verbose = [a for a in c.povray_command("flat.pov", "povray-flat.png", folder)
                       if a != "-GA"]
            _, stderr, _ = c.run_command(verbose, folder, timeout)
            pov = "error"
            notes.append("povray flat " + c.describe_failure(code, stderr, timeout, True))
        else:
            comparison = imagediff.compare(imagediff.read_png(reference),
                                           imagediff.read_png(flat_png))
            pov = comparison.verdict()
            if pov != "match":
                notes.append(f"povray {pov}: {comparison.fraction_over * 100:.1f}% pixels")
        images = []
        for name in (scene, "flat.pov"):
            out = os.path.join(folder, f"durer-{len(images)}.png")
            code, stderr, _ = c.run_command(
                [durer, "render", name, "-o", out, "--width", str(c.WIDTH), "--height",
                 str(c.HEIGHT), "-L", c.INCLUDE, "--quiet"], folder, timeout)
            if code != 0 or not os.path.exists(out):
                notes.append(f"durer {name}: " + c.describe_failure(code, stderr, timeout))
                images.append(None)
            else:
                with open(out, "rb") as handle:
                    images.append(handle.read())
        if images[0] is None or images[1] is None:
            same = "error"
        else:
            same = "identical" if images[0] == images[1] else "different"
            if same == "different":
                diff = imagediff.compare(imagediff.read_png(os.path.join(folder, "durer-0.png")),
                                         imagediff.read_png(os.path.join(folder, "durer-1.png")))
                notes.append(f"durer bytes differ ({diff.verdict()}, max {diff.max_diff:.0f})")
        ok = pov == "match" and same == "identical" and not directives
        return ("pass" if ok else "fail"), pov, same, size, "; ".join(notes)
    finally:
        shutil.rmtree(os.path.join(c.WORK, "run", entry.slug, "expand"), ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--set", default="corpus", choices=["corpus", "examples"])
    parser.add_argument("--corpus", default=os.path.join(c.REPO, "..", "shared", "corpus.txt"))
    parser.add_argument("--durer", default=None)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--filter", default="")
    parser.add_argument("--report", default="")
    args = parser.parse_args()
    durer = args.durer or c.default_durer()
    entries = (c.read_corpus(args.corpus) if args.set == "corpus"
               else c.read_all_examples(args.corpus))
    entries = [e for e in entries if args.filter in e.path]
    os.makedirs(c.CACHE, exist_ok=True)
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(round_trip, e, durer, args.timeout): e for e in entries}
        for future in concurrent.futures.as_completed(futures):
            entry = futures[future]
            try:
                row = future.result()
            except Exception as error:  # a script bug must not lose the other scenes
                row = ("error", "", "", 0, f"script error: {error}")
            rows.append((entry, row))
            if row[0] not in ("pass", "skip"):
                print(f"{row[0]:5} {entry.path}: {row[4]}", flush=True)
    rows.sort(key=lambda r: r[0].order)
    tally = {}
    for _, row in rows:
        tally[row[0]] = tally.get(row[0], 0) + 1
    povray_match = sum(1 for _, r in rows if r[1] == "match")
    identical = sum(1 for _, r in rows if r[2] == "identical")
    tried = sum(1 for _, r in rows if r[0] != "skip")
    print(f"{tried} scenes round-tripped: {tally.get('pass', 0)} pass, "
          f"{tally.get('fail', 0)} fail, {tally.get('error', 0)} error "
          f"({tally.get('skip', 0)} skipped); povray match {povray_match}, "
          f"durer byte-identical {identical}")
    if args.report:
        with open(args.report, "w", encoding="utf-8") as handle:
            handle.write("| scene | result | povray flat vs original | durer flat vs original "
                         "| flat bytes | note |\n|---|---|---|---|---|---|\n")
            for entry, (verdict, pov, same, size, note) in rows:
                handle.write(f"| {entry.path} | {verdict} | {pov} | {same} | {size} | "
                             f"{c.markdown_cell(note)} |\n")
    return 0 if tally.get("fail", 0) + tally.get("error", 0) == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
