#!/usr/bin/env python3
"""Render conformance scenes with POV-Ray and durer and compare the images.

usage: scripts/conformance.py [--set corpus|examples|wild|all]... [--corpus FILE]
                              [--durer PATH] [--jobs N] [--timeout S]
                              [--out docs/conformance.md] [--filter SUBSTR]
                              [--wild-list FILE]

Three sets of scenes, chosen with --set (repeatable; default corpus):

    corpus    ../shared/corpus.txt: 299 of POV-Ray's example scenes, one per line
              `path<TAB>tier<TAB>yes|no`, paths relative to /usr/share/doc/povray/examples
              (--corpus FILE reads another list of that form)
    examples  every .pov file under /usr/share/doc/povray/examples (396), tier from the
              corpus list where it has one; POV-Ray itself decides what renders
    wild      tests/wild/list.tsv: scenes people published in their own repositories,
              `repo<TAB>commit<TAB>path<TAB>extra paths<TAB>category<TAB>yes|no<TAB>note`,
              exported by scripts/fetch-wild.py into conformance-work/wild/ (run it first;
              --wild-list FILE reads another list of that form, e.g. candidates to screen)

Lines starting with `#` are comments. Each scene's folder (for wild scenes, the exported
tree of its repository) is copied into conformance-work/ (git-ignored) and rendered there at
160x120 by

    povray -D +Iscene.pov +Oout.png +W160 +H120 -GA +WT1 +L<include> +L<scene folder>
    durer render scene.pov -o out.png --width 160 --height 120 -L <include> --quiet

POV-Ray renders are cached in conformance-work/povray-cache/, keyed by scene path and
modification time, so reruns only pay for durer. Results are classified as

    match   at most 2% of pixels differ by more than 24/255 in a channel
    close   4x4-block means differ by at most 6/255 on average
    differ  neither
    error   durer failed (exit status, timeout, missing or unreadable image, wrong size)
    skip    POV-Ray failed, or the corpus marks the scene as not rendering

and written as a Markdown report (default docs/conformance.md) with one section per set: a
run replaces the sections of the sets it ran and keeps the others. The summary is also
printed. Standard library only.
"""

import argparse
import concurrent.futures
import datetime
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import imagediff  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = os.path.join(REPO, "conformance-work")
CACHE = os.path.join(WORK, "povray-cache")
EXAMPLES = "/usr/share/doc/povray/examples"
WILD_LIST = os.path.join(REPO, "tests", "wild", "list.tsv")
WILD_TREES = os.path.join(WORK, "wild")
SETS = ["corpus", "examples", "wild"]
SET_TITLES = {
    "corpus": "POV-Ray's example corpus (../shared/corpus.txt)",
    "examples": "All of POV-Ray's example scenes",
    "wild": "Real-world scenes (tests/wild/list.tsv)",
}
INCLUDE = "/usr/share/povray-3.7/include"
WIDTH, HEIGHT = 160, 120
CLASSES = ["match", "close", "differ", "error", "skip"]
# Bump when the POV-Ray command changes, so stale cache entries are not reused.
CACHE_VERSION = 1


class Entry:
    """One scene to render: its name in the report, where it lives and what it needs."""

    def __init__(self, path, tier, renders, order, source=None, tree=None, cache_tag=""):
        self.path = path
        self.tier = tier
        self.renders = renders
        self.order = order
        # The scene file, and the folder copied for each render (the scene's own by default).
        self.source = source or (path if os.path.isabs(path) else os.path.join(EXAMPLES, path))
        self.tree = tree or os.path.dirname(self.source)
        # Added to the POV-Ray cache key (a wild scene's commit).
        self.cache_tag = cache_tag

    @property
    def slug(self):
        return re.sub(r"[^A-Za-z0-9_.-]+", "_", self.path.replace(".pov", ""))

    @property
    def scene_folder(self):
        """The scene's folder relative to the copied tree."""
        return os.path.relpath(os.path.dirname(self.source), self.tree)


