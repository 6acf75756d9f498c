#!/usr/bin/env python3
"""Compare how POV-Ray 3.7 and durer read the test images of tests/reference/images.

For every image file and a few reading modes (3.7 scene at assumed_gamma 1 and 2.2, legacy
scene, `gamma` in the block, `image_pattern`, `use_alpha`), evaluates
`function { pigment { image_map { .. } } }` at the centres of sample pixels in one run of each
program (values printed with #debug) and prints the largest difference per file and mode.

Modes `height` (trace heights of `height_field`) and `palette` (`filter N`/`transmit N`,
which POV-Ray refuses for files without a palette: run it with `--only gif_` or
`--only mapped8`) are included.

usage: scripts/probe-image-formats.py [--durer PATH] [--only SUBSTRING] [--mode MODE] [--show]
"""
import argparse
import os
import re
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
IMAGES = os.path.join(HERE, "..", "tests", "reference", "images")
SIZE = 16
SAMPLES = [(0, 0), (3, 1), (7, 5), (8, 8), (12, 3), (15, 15), (5, 12), (10, 14), (14, 9)]

FORMATS = {".tga": "tga", ".ppm": "ppm", ".pgm": "pgm", ".hdr": "hdr", ".gif": "gif",
           ".jpg": "jpeg", ".png": "png"}

MODES = {
    "v37_ag1": ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n", "pigment", ""),
    "v37_ag22": ("#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n", "pigment", ""),
    "legacy": ("#version 3.6;\n", "pigment", ""),
    "gamma2": ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n", "pigment", "gamma 2.0"),
    "pattern": ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n", "pattern", ""),
    "alpha": ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n", "pattern", "use_alpha"),
    "height": ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n", "height", ""),
    "palette": ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n", "pigment",
                "filter 5, 1.0 transmit 10, 0.5"),
}


def scene(files, mode):
    prelude, kind, extra = MODES[mode]
    lines = [prelude]
    for number, name in enumerate(files):
        keyword = FORMATS[os.path.splitext(name)[1]]
        if kind == "height":
            lines.append('#declare F%d = height_field { %s "%s" }\n' % (number, keyword, name))
        elif kind == "pigment":
            lines.append('#declare F%d = function { pigment { image_map { %s "%s" %s } } }\n'
                         % (number, keyword, name, extra))
        else:
            lines.append('#declare F%d = function { pattern { image_pattern { %s "%s" %s } } }\n'
                         % (number, keyword, name, extra))
        for column, row in SAMPLES:
            u = (column + 0.5) / SIZE
            v = 1 - (row + 0.5) / SIZE
            if kind == "height":
                value = ("vstr(3, trace(F%d, <%r, 2, %r>, -y), \" \", 0, 6)"
                         % (number, min(max(column / (SIZE - 1), 1e-4), 1 - 1e-4),
                            min(max(1 - row / (SIZE - 1), 1e-4), 1 - 1e-4)))
            elif kind == "pigment":
                value = ('str(F%d(%r,%r,0).red,0,6)," ",str(F%d(%r,%r,0).green,0,6)," ",'
                         'str(F%d(%r,%r,0).blue,0,6)," ",str(F%d(%r,%r,0).filter,0,6)," ",'
                         'str(F%d(%r,%r,0).transmit,0,6)' % ((number, u, v) * 5))
            else:
                value = "str(F%d(%r,%r,0),0,6)" % (number, u, v)
            lines.append('#debug concat("PROBE %d ", %s, "\\n")\n' % (number, value))
    return "".join(lines)


def run(command, text):
    handle, path = tempfile.mkstemp(suffix=".pov", dir=IMAGES)
    try:
        with os.fdopen(handle, "w") as file:
            file.write(text)
        result = subprocess.run(command(path), capture_output=True, text=True, cwd=IMAGES)
        values = {}
        for line in (result.stdout + result.stderr).splitlines():
            match = re.match(r"PROBE (\d+) (.*)", line)
            if match:
                values.setdefault(int(match.group(1)), []).append(
                    [float(v) for v in match.group(2).split()])
        errors = [line for line in (result.stdout + result.stderr).splitlines()
                  if "rror" in line][:3]
        return values, errors
    finally:
        os.remove(path)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--durer", default=os.path.join(HERE, "..", "target", "release", "durer"))
    parser.add_argument("--only", default="")
    parser.add_argument("--mode", default="")
    parser.add_argument("--show", action="store_true")
    arguments = parser.parse_args()
    files = sorted(name for name in os.listdir(IMAGES)
                   if os.path.splitext(name)[1] in FORMATS and arguments.only in name
                   and not name.endswith(".pot"))
    for mode in MODES:
        if arguments.mode not in mode:
            continue
        text = scene(files, mode)
        povray, povray_errors = run(
            lambda path: ["povray", "-D", "+I" + path, "+W1", "+H1", "-F", "-O/dev/null"], text)
        durer, durer_errors = run(
            lambda path: [arguments.durer, "check", path], text)
        for error in povray_errors:
            print(f"{mode}: povray: {error}")
        for error in durer_errors:
            print(f"{mode}: durer: {error}")
        for number, name in enumerate(files):
            expected = povray.get(number)
            actual = durer.get(number)
            if expected is None or actual is None:
                print(f"{mode:9} {name:24} povray {'-' if expected is None else 'ok'} "
                      f"durer {'-' if actual is None else 'ok'}")
                continue
            worst = max(abs(a - b) for pe, pa in zip(expected, actual) for a, b in zip(pe, pa))
            flag = "" if worst < 0.004 else "  <-- DIFFERS"
            print(f"{mode:9} {name:24} max diff {worst:.4f}{flag}")
            if arguments.show or worst >= 0.004:
                for pe, pa in zip(expected, actual):
                    print(f"      povray {pe}  durer {pa}")


if __name__ == "__main__":
    main()
