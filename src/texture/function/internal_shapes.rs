//! The formulas behind POV-Ray's geometric internal functions (functions.inc): algebraic
//! surfaces, 2d curves swept or extruded, helices, blobs and the like.
//!
//! In: the point `x, y, z` and the function's parameters. Out: the field value, each formula
//! recovered from values povray 3.7 prints with `#debug` (the manual names the parameters but
//! gives no formulas). Holds: pure functions, no allocation.

use super::internal_table::Internal;
use std::f64::consts::PI;

/// The largest magnitude the "field strength" functions return: povray clips their values to
/// [-10, 10] (measured).
const FIELD_CLIP: f64 = 10.0;

/// `strength * value` clipped to the field range povray uses for its algebraic surfaces.
pub fn with_strength(strength: f64, value: f64) -> f64 {
    (strength * value).clamp(-FIELD_CLIP, FIELD_CLIP)
}

/// The plane a 2d curve is evaluated in: `(x, y)` unchanged when the SOR switch is zero or
/// negative (the curve is extruded along z); otherwise the distance from the y axis minus
/// `offset`, with `y`, rotated by `angle` degrees about z (the curve is swept around y).
pub fn curve_plane(x: f64, y: f64, z: f64, switch: f64, offset: f64, angle: f64) -> (f64, f64) {
    if switch <= 0.0 {
        return (x, y);
    }
    let radial = x.hypot(z) - offset;
    let (sin, cos) = angle.to_radians().sin_cos();
    (radial * cos - y * sin, radial * sin + y * cos)
}

/// The cross-section "distance" of the helix and spiral functions: `(u, v)` rotated by `angle`
/// degrees, measured with the p-norm `p = 2 / kind` (0 square, 1 circle, 2 diamond, 3 concave
/// diamond, in between rounded).
pub fn cross_section(u: f64, v: f64, kind: f64, angle: f64) -> f64 {
    let (sin, cos) = angle.to_radians().sin_cos();
    let (u, v) = ((u * cos - v * sin).abs(), (u * sin + v * cos).abs());
    if kind <= 0.0 {
        return u.max(v);
    }
    let power = 2.0 / kind;
    (u.powf(power) + v.powf(power)).powf(1.0 / power)
}

/// `f_helix1`: `count` tubes of radius `minor` winding at `major` around the y axis, `period`
/// radians per unit of height; `shape` stretches the section along y.
#[allow(clippy::too_many_arguments)]
pub fn helix1(
    (x, y, z): (f64, f64, f64),
    count: f64,
    period: f64,
    minor: f64,
    major: f64,
    shape: f64,
    kind: f64,
    angle: f64,
) -> f64 {
    let radius = x.hypot(z);
    let spacing = 2.0 * PI / count;
    let phase = ((-z).atan2(x) - period * y + PI / count).rem_euclid(spacing);
    let signed_phase = if phase < spacing / 2.0 {
        phase
    } else {
        phase - spacing
    };
    let height = -signed_phase / period;
    let section = cross_section(radius - major, height / shape, kind, angle);
    section.min(radius + major) - minor
}

/// `f_helix2`: the section centred `major` from the y axis, turned `period * y` radians about
/// it (povray ignores the section angle here).
pub fn helix2((x, y, z): (f64, f64, f64), period: f64, minor: f64, major: f64, kind: f64) -> f64 {
    let (sin, cos) = (period * y).sin_cos();
    let along = x * cos + z * sin;
    let across = z * cos - x * sin;
    cross_section(along - major, across, kind, 0.0) - minor
}

/// `f_blob2`: two gaussian components, at the origin and `separation` along x.
pub fn blob2(
    (x, y, z): (f64, f64, f64),
    separation: f64,
    inverse_size: f64,
    strength: f64,
    threshold: f64,
) -> f64 {
    let near = x * x + y * y + z * z;
    let far = (x - separation).powi(2) + y * y + z * z;
    threshold - strength * ((-inverse_size * near).exp() + (-inverse_size * far).exp())
}