class Result:
    """The outcome for one scene."""

    def __init__(self, entry, verdict, note="", comparison=None, povray_time=None,
                 durer_time=None):
        self.entry = entry
        self.verdict = verdict
        self.note = note
        self.comparison = comparison
        self.povray_time = povray_time
        self.durer_time = durer_time


def list_lines(path):
    """(line number, fields) of a tab-separated list, without comments and blank lines."""
    with open(path, encoding="utf-8") as handle:
        for number, line in enumerate(handle, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            yield number, (line.split("\t") if "\t" in line else line.split())


def read_corpus(path):
    entries = []
    for number, fields in list_lines(path):
        if len(fields) < 3:
            raise SystemExit(f"{path}:{number}: expected path<TAB>tier<TAB>yes|no")
        renders = fields[2].strip().lower()
        if renders not in ("yes", "no"):
            raise SystemExit(f"{path}:{number}: third column must be yes or no")
        entries.append(Entry(fields[0].strip(), fields[1].strip(), renders == "yes",
                             len(entries)))
    return entries


def read_all_examples(corpus_path):
    """Every .pov file of POV-Ray's examples; POV-Ray decides which render."""
    tiers = {}
    if os.path.exists(corpus_path):
        tiers = {entry.path: entry.tier for entry in read_corpus(corpus_path)}
    paths = []
    for folder, _, files in os.walk(EXAMPLES):
        paths += [os.path.relpath(os.path.join(folder, name), EXAMPLES)
                  for name in files if name.endswith(".pov")]
    return [Entry(path, tiers.get(path, "-"), True, order)
            for order, path in enumerate(sorted(paths))]


def read_wild(path):
    """The real-world list; scenes not yet exported by scripts/fetch-wild.py are errors."""
    entries = []
    for number, fields in list_lines(path):
        if len(fields) < 6:
            raise SystemExit(f"{path}:{number}: expected repo, commit, path, extra paths, "
                             "category, yes|no, note")
        repo, commit, scene, _, category, renders = (field.strip() for field in fields[:6])
        if renders not in ("yes", "no"):
            raise SystemExit(f"{path}:{number}: sixth column must be yes or no")
        tree = os.path.join(WILD_TREES, repo.replace("/", "+"))
        entries.append(Entry(f"{repo}/{scene}", category, renders == "yes", len(entries),
                             source=os.path.join(tree, scene), tree=tree, cache_tag=commit))
    return entries


def run_command(command, cwd, timeout):
    """Run a command in its own process group; returns (exit code or None, stderr, seconds)."""
    start = time.monotonic()
    process = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               start_new_session=True)
    try:
        _, stderr = process.communicate(timeout=timeout)
        code = process.returncode
    except subprocess.TimeoutExpired:
        # The group holds only the process started here and its own children.
        os.killpg(process.pid, signal.SIGKILL)
        _, stderr = process.communicate()
        code = None
    return code, stderr.decode("utf-8", "replace"), time.monotonic() - start


def describe_failure(code, stderr, timeout, pick_error_line=False):
    if code is None:
        return f"timeout after {timeout:g} s"
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    if pick_error_line:
        # POV-Ray prints its banner first; the interesting line mentions an error.
        errors = [line for line in lines if "error" in line.lower()]
        lines = errors or lines[-1:]
    first = lines[0] if lines else ""
    status = f"killed by signal {-code}" if code < 0 else f"exit {code}"
    return f"{status}: {first}" if first else status


def fresh_copy(entry, kind):
    """Copy the scene's tree into the scratch area; returns the copy's scene folder."""
    target = os.path.join(WORK, "run", entry.slug, kind)
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(entry.tree, target, symlinks=True)
    return os.path.normpath(os.path.join(target, entry.scene_folder))


def remove_copy(entry, kind):
    shutil.rmtree(os.path.join(WORK, "run", entry.slug, kind), ignore_errors=True)


