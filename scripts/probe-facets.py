#!/usr/bin/env python3
"""Compare durer's `facets` normal with POV-Ray 3.7's, black-box (standard library only).

Renders a lit plane and a lit sphere carrying `normal { facets ... }` with many settings
(coords and size forms, bump amounts that must be ignored, tiny and negative sizes,
transformed patterns and objects, turbulence) with both povray and durer at 160x120 without
anti-aliasing, and prints the largest channel difference and the share of differing pixels
of each. Needs povray on the PATH and a release build (target/release/durer).

usage: scripts/probe-facets.py
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import imagediff  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = tempfile.mkdtemp(prefix="probe-facets-")
SCENE = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }
light_source { <0.6, 0.3, -0.8> * 1000 color 1 parallel point_at 0 shadowless }
%s pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { %s } %s }
"""
SHAPES = ["plane { -z, 0", "sphere { 0, 1.4"]
NORMALS = [
    "facets coords 0.5",
    "facets 3 coords 1",
    "facets coords -0.4 size 0.3 scale 3",
    "facets coords 0.5 scale <1, 2, 0.5> rotate 20 * x",
    "facets coords 0.5 turbulence 0.5",
    "facets coords 0.5 size 0",
    "facets",
    "facets 3 size 0.05",
    "facets size 0.2 scale <1, 2, 1> rotate 30 * y",
    "facets size 0",
    "facets size -0.2",
]
OBJECT_TRANSFORMS = ["", "scale <1, 0.7, 1> rotate 20 * y"]


def render(renderer, scene, image):
    if renderer == "povray":
        command = ["povray", "+I" + scene, "+O" + image, "+W160", "+H120", "-A", "-D", "-GA",
                   "+WT1"]
    else:
        command = [os.path.join(ROOT, "target/release/durer"), "render", "-q", "--width", "160",
                   "--height", "120", "-o", image, scene]
    subprocess.run(command, capture_output=True, check=False)
    return imagediff.read_png(image).pixels


def main():
    scene = os.path.join(WORK, "facets.pov")
    for shape in SHAPES:
        for normal in NORMALS:
            for transform in OBJECT_TRANSFORMS:
                with open(scene, "w") as handle:
                    handle.write(SCENE % (shape, normal, transform))
                expected = render("povray", scene, os.path.join(WORK, "povray.png"))
                actual = render("durer", scene, os.path.join(WORK, "durer.png"))
                differences = [abs(a - b) for a, b in zip(expected, actual)]
                pixels = [max(differences[i:i + 3]) for i in range(0, len(differences), 3)]
                share = sum(1 for d in pixels if d > 0) / len(pixels)
                print("%-16s %-52s %-33s max %3d  differing %.3f%%" % (
                    shape.split()[0], normal, transform, max(pixels), 100 * share))


if __name__ == "__main__":
    main()