/// `f_blob(x,y,z, separation, strength1, inverse radius1, strength2, inverse radius2)`: two
/// blob components at `∓separation / 2` on the x axis, each `-s (1 - (k r)²)²` within `1 / k`.
pub fn blob((x, y, z): (f64, f64, f64), separation: f64, components: [(f64, f64); 2]) -> f64 {
    let [(strength1, inverse1), (strength2, inverse2)] = components;
    let component = |centre: f64, strength: f64, inverse_radius: f64| {
        let scaled = inverse_radius * inverse_radius * ((x - centre).powi(2) + y * y + z * z);
        if scaled < 1.0 {
            strength * (1.0 - scaled).powi(2)
        } else {
            0.0
        }
    };
    -(component(-separation / 2.0, strength1, inverse1)
        + component(separation / 2.0, strength2, inverse2))
}

/// The exponents of the three ellipsoids, one along each axis, of `f_cross_ellipsoids`,
/// `f_isect_ellipsoids` and `f_flange_cover`: `k (axis² + e (other two²))`.
pub fn axis_ellipsoids(
    (x, y, z): (f64, f64, f64),
    eccentricity: f64,
    inverse_size: f64,
) -> [f64; 3] {
    let (xx, yy, zz) = (x * x, y * y, z * z);
    [
        inverse_size * (xx + eccentricity * (yy + zz)),
        inverse_size * (yy + eccentricity * (xx + zz)),
        inverse_size * (zz + eccentricity * (xx + yy)),
    ]
}

/// `f_quantum`: a d orbital's density, `1.2 - 1.6 e^(-4r/3) (3y² - r²)²` (povray's exponent
/// factor is 1.33333332, measured).
pub fn quantum((x, y, z): (f64, f64, f64)) -> f64 {
    let squared = x * x + y * y + z * z;
    1.2 - 1.6 * (-1.333_333_32 * squared.sqrt()).exp() * (3.0 * y * y - squared).powi(2)
}

/// `f_hex_x`: the hexagonal distance to the nearest centre of a honeycomb of prisms along z,
/// centres `√3` apart along x and `(√3/2, 3/2)` apart diagonally.
pub fn hexagonal_prisms(x: f64, y: f64) -> f64 {
    let root3 = 3f64.sqrt();
    let hexagon = |u: f64, v: f64| u.abs().max(u.abs() / 2.0 + v.abs() * root3 / 2.0);
    let column = (x / root3).round();
    let row = (y / 3.0).round();
    let mut nearest = f64::INFINITY;
    for i in -1..=1 {
        for j in -1..=1 {
            let (centre_x, centre_y) =
                ((column + f64::from(i)) * root3, (row + f64::from(j)) * 3.0);
            nearest = nearest
                .min(hexagon(x - centre_x, y - centre_y))
                .min(hexagon(x - centre_x - root3 / 2.0, y - centre_y - 1.5));
        }
    }
    nearest
}

/// `f_spikes(x,y,z, spikiness, hollowness, size, roundness, fatness)`: the three axis
/// ellipsoids' gaussians (exponents scaled by the hollowness) less a central gaussian.
pub fn spikes((x, y, z): (f64, f64, f64), parameters: [f64; 5]) -> f64 {
    let [spikiness, hollowness, size, roundness, fatness] = parameters;
    let arms: f64 = axis_ellipsoids((x, y, z), spikiness, hollowness)
        .iter()
        .map(|exponent| (-exponent).exp())
        .sum();
    size * (arms - fatness * (-roundness * (x * x + y * y + z * z)).exp())
}

/// `f_spiral(x,y,z, spacing, thickness, outer radius, -, -, section)`: an Archimedean
/// spiral in the xz plane, `spacing` further out each turn, cut off by a sphere.
pub fn spiral(
    (x, y, z): (f64, f64, f64),
    spacing: f64,
    thickness: f64,
    outer: f64,
    kind: f64,
) -> f64 {
    // povray moves a point on the y axis 1e-6 off it (measured).
    let radius = x.hypot(z);
    let radius = if radius == 0.0 { 1e-6 } else { radius };
    let turn = (radius / spacing - (-z).atan2(x) / (2.0 * PI)).rem_euclid(1.0);
    let distance = radius.hypot(y);
    let section = cross_section((turn - 0.5) * spacing, y, kind, 0.0).min(distance);
    (section - thickness).max(distance - outer)
}

/// The most tubes `f_polytubes` draws (a guard against absurd counts).
const MAX_TUBES: f64 = 1024.0;