def povray_option(switch, value):
    """`+Ivalue`; POV-Ray splits options at spaces, so a value with one is quoted."""
    return f'{switch}"{value}"' if " " in value else f"{switch}{value}"


def povray_command(scene_name, output, folder):
    return ["povray", "-D", povray_option("+I", scene_name), povray_option("+O", output),
            f"+W{WIDTH}", f"+H{HEIGHT}", "-GA", "+WT1", f"+L{INCLUDE}",
            povray_option("+L", folder)]


def povray_render(entry, timeout):
    """Render with POV-Ray, or reuse the cache; returns (png path or None, seconds, note)."""
    mtime = os.stat(entry.source).st_mtime_ns
    key_text = f"{CACHE_VERSION}\0{entry.source}\0{mtime}\0{WIDTH}x{HEIGHT}{entry.cache_tag}"
    key = hashlib.sha1(key_text.encode()).hexdigest()[:12]
    png = os.path.join(CACHE, f"{entry.slug}-{key}.png")
    record_path = os.path.join(CACHE, f"{entry.slug}-{key}.json")
    if os.path.exists(record_path):
        with open(record_path, encoding="utf-8") as handle:
            record = json.load(handle)
        # A render that timed out is retried when a longer timeout is allowed.
        retry = record.get("timed_out") and timeout > record.get("timeout", 0)
        if (record["ok"] and os.path.exists(png)) or (not record["ok"] and not retry):
            return (png if record["ok"] else None), record["seconds"], record["note"]
    folder = fresh_copy(entry, "povray")
    partial = png + ".partial.png"
    code, stderr, seconds = run_command(
        povray_command(os.path.basename(entry.source), partial, folder), folder, timeout)
    ok = code == 0 and os.path.exists(partial)
    note = ""
    if code is not None and code != 0:
        # -GA hides POV-Ray's diagnostics; rerun with messages on to say why it failed.
        verbose = [arg for arg in povray_command(os.path.basename(entry.source), partial, folder)
                   if arg != "-GA"]
        _, stderr, _ = run_command(verbose, folder, timeout)
    if not ok:
        note = "povray " + describe_failure(code, stderr, timeout, pick_error_line=True)
    if code == 0 and not ok:
        note = "povray wrote no image"
    if ok:
        os.replace(partial, png)
    elif os.path.exists(partial):
        os.remove(partial)
    remove_copy(entry, "povray")
    with open(record_path, "w", encoding="utf-8") as handle:
        json.dump({"scene": entry.source, "ok": ok, "seconds": seconds, "note": note,
                   "timed_out": code is None, "timeout": timeout}, handle)
    return (png if ok else None), seconds, note


def durer_render(entry, durer, timeout):
    """Render with durer; returns (png path or None, seconds, note)."""
    folder = fresh_copy(entry, "durer")
    output = os.path.join(WORK, "durer-out", entry.slug + ".png")
    if os.path.exists(output):
        os.remove(output)
    command = [durer, "render", os.path.basename(entry.source), "-o", output,
               "--width", str(WIDTH), "--height", str(HEIGHT), "-L", INCLUDE, "--quiet"]
    code, stderr, seconds = run_command(command, folder, timeout)
    remove_copy(entry, "durer")
    if code != 0:
        return None, seconds, describe_failure(code, stderr, timeout)
    if not os.path.exists(output):
        return None, seconds, "exit 0 but no image written"
    return output, seconds, ""


def run_scene(entry, durer, timeout):
    if not entry.renders:
        return Result(entry, "skip", "list: does not render in POV-Ray")
    if not os.path.exists(entry.source):
        return Result(entry, "skip", "not fetched: run scripts/fetch-wild.py")
    reference, povray_time, note = povray_render(entry, timeout)
    if reference is None:
        return Result(entry, "skip", note, povray_time=povray_time)
    output, durer_time, note = durer_render(entry, durer, timeout)
    result = Result(entry, "error", note, povray_time=povray_time, durer_time=durer_time)
    if output is None:
        return result
    try:
        comparison = imagediff.compare(imagediff.read_png(reference), imagediff.read_png(output))
    except (OSError, imagediff.PngError, ValueError) as error:
        result.note = f"bad image: {error}"
        return result
    result.verdict = comparison.verdict()
    result.comparison = comparison
    result.note = f"max diff {comparison.max_diff:.0f}" if result.verdict != "match" else ""
    return result


