//! Four internal functions of functions.inc whose formulas are not polynomials in `x, y, z`
//! alone: `f_comma`, `f_dupin_cyclid`, `f_enneper` and `f_helical_torus`.
//!
//! In: the point `x, y, z` and the function's parameters. Out: the field value. Each formula
//! was recovered from values povray 3.7 prints with `#debug` (the manual names the parameters
//! only) and is checked against them in internal_known_answers.txt. Holds: pure functions, no
//! allocation; odd inputs give povray's odd values (NaN only where povray's would be).

use super::internal_shapes::with_strength;
use std::f64::consts::PI;

/// The `x` povray puts for a point on the y axis in `f_comma` (measured: `f_comma(0,y,0, s)`
/// equals `f_comma(1e-4,y,0, s)`).
const COMMA_AXIS_X: f64 = 1e-4;

/// `f_comma(x,y,z, scale)`: a ball of diameter `scale` touching the origin from +x, and a tail
/// curling from the tip `(-scale, 0, 0)` over +z back into the ball. The tail is a tube around
/// the circle of radius `3/4 scale` centred at `(-scale/4, 0, 0)` in the xz plane, whose radius
/// is `scale/2 cos(θ/2)` with `θ` the angle about the y axis from +x (0 at the ball, π at the
/// tip), cut off below the plane `z = 0`.
pub fn comma((x, y, z): (f64, f64, f64), scale: f64) -> f64 {
    let x = if x == 0.0 && z == 0.0 {
        COMMA_AXIS_X
    } else {
        x
    };
    let half = 0.5 * scale;
    let ball = ((x - half).powi(2) + y * y + z * z).sqrt() - half;
    let angle = z.abs().atan2(x);
    let from_circle = (x + 0.25 * scale).hypot(z) - 0.75 * scale;
    let tube = from_circle.hypot(y) - half * (0.5 * angle).cos();
    ball.min((-z).max(tube))
}

/// `f_dupin_cyclid(x,y,z, strength, major, minor, x shift, y shift, inversion radius)`: the
/// torus of radii `major`, `minor` around the y axis, shifted by `(x shift, y shift, 0)`, seen
/// through the inversion in the sphere of the given radius about the origin, multiplied out so
/// that no division remains (the origin gives `-strength k⁸`). One difference from the plain
/// inverted torus, measured: the term `2 (major² - minor²) |q|²` of the torus equation takes
/// the y shift with the opposite sign.
pub fn dupin_cyclid((x, y, z): (f64, f64, f64), parameters: [f64; 6]) -> f64 {
    let [strength, major, minor, shift_x, shift_y, inversion] = parameters;
    let rr = x * x + y * y + z * z;
    let k2 = inversion * inversion;
    let shift2 = shift_x * shift_x + shift_y * shift_y;
    let radii = major * major - minor * minor;
    // |q|² |p|² for the inverted point q = k² p / |p|² - shift, and its mirror in the y shift.
    let inverted = k2 * k2 - 2.0 * k2 * (x * shift_x + y * shift_y) + shift2 * rr;
    let mirrored = k2 * k2 - 2.0 * k2 * (x * shift_x - y * shift_y) + shift2 * rr;
    let across = (k2 * x - shift_x * rr).powi(2) + k2 * k2 * z * z;
    let quartic = inverted * inverted + 2.0 * radii * rr * mirrored + radii * radii * rr * rr
        - 4.0 * major * major * across;
    with_strength(-strength, quartic)
}

/// How close to the plane `z = 0` povray's `f_enneper` stops dividing by `z` (measured: the
/// field is the `|z| = 0.2` one all through `|z| < 0.2`).
const ENNEPER_MIN_Z: f64 = 0.2;

/// `f_enneper(x,y,z, strength)`: `(P - Q)³ + 3/2 P²` with `P = (x² - y²) / 2z` and
/// `Q = 2/9 z²`, `z` in the division raised to 0.2 where `|z| < 0.2`.
pub fn enneper((x, y, z): (f64, f64, f64), strength: f64) -> f64 {
    let divisor = if z.abs() >= ENNEPER_MIN_Z {
        z
    } else {
        ENNEPER_MIN_Z
    };
    let p = (x * x - y * y) / (2.0 * divisor);
    let q = 2.0 / 9.0 * z * z;
    with_strength(strength, (p - q).powi(3) + 1.5 * p * p)
}

/// `f_helical_torus(x,y,z, major, loops, twist, fatness, threshold, inner, winding fatness,
/// groove period, groove amplitude, groove phase)`, in the torus's own coordinates: `θ` the
/// angle about the y axis (`atan2(x, z)`), `d` the distance from the core circle of radius
/// `major`, `φ = atan2(ρ - major, y)` the angle about the core. The winding's phase
/// `w = loops θ + twist φ - π`, wrapped to [-π, π), is 0 on the winding; the winding field is
/// `√((d - inner)² + winding fatness w²)`, at most `d + inner`, grooved by
/// `fatness cos(groove period atan2(groove amplitude w, d - inner) + groove phase θ)`; the
/// result is the smaller of that and the column `ρ + major - inner`, less `threshold`.
pub fn helical_torus((x, y, z): (f64, f64, f64), parameters: [f64; 10]) -> f64 {
    let [major, loops, twist, fatness, threshold, inner, winding, period, amplitude, phase] =
        parameters;
    let radial = x.hypot(z);
    let around = x.atan2(z);
    let out = radial - major;
    let distance = out.hypot(y);
    let about_core = out.atan2(y);
    let turn = loops * around + twist * about_core - PI;
    let w = turn - 2.0 * PI * ((turn + PI) / (2.0 * PI)).floor();
    // A negative winding fatness makes the root NaN, and povray's comparisons then keep it
    // here and drop it below (measured: the column is left).
    let squared = (distance - inner).powi(2) + winding * w * w;
    let core = if squared >= 0.0 {
        squared.sqrt()
    } else {
        f64::NAN
    };
    let capped = if distance + inner < core {
        distance + inner
    } else {
        core
    };
    let groove = (period * (amplitude * w).atan2(distance - inner) + phase * around).cos();
    let wound = capped - fatness * groove;
    let column = radial + major - inner;
    (if wound < column { wound } else { column }) - threshold
}