/// `f_polytubes(x,y,z, count, c0..c4)`: the distance to the nearest of `count` vertical
/// tubes whose distance from the y axis is the quartic in y, the first towards +z.
pub fn polytubes((x, y, z): (f64, f64, f64), count: f64, coefficients: [f64; 5]) -> f64 {
    let radius = quartic(y, coefficients);
    let count = count.clamp(1.0, MAX_TUBES).floor();
    let mut nearest = f64::INFINITY;
    let mut tube = 0.0;
    while tube < count {
        let (sin, cos) = (2.0 * PI * tube / count).sin_cos();
        nearest = nearest.min((x - radius * sin).hypot(z - radius * cos));
        tube += 1.0;
    }
    nearest
}

/// `f_hex_y`: the distance to the nearest line of the triangular grid through the centres
/// of `f_hex_x`'s honeycomb (lines along x, at 60° and at 120°, 1.5 apart in each family).
pub fn hexagonal_lines(x: f64, y: f64) -> f64 {
    let half_root3 = 3f64.sqrt() / 2.0;
    [(0.0, 1.0), (half_root3, 0.5), (half_root3, -0.5)]
        .iter()
        .map(|(a, b)| {
            let offset = (a * x + b * y).rem_euclid(LINE_SPACING);
            offset.min(LINE_SPACING - offset)
        })
        .fold(f64::INFINITY, f64::min)
}

/// The distance between neighbouring parallel lines of `f_hex_y`.
const LINE_SPACING: f64 = 1.5;

/// `f_mesh1(x,y,z, x spacing, z spacing, thickness, amplitude, y thickness)`: the
/// distance to the nearest thread of a woven grid, threads along z every `x spacing` and
/// along x every `z spacing`, each rising and falling `amplitude cos(π t / spacing)`
/// opposite to its neighbours.
pub fn mesh1((x, y, z): (f64, f64, f64), parameters: [f64; 5]) -> f64 {
    let [x_spacing, z_spacing, thickness, amplitude, y_thickness] = parameters;
    let distance =
        |across: f64, height: f64| (thickness * across).hypot(y_thickness * (y - height));
    let alternate = |index: f64| {
        if index.rem_euclid(2.0) == 0.0 {
            1.0
        } else {
            -1.0
        }
    };
    let (column, row) = ((x / x_spacing).round(), (z / z_spacing).round());
    let mut nearest = f64::INFINITY;
    for step in [-1.0, 0.0, 1.0] {
        let along_z = -amplitude * (PI * z / z_spacing).cos() * alternate(column + step);
        nearest = nearest.min(distance(x - (column + step) * x_spacing, along_z));
        let along_x = amplitude * (PI * x / x_spacing).cos() * alternate(row + step);
        nearest = nearest.min(distance(z - (row + step) * z_spacing, along_x));
    }
    nearest
}

/// The quartic `c0 + c1 y + c2 y² + c3 y³ + c4 y⁴` of `f_poly4`.
pub fn quartic(y: f64, coefficients: [f64; 5]) -> f64 {
    coefficients
        .iter()
        .rev()
        .fold(0.0, |sum, coefficient| sum * y + coefficient)
}

/// Apéry's sextic for Boy's surface.
fn apery_boy_surface(x: f64, y: f64, z: f64) -> f64 {
    let root2 = std::f64::consts::SQRT_2;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let around = xx + yy;
    64.0 * (1.0 - z).powi(3) * z * zz - 48.0 * (1.0 - z).powi(2) * zz * (3.0 * around + 2.0 * zz)
        + 12.0
            * (1.0 - z)
            * z
            * (27.0 * around * around - 24.0 * zz * around
                + 36.0 * root2 * y * z * (yy - 3.0 * xx)
                + 4.0 * zz * zz)
        + (9.0 * around - 2.0 * zz)
            * (-81.0 * around * around - 72.0 * zz * around
                + 108.0 * root2 * x * z * (xx - 3.0 * yy)
                + 4.0 * zz * zz)
}