def counts(results):
    tally = {name: 0 for name in CLASSES}
    for result in results:
        tally[result.verdict] += 1
    return ", ".join(f"{tally[name]} {name}" for name in CLASSES)


def summary_lines(results, group="tier"):
    lines = [f"{len(results)} scenes: {counts(results)}"]
    for tier in sorted({r.entry.tier for r in results}):
        in_tier = [r for r in results if r.entry.tier == tier]
        lines.append(f"{group} {tier} ({len(in_tier)} scenes): {counts(in_tier)}")
    return lines


def seconds_text(value):
    return "" if value is None else f"{value:.2f}"


def markdown_cell(text, limit=140):
    text = text.replace("|", "\\|").replace("\n", " ")
    return text if len(text) <= limit else text[: limit - 1] + "…"


REPORT_INTRO = [
    "# Conformance against POV-Ray 3.7",
    "",
    "Written by `scripts/conformance.py`, one section per set of scenes (`--set corpus`, "
    "`--set examples`, `--set wild`); a run replaces the sections it ran.",
    "",
    "**match**: at most 2% of pixels differ by more than 24/255 in a channel; "
    "**close**: 4x4-block means differ by at most 6/255 on average; "
    "**error**: durer failed; **skip**: POV-Ray failed, the list says it does not "
    "render, or the scene was not fetched.",
    "",
]


def section_marker(name):
    return f"<!-- conformance set: {name} -->"


def report_section(name, results, args, wall):
    group = "category" if name == "wild" else "tier"
    lines = [
        section_marker(name),
        f"## {SET_TITLES[name]}",
        "",
        f"Generated on {datetime.date.today().isoformat()}: "
        f"{WIDTH}x{HEIGHT}, timeout {args.timeout:g} s, {args.jobs} jobs in parallel "
        f"(times are wall-clock seconds; POV-Ray single-threaded, cached times are from "
        f"the run that filled the cache). Run time {wall:.0f} s"
        + (f", scenes whose path contains `{args.filter}`" if args.filter else "") + ".",
        "",
    ]
    lines += [f"- {line}" for line in summary_lines(results, group)]
    lines += [
        "",
        f"| scene | {group} | result | over 24/255 | block diff | povray s | durer s | note |",
        "|---|---|---|---:|---:|---:|---:|---|",
    ]
    for r in results:
        c = r.comparison
        over = f"{100 * c.fraction_over:.2f}%" if c else ""
        block = f"{c.block_diff:.2f}" if c else ""
        lines.append(
            f"| {r.entry.path} | {r.entry.tier} | {r.verdict} | {over} | {block} | "
            f"{seconds_text(r.povray_time)} | {seconds_text(r.durer_time)} | "
            f"{markdown_cell(r.note)} |"
        )
    return lines + [""]


def existing_sections(path):
    """The sections of an earlier report, by set name."""
    sections = {}
    if not os.path.exists(path):
        return sections
    current = None
    with open(path, encoding="utf-8") as handle:
        for line in handle.read().splitlines():
            match = re.fullmatch(r"<!-- conformance set: (\w+) -->", line)
            if match:
                current = match.group(1)
                sections[current] = []
            if current:
                sections[current].append(line)
    return sections


def write_report(path, sections):
    """Writes the report: the new sections, and the earlier report's other sections."""
    merged = existing_sections(path)
    merged.update(sections)
    lines = list(REPORT_INTRO)
    for name in SETS:
        if name in merged:
            lines += merged[name]
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    temporary = path + ".partial"
    with open(temporary, "w", encoding="utf-8") as handle:
        handle.write("\n".join(lines).rstrip("\n") + "\n")
    os.replace(temporary, path)


