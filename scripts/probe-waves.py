#!/usr/bin/env python3
"""Measure the wave sources of POV-Ray 3.7's ripples and waves patterns, black-box.

Checks, against povray, the model src/texture/pattern/waves.rs implements (needs numpy):

1. centres: source i is POV-Ray's vector noise at <i, 0, 0>, normalised (read through
   povray's own `vturbulence(2, 0.5, 1, <i, 0, 0>)`); ripples values at random points
   must equal 0.5 + sum(sin(2 pi d_i)) / (2 N);
2. frequencies: fitted by Gauss-Newton from waves values, model
   0.5 + sum(sin(2 pi f_i d_i) / f_i) / (5 N) (start: the peaks of a spectrum of waves
   along a far line, assigned to centres by a linear fit), then compared with the LCG rule
   f_i = ((s >> 16) & 0x7FFF) / 32767 + 0.01, s = s * 1812433253 + 12345 from -560851967;
3. number_of_waves: 16-bit linear renders of ripples/waves pigments with N sources;
4. normals: 16-bit linear renders of `normal { ripples|waves 0.3 }` on a plane lit from five
   directions against normalize(n + 0.3 * sum(u_i * w_i) / N), u_i the unit direction from
   centre i, w_i = sin(2 pi (d_i f + phase)) (ripples) or sin(2 pi (d_i f_i f + phase)) / f_i.

Prints the largest deviation of each check (values ~1e-15; renders ~8e-6, the 16-bit step).

usage: scripts/probe-waves.py
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import imagediff  # noqa: E402

WORK = tempfile.mkdtemp(prefix="probe-waves-")
SEED = (-560851967) % 2**32


def povray_lines(body):
    """Runs a 1x1 povray scene and returns the fields of its `PROBE` debug lines."""
    path = os.path.join(WORK, "probe.pov")
    with open(path, "w") as scene:
        scene.write("#version 3.7;\n" + body)
    result = subprocess.run(
        ["povray", "-D", "+I" + path, "+W1", "+H1", "-F", "-O/dev/null"],
        capture_output=True,
        text=True,
        check=False,
    )
    return [line.split()[1:] for line in result.stderr.splitlines() if line.startswith("PROBE")]


def pattern_values(spec, points):
    body = "#declare F_ = function { pattern { %s } }\n" % spec
    for x, y, z in points:
        body += '#debug concat("PROBE ", str(F_(%r, %r, %r), 0, 17), "\\n")\n' % (
            float(x), float(y), float(z))
    return np.array([float(fields[0]) for fields in povray_lines(body)])


def centres(count):
    body = ""
    for i in range(count):
        body += (
            "#local V_ = vturbulence(2, 0.5, 1, <%d, 0, 0>);\n"
            '#debug concat("PROBE ", str(V_.x, 0, 17), " ", str(V_.y, 0, 17), " ",'
            ' str(V_.z, 0, 17), "\\n")\n' % i
        )
    vectors = np.array([[float(v) for v in fields] for fields in povray_lines(body)])
    return vectors / np.linalg.norm(vectors, axis=1)[:, None]


def lcg_frequencies(count):
    state, result = SEED, []
    for _ in range(count):
        state = (state * 1812433253 + 12345) % 2**32
        result.append(((state >> 16) & 0x7FFF) / 32767 + 0.01)
    return np.array(result)


def fit_frequencies(points, values, centre):
    """Per-source frequencies of `waves`, fitted from scratch."""
    # Spectrum along a far line: every source shows as one sine of its frequency.
    direction = np.array([0.3, 0.5, 0.8]) / np.linalg.norm([0.3, 0.5, 0.8])
    count, step = 4096, 0.05
    t = 1000 + step * np.arange(count)
    line = pattern_values("waves", t[:, None] * direction[None])
    spectrum = np.abs(np.fft.rfft((line - line.mean()) * np.hanning(count)))
    frequency_axis = np.fft.rfftfreq(count, step)
    peaks = [k for k in range(1, len(spectrum) - 1)
             if spectrum[k] > spectrum[k - 1] and spectrum[k] > spectrum[k + 1]]
    peaks = sorted(peaks, key=lambda k: -spectrum[k])[: len(centre)]
    candidates = frequency_axis[peaks]
    # Which peak belongs to which centre: a linear fit over all pairs.
    distance = np.linalg.norm(points[:, None, :] - centre[None], axis=2)
    columns = [np.ones(len(values))]
    for i in range(len(centre)):
        for f in candidates:
            columns += [np.sin(2 * np.pi * f * distance[:, i]) / f,
                        np.cos(2 * np.pi * f * distance[:, i]) / f]
    coefficients = np.linalg.lstsq(np.array(columns).T, values, rcond=None)[0]
    weight = np.hypot(coefficients[1::2], coefficients[2::2]).reshape(len(centre), -1)
    frequency = candidates[weight.argmax(axis=1)].copy()
    # Refine with the full model.
    for _ in range(30):
        model = 0.5 + (np.sin(2 * np.pi * frequency * distance) / frequency).sum(1) / (5 * len(centre))
        residual = values - model
        jacobian = (2 * np.pi * distance * np.cos(2 * np.pi * frequency * distance) / frequency
                    - np.sin(2 * np.pi * frequency * distance) / frequency**2) / (5 * len(centre))
        frequency += np.linalg.lstsq(jacobian, residual, rcond=None)[0]
    return frequency, np.abs(residual).max()


def render_plane(texture, width=80, height=60, settings=""):
    """A 16-bit linear render of the plane z = 0 seen from -z over [-2, 2] x [-1.5, 1.5]."""
    scene = os.path.join(WORK, "plane.pov")
    image = os.path.join(WORK, "plane.png")
    with open(scene, "w") as handle:
        handle.write(
            "#version 3.7;\nglobal_settings { assumed_gamma 1 %s }\n"
            "camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }\n"
            "%s\n" % (settings, texture))
    subprocess.run(["povray", "+I" + scene, "+O" + image, "+W%d" % width, "+H%d" % height, "-A",
                    "+FN16", "File_Gamma=1.0", "-D", "-GA", "+WT1"], capture_output=True, check=False)
    decoded = imagediff.read_png(image)
    red = np.array(decoded.pixels, dtype=float)[0::3] / 255.0
    xs = -2 + (np.arange(width) + 0.5) * 4 / width
    ys = 1.5 - (np.arange(height) + 0.5) * 3 / height
    grid_x, grid_y = np.meshgrid(xs, ys)
    points = np.stack([grid_x, grid_y, np.zeros_like(grid_x)], -1).reshape(-1, 3)
    return points, red


def main():
    rng = np.random.default_rng(2)
    points = rng.uniform(-4, 4, (400, 3))
    centre = centres(40)
    frequency = lcg_frequencies(40)
    distance = np.linalg.norm(points[:, None, :] - centre[None, :10], axis=2)

    ripples = pattern_values("ripples", points)
    model = 0.5 + np.sin(2 * np.pi * distance).sum(1) / 20
    print("ripples values vs model:           %.3g" % np.abs(ripples - model).max())

    waves = pattern_values("waves", points)
    fitted, residual = fit_frequencies(points, waves, centre[:10])
    print("waves frequency fit residual:       %.3g" % residual)
    print("fitted frequencies vs LCG rule:     %.3g" % np.abs(fitted - frequency[:10]).max())

    for kind in ("ripples", "waves"):
        for count in (1, 3, 12, 40):
            grid, image = render_plane(
                "plane { -z, 0 pigment { %s color_map { [0 rgb 0] [1 rgb 1] } }"
                " finish { ambient 1 diffuse 0 } }" % kind,
                settings="number_of_waves %d" % count)
            d = np.linalg.norm(grid[:, None, :] - centre[None, :count], axis=2)
            f = frequency[:count]
            if kind == "ripples":
                value = 0.5 + np.sin(2 * np.pi * d).sum(1) / (2 * count)
            else:
                value = 0.5 + (np.sin(2 * np.pi * f * d) / f).sum(1) / (5 * count)
            value = np.clip(value % 1.00001, 0, 1)
            print("%-7s number_of_waves %-2d render:  %.3g" % (kind, count, np.abs(value - image).max()))

    lights = [(0, 0, -1), (0.6, 0, -0.8), (0, 0.6, -0.8), (-0.6, 0, -0.8), (0, -0.6, -0.8)]
    for kind, scale, phase in (("ripples", 1, 0), ("ripples", 2, 0.1), ("waves", 1, 0), ("waves", 0.7, 0.35)):
        worst = 0.0
        for light in lights:
            grid, image = render_plane(
                "light_source { <%g, %g, %g> * 1000 color 1 parallel point_at 0 shadowless }\n"
                "plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 specular 0 }"
                " normal { %s 0.3 frequency %g phase %g } }" % (light + (kind, scale, phase)))
            offset = grid[:, None, :] - centre[None, :10]
            d = np.linalg.norm(offset, axis=2)
            f = frequency[:10] if kind == "waves" else 1.0
            weight = np.sin(2 * np.pi * (d * f * scale + phase)) / f
            perturbation = (offset / d[..., None] * weight[..., None]).sum(1) / 10
            normal = np.array([0, 0, -1.0]) + 0.3 * perturbation
            normal /= np.linalg.norm(normal, axis=1)[:, None]
            worst = max(worst, np.abs(np.clip(normal @ np.array(light), 0, 1) - image).max())
        print("%-7s normal frequency %-3g phase %-4g: %.3g" % (kind, scale, phase, worst))


if __name__ == "__main__":
    main()