/// The algebraic surfaces and curves that take a field strength, by function: the
/// polynomial (before strength) at `(x, y, z)` with the remaining parameters.
pub fn algebraic(function: Internal, (x, y, z): (f64, f64, f64), p: &[f64]) -> f64 {
    let parameter = |index: usize| p.get(index).copied().unwrap_or(0.0);
    let (a, b, c) = (parameter(0), parameter(1), parameter(2));
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let rr = xx + yy + zz;
    let fourth_powers = xx * xx + yy * yy + zz * zz;
    let mixed_squares = xx * yy + yy * zz + zz * xx;
    match function {
        // f_algbr_cyl1..4 (2d curves in x, y).
        Internal::AlgebraicCylinder1 => yy - xx + x.abs().powi(3),
        Internal::AlgebraicCylinder2 => -yy + 2.0 * y * yy - yy * yy + 3.0 * xx * y - 2.0 * xx * xx,
        Internal::AlgebraicCylinder3 => -yy + x * yy + 2.0 * xx * y - xx * yy - xx * xx,
        Internal::AlgebraicCylinder4 => y * yy - yy * yy - 3.0 * xx * y - 2.0 * xx * yy - xx * xx,
        // f_boy_surface: Apéry's sextic, scaled by a as well as the strength (measured).
        Internal::BoySurface => a * apery_boy_surface(x, y, z),
        // f_bicorn, scale a.
        Internal::Bicorn => {
            let around = xx + zz;
            yy * (a * a - around) - (around + 2.0 * a * y - a * a).powi(2)
        }
        // f_bifolia, scale a.
        Internal::Bifolia => a * y * (xx + zz) - rr * rr,
        Internal::CrossedTrough => xx * zz - y,
        Internal::CubicSaddle => z + y * yy - x * xx,
        // f_cushion and f_odd (povray gives both the same values).
        Internal::Cushion | Internal::Odd => {
            xx + yy - 2.0 * zz + 2.0 * z * zz + 2.0 * yy * z - zz * zz - yy * zz - yy * yy + xx * zz
                - 2.0 * xx * yy
                - xx * xx
        }
        Internal::DevilsCurve => {
            -yy / 4.0 + 9.0 * xx / 25.0 - zz * zz + yy * yy - 2.0 * xx * zz - xx * xx
        }
        // f_devils_curve_2d, x factor a, y factor b.
        Internal::DevilsCurve2d => -b * b * yy + yy * yy + a * a * xx - xx * xx,
        // f_folium_surface, neck a, divergence b.
        Internal::FoliumSurface => yy + zz + xx * (1.0 + b) + x * (yy + zz) * (b - 4.0 * a),
        Internal::FoliumSurface2d => -(yy + xx * (1.0 + b) + x * yy * (b - 4.0 * a)),
        Internal::Glob => x * xx * xx / 2.0 + xx * xx / 2.0 - yy - zz,
        Internal::Heart => xx * z * zz / 10.0 + yy * z * zz - (2.0 * xx + yy + zz - 1.0).powi(3),
        // f_hyperbolic_torus, major a, minor b.
        // f_hunt_surface.
        Internal::HuntSurface => {
            -(4.0 * (rr - 13.0).powi(3) + 27.0 * (3.0 * xx + yy - 4.0 * zz - 12.0).powi(2))
        }
        Internal::HyperbolicTorus => {
            -(xx + yy - zz + a * a - b * b).powi(2) + 4.0 * a * a * (xx - zz)
        }
        // f_kampyle_of_eudoxus, dimple a, closeness b.
        Internal::KampyleOfEudoxus => b * b * xx * (xx - a * a) - yy - zz,
        Internal::KampyleOfEudoxus2d => -yy - a * b * b * b * xx + b * b * xx * xx,
        Internal::KleinBottle => {
            let lower = rr - 2.0 * y - 1.0;
            -((rr + 2.0 * y - 1.0) * (lower * lower - 8.0 * zz) + 16.0 * x * z * lower)
        }
        Internal::KummerSurface1 => -1.0 + rr - fourth_powers + mixed_squares,
        // f_kummer_surface_v2, rod width a, divergence b, rod length c.
        Internal::KummerSurface2 => {
            1.0 - a * rr - fourth_powers - b * mixed_squares - c * x * y * z
        }
        Internal::LemniscateOfGerono => xx - xx * xx - yy - zz,
        // f_piriform_2d, size factors a and b, fatness c.
        Internal::Piriform2d => -yy + c * c * xx * (a * x + b * xx),
        // f_lemniscate_of_gerono_2d, size a, width b.
        Internal::LemniscateOfGerono2d => -yy + a * a * b * b * xx - b * b * xx * xx,
        Internal::Mitre => yy * (1.0 - yy - zz) - 4.0 * xx * rr,
        Internal::NodalCubic => 6.0 * y * z - z * zz - y * yy,
        // f_ovals_of_cassini, major a, filling b, thickness c.
        Internal::OvalsOfCassini => -(rr + a * a).powi(2) + a * a * c * (xx + zz) + b * b,
        // f_parabolic_torus, major a, minor b.
        Internal::ParabolicTorus => {
            let (major, minor) = (a * a, b * b);
            -(xx + yy - z).powi(2) - (major - minor).powi(2) - (major - minor) * yy
                + (major + minor) * (xx - z)
        }
        Internal::Pillow => fourth_powers - rr,
        Internal::Piriform => xx * xx - x * xx + yy + zz,
        Internal::QuarticParaboloid => y - xx * xx - zz * zz,
        Internal::QuarticSaddle => y + zz * zz - xx * xx,
        // f_quartic_cylinder, egg diameter a, width b.
        Internal::QuarticCylinder => a * a * b * b - (xx + zz) * (yy + b * b),
        Internal::SteinersRoman => -x * y * z - mixed_squares,
        // f_strophoid (and its 2d curve with z = 0), bulb a, sharpness b, fatness c.
        Internal::Strophoid | Internal::Strophoid2d => (x - b) * (yy + zz) + c * c * xx * (x + a),
        Internal::TorusGumdrop => {
            let around = yy + zz;
            -17.0 + 20.0 * rr - 4.0 * around * around - 17.0 * xx * around - 4.0 * xx * xx
        }
        Internal::Umbrella => y * zz - xx,
        // f_witch_of_agnesi, width a.
        Internal::WitchOfAgnesi => a - y * (a + xx + zz),
        // f_witch_of_agnesi_2d, size a, height b.
        Internal::WitchOfAgnesi2d => b - y * (a * a + xx),
        // No polynomial: [`Internal::eval`] computes these otherwise and never asks.
        Internal::Blob
        | Internal::Blob2
        | Internal::CrossEllipsoids
        | Internal::Ellipsoid
        | Internal::FlangeCover
        | Internal::Helix1
        | Internal::Helix2
        | Internal::HexagonalPrisms
        | Internal::HexagonalLines
        | Internal::HeteroMultifractal
        | Internal::IsectEllipsoids
        | Internal::Mesh1
        | Internal::Paraboloid
        | Internal::Phi
        | Internal::Poly4
        | Internal::Polytubes
        | Internal::Quantum
        | Internal::Radius
        | Internal::Ridge
        | Internal::RidgedMultifractal
        | Internal::RoundedBox
        | Internal::Sphere
        | Internal::Spikes
        | Internal::Spikes2d
        | Internal::Spiral
        | Internal::Superellipsoid
        | Internal::Theta
        | Internal::Torus
        | Internal::Torus2
        | Internal::Noise3d
        | Internal::NoiseGenerator
        | Internal::Comma
        | Internal::DupinCyclid
        | Internal::Enneper
        | Internal::HelicalTorus => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sor_switch_sweeps_the_curve_around_y() {
        assert_eq!(curve_plane(0.3, 0.4, 0.5, 0.0, 0.2, 30.0), (0.3, 0.4));
        let (u, v) = curve_plane(0.3, 0.4, 0.4, 1.0, 0.5, 90.0);
        assert!((u + 0.4).abs() < 1e-12 && v.abs() < 1e-12, "({u}, {v})");
    }

    #[test]
    fn cross_sections_are_squares_circles_and_diamonds() {
        assert!((cross_section(0.3, 0.4, 0.0, 0.0) - 0.4).abs() < 1e-12);
        assert!((cross_section(0.3, 0.4, 1.0, 0.0) - 0.5).abs() < 1e-12);
        assert!((cross_section(0.3, 0.4, 2.0, 0.0) - 0.7).abs() < 1e-12);
    }

    #[test]
    fn quartic_is_evaluated_in_rising_powers() {
        assert!((quartic(2.0, [1.0, 2.0, 3.0, 4.0, 5.0]) - 129.0).abs() < 1e-12);
    }
}