def default_durer():
    for profile in ("release", "debug"):
        candidate = os.path.join(REPO, "target", profile, "durer")
        if os.path.exists(candidate):
            return candidate
    return os.path.join(REPO, "target", "release", "durer")


def main():
    global WIDTH, HEIGHT
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--set", dest="sets", action="append", choices=SETS + ["all"],
                        help="which scenes: corpus (default), examples, wild or all")
    parser.add_argument("--corpus", default=os.path.join(REPO, "..", "shared", "corpus.txt"),
                        help="the list for --set corpus")
    parser.add_argument("--durer", default=None,
                        help="durer binary (default target/release/durer, else target/debug)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per render")
    parser.add_argument("--out", default=os.path.join(REPO, "docs", "conformance.md"))
    parser.add_argument("--filter", default="", help="only scenes whose path contains this")
    parser.add_argument("--wild-list", default=WILD_LIST,
                        help="the list for --set wild (default tests/wild/list.tsv)")
    parser.add_argument("--size", default=f"{WIDTH}x{HEIGHT}",
                        help="image size WIDTHxHEIGHT for both renderers (default 160x120)")
    args = parser.parse_args()
    try:
        WIDTH, HEIGHT = (int(part) for part in args.size.lower().split("x"))
    except ValueError:
        print(f"error: --size wants WIDTHxHEIGHT, got {args.size!r}", file=sys.stderr)
        return 2

    durer = os.path.abspath(args.durer) if args.durer else default_durer()
    if not os.path.exists(durer):
        print(f"error: durer binary not found at {durer}; run `cargo build --release` "
              "or pass --durer PATH", file=sys.stderr)
        return 2
    if shutil.which("povray") is None:
        print("error: povray not found on PATH; install POV-Ray 3.7 "
              "(e.g. `sudo apt-get install povray povray-includes povray-examples`)",
              file=sys.stderr)
        return 2
    sets = args.sets or ["corpus"]
    sets = SETS if "all" in sets else [name for name in SETS if name in sets]
    readers = {"corpus": lambda: read_corpus(args.corpus),
               "examples": lambda: read_all_examples(args.corpus),
               "wild": lambda: read_wild(args.wild_list)}
    chosen = {name: [e for e in readers[name]() if args.filter in e.path] for name in sets}
    if not any(chosen.values()):
        print("error: no scenes selected", file=sys.stderr)
        return 2
    os.makedirs(CACHE, exist_ok=True)
    os.makedirs(os.path.join(WORK, "durer-out"), exist_ok=True)

    sections = {}
    for name, entries in chosen.items():
        if not entries:
            continue
        start = time.monotonic()
        results = render_all(name, entries, durer, args)
        wall = time.monotonic() - start
        sections[name] = report_section(name, results, args, wall)
        print(f"{SET_TITLES[name]}:")
        for line in summary_lines(results, "category" if name == "wild" else "tier"):
            print(f"  {line}")
    write_report(args.out, sections)
    print(f"report: {os.path.abspath(args.out)}")
    return 0


def render_all(name, entries, durer, args):
    """Renders one set's scenes in parallel; results in list order."""
    results = []
    lock = threading.Lock()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run_scene, e, durer, args.timeout): e for e in entries}
        for future in concurrent.futures.as_completed(futures):
            entry = futures[future]
            try:
                result = future.result()
            except Exception as error:  # a harness bug must not lose the whole run
                result = Result(entry, "error", f"harness: {type(error).__name__}: {error}")
            with lock:
                results.append(result)
                print(f"[{name} {len(results)}/{len(entries)}] {entry.path}: {result.verdict}"
                      + (f" ({result.note})" if result.note else ""), file=sys.stderr)
    results.sort(key=lambda r: r.entry.order)
    return results

if __name__ == "__main__":
    sys.exit(main())
