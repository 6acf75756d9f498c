//! POV-Ray's built-in functions of functions.inc (`function { internal(N) }`), those durer
//! implements.
//!
//! In: the number N and the call's arguments `x, y, z, P0, P1, ..`. Out: the function's
//! value, each formula checked against values povray 3.7 prints with `#debug` (the table in
//! internal_known_answers.txt). Holds: pure functions; numbers durer does not implement are
//! refused when compiled. The formulas live in internal_shapes.rs, internal_surfaces.rs and
//! internal_fractals.rs.

use super::internal_fractals::{
    generator_parameter, hetero_multifractal, ridge, ridged_multifractal, Multifractal,
};
use super::internal_shapes::{
    algebraic, axis_ellipsoids, blob, blob2, curve_plane, helix1, helix2, hexagonal_lines,
    hexagonal_prisms, mesh1, polytubes, quantum, quartic, spikes, spiral, with_strength,
};
use super::internal_surfaces::{comma, dupin_cyclid, enneper, helical_torus};
use super::internal_table::Internal;
use crate::noise::{noise, NoiseGenerator};
use glam::DVec3;

/// The offset POV-Ray subtracts from `f_rounded_box`'s distance (measured).
const ROUNDED_BOX_OFFSET: f64 = 1e-6;

impl Internal {
    /// The value for the arguments `x, y, z, P0, ..` (missing ones read as 0).
    pub fn eval(self, arguments: &[f64]) -> f64 {
        let argument = |index: usize| arguments.get(index).copied().unwrap_or(0.0);
        // Five consecutive arguments from `first` on.
        let run = |first: usize| -> [f64; 5] { std::array::from_fn(|i| argument(first + i)) };
        let (x, y, z) = (argument(0), argument(1), argument(2));
        let point = DVec3::new(x, y, z);
        let shape_parameters = arguments.get(4..).unwrap_or(&[]);
        match self {
            Internal::AlgebraicCylinder1
            | Internal::AlgebraicCylinder2
            | Internal::AlgebraicCylinder3
            | Internal::AlgebraicCylinder4 => {
                let (strength, limit) = (argument(3), argument(4));
                let (u, v) = curve_plane(x, y, z, argument(5), argument(6), argument(7));
                let value = strength * algebraic(self, (u, v, 0.0), &[]);
                value.max(-limit).min(limit)
            }
            Internal::DevilsCurve2d
            | Internal::FoliumSurface2d
            | Internal::KampyleOfEudoxus2d
            | Internal::LemniscateOfGerono2d
            | Internal::WitchOfAgnesi2d => {
                let (u, v) = curve_plane(x, y, z, argument(6), argument(7), argument(8));
                with_strength(argument(3), algebraic(self, (u, v, 0.0), shape_parameters))
            }
            Internal::Piriform2d | Internal::Strophoid2d => {
                let (u, v) = curve_plane(x, y, z, argument(7), argument(8), argument(9));
                with_strength(argument(3), algebraic(self, (u, v, 0.0), shape_parameters))
            }
            Internal::Bicorn
            | Internal::Bifolia
            | Internal::BoySurface
            | Internal::HuntSurface
            | Internal::CrossedTrough
            | Internal::CubicSaddle
            | Internal::Cushion
            | Internal::DevilsCurve
            | Internal::FoliumSurface
            | Internal::Glob
            | Internal::Heart
            | Internal::HyperbolicTorus
            | Internal::KampyleOfEudoxus
            | Internal::KleinBottle
            | Internal::KummerSurface1
            | Internal::KummerSurface2
            | Internal::LemniscateOfGerono
            | Internal::Mitre
            | Internal::NodalCubic
            | Internal::Odd
            | Internal::OvalsOfCassini
            | Internal::ParabolicTorus
            | Internal::Pillow
            | Internal::Piriform
            | Internal::QuarticParaboloid
            | Internal::QuarticSaddle
            | Internal::QuarticCylinder
            | Internal::SteinersRoman
            | Internal::Strophoid
            | Internal::TorusGumdrop
            | Internal::Umbrella
            | Internal::WitchOfAgnesi => {
                with_strength(argument(3), algebraic(self, (x, y, z), shape_parameters))
            }
            Internal::Blob => blob(
                (x, y, z),
                argument(3),
                [(argument(4), argument(5)), (argument(6), argument(7))],
            ),
            Internal::CrossEllipsoids | Internal::IsectEllipsoids | Internal::FlangeCover => {
                let exponents = axis_ellipsoids((x, y, z), argument(3), argument(4));
                let (scale, threshold) = (argument(5), argument(6));
                let field = match self {
                    Internal::CrossEllipsoids => {
                        (-exponents[0].min(exponents[1]).min(exponents[2])).exp()
                    }
                    Internal::IsectEllipsoids => {
                        (-exponents[0].max(exponents[1]).max(exponents[2])).exp()
                    }
                    _ => exponents.iter().map(|exponent| (-exponent).exp()).sum(),
                };
                threshold - scale * field
            }
            Internal::Comma => comma((x, y, z), argument(3)),
            Internal::DupinCyclid => {
                dupin_cyclid((x, y, z), std::array::from_fn(|i| argument(3 + i)))
            }
            Internal::Enneper => enneper((x, y, z), argument(3)),
            Internal::HelicalTorus => {
                helical_torus((x, y, z), std::array::from_fn(|i| argument(3 + i)))
            }
            Internal::HexagonalPrisms => hexagonal_prisms(x, y),
            Internal::HexagonalLines => hexagonal_lines(x, y),
            Internal::Quantum => quantum((x, y, z)),
            Internal::Spikes2d => {
                let (height, x_frequency, z_frequency, rate) =
                    (argument(3), argument(4), argument(5), argument(6));
                y - height
                    * (x_frequency * x).cos()
                    * (z_frequency * z).cos()
                    * (-rate * (x * x + z * z)).exp()
            }
            Internal::Mesh1 => mesh1((x, y, z), run(3)),
            Internal::Polytubes => polytubes((x, y, z), argument(3), run(4)),
            Internal::Spikes => spikes((x, y, z), run(3)),
            Internal::Spiral => spiral(
                (x, y, z),
                argument(3),
                argument(4),
                argument(5),
                argument(8),
            ),
            Internal::Blob2 => blob2(
                (x, y, z),
                argument(3),
                argument(4),
                argument(5),
                argument(6),
            ),
            Internal::Helix1 => helix1(
                (x, y, z),
                argument(3),
                argument(4),
                argument(5),
                argument(6),
                argument(7),
                argument(8),
                argument(9),
            ),
            Internal::Helix2 => helix2(
                (x, y, z),
                argument(4),
                argument(5),
                argument(6),
                argument(8),
            ),
            Internal::HeteroMultifractal | Internal::RidgedMultifractal => {
                let fractal = Multifractal {
                    dimension: argument(3),
                    lacunarity: argument(4),
                    octaves: argument(5),
                    offset: argument(6),
                    control: argument(7),
                    generator: argument(8),
                };
                if self == Internal::HeteroMultifractal {
                    hetero_multifractal(point, fractal)
                } else {
                    ridged_multifractal(point, fractal)
                }
            }
            Internal::Ridge => ridge(
                point,
                [
                    argument(3),
                    argument(4),
                    argument(5),
                    argument(6),
                    argument(7),
                    argument(8),
                ],
            ),
            Internal::Poly4 => {
                let coefficients = run(3);
                x.hypot(z) - quartic(y, coefficients)
            }
            Internal::Ellipsoid => {
                (point * DVec3::new(argument(3), argument(4), argument(5))).length()
            }
            Internal::Paraboloid => argument(3) * (y - x * x - z * z),
            Internal::Phi => (y / point.length()).acos(),
            Internal::Radius => point.length(),
            Internal::RoundedBox => {
                let radius = argument(3);
                let size = DVec3::new(argument(4), argument(5), argument(6));
                let outside = (point.abs() - size + radius).max(DVec3::ZERO);
                outside.length() - radius - ROUNDED_BOX_OFFSET
            }
            Internal::Sphere => point.length() - argument(3),
            Internal::Superellipsoid => {
                let (east_west, north_south) = (argument(3), argument(4));
                let horizontal = x.abs().powf(2.0 / east_west) + y.abs().powf(2.0 / east_west);
                let sum =
                    horizontal.powf(east_west / north_south) + z.abs().powf(2.0 / north_south);
                1.0 - sum.powf(north_south / 2.0)
            }
            Internal::Theta => x.atan2(z),
            Internal::Torus => {
                let ring = (x * x + z * z).sqrt() - argument(3);
                (ring * ring + y * y).sqrt() - argument(4)
            }
            Internal::Torus2 => {
                let (strength, major, minor) = (argument(3), argument(4), argument(5));
                let squared = point.length_squared() + major * major - minor * minor;
                -strength * (squared * squared - 4.0 * major * major * (x * x + z * z))
            }
            Internal::Noise3d => noise(point, NoiseGenerator::default()),
            Internal::NoiseGenerator => noise(point, generator_parameter(argument(3))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values povray 3.7 prints for the same calls.
    #[test]
    fn values_match_povray() {
        let cases: [(f64, &[f64], f64); 11] = [
            (61.0, &[0.3, 0.4, 0.5, 0.7], 0.007106781187),
            (70.0, &[0.3, 0.4, 0.5, 0.7, 0.2], 0.216733409654),
            (60.0, &[0.3, 0.4, 0.5, 0.1, 0.2, 0.3, 0.25], 0.349999),
            (60.0, &[1.3, -0.4, 0.5, 0.1, 0.5, 0.3, 0.25], 0.886153146166),
            (60.0, &[0.05, 0.02, 0.01, 0.1, 0.5, 0.3, 0.25], -0.100001),
            (68.0, &[0.3, 0.4, 0.5, 0.5, 0.7], 0.405067003168),
            (69.0, &[0.3, 0.4, 0.5], 0.540419500271),
            (47.0, &[0.3, 0.4, 0.5], 0.969532110116),
            (45.0, &[0.3, 0.7, 0.5, 2.0], 0.72),
            (17.0, &[0.3, 0.4, 0.5, 1.5, 2.0, 3.0], 1.758550539507),
            (71.0, &[0.3, 0.4, 0.5, 1.5, 0.7, 0.2], -0.35415),
        ];
        for (number, arguments, expected) in cases {
            let function = Internal::from_number(number).unwrap();
            assert_eq!(function.arity(), arguments.len());
            let value = function.eval(arguments);
            assert!(
                (value - expected).abs() < 1e-9,
                "internal({number}) gave {value}, povray {expected}"
            );
        }
    }

    #[test]
    fn unknown_numbers_are_refused() {
        assert!(Internal::from_number(100.0).is_none());
        assert!(Internal::from_number(61.5).is_none());
        assert!(Internal::from_number(77.0).is_none());
        assert!(Internal::from_number(-1.0).is_none());
        assert!(Internal::from_number(1e20).is_none());
    }

    #[test]
    fn numbers_round_trip() {
        for number in 0..=255u8 {
            if let Some(function) = Internal::from_number(f64::from(number)) {
                assert_eq!(function.number(), number);
            }
        }
    }

    /// Every line of internal_known_answers.txt, `N|x,y,z,P0,..|value`, is a call povray 3.7
    /// printed with `#debug`; durer must give the same value.
    #[test]
    fn known_answers_match_povray() {
        let table = include_str!("internal_known_answers.txt");
        let mut failures = Vec::new();
        let mut count = 0;
        for line in table
            .lines()
            .filter(|line| !line.is_empty() && !line.starts_with('#'))
        {
            let fields: Vec<&str> = line.split('|').collect();
            let number: f64 = fields[0].parse().unwrap();
            let arguments: Vec<f64> = fields[1].split(',').map(|a| a.parse().unwrap()).collect();
            let expected: f64 = fields[2].parse().unwrap();
            let function = Internal::from_number(number).unwrap();
            assert_eq!(function.arity(), arguments.len(), "{line}");
            let value = function.eval(&arguments);
            // durer's Perlin noise (generator 3) matches povray's to about 1e-8 (see
            // noise::tests); everything else to the printed digits.
            let generator_argument = match function {
                Internal::HeteroMultifractal | Internal::Ridge | Internal::RidgedMultifractal => 8,
                Internal::NoiseGenerator => 3,
                _ => usize::MAX,
            };
            let noisy = arguments.get(generator_argument).is_some_and(|&generator| {
                generator_parameter(generator) == crate::noise::NoiseGenerator::Perlin
            });
            let tolerance = if noisy { 1e-7 } else { 1e-9 };
            if (value - expected).abs() > tolerance * expected.abs().max(1.0) {
                failures.push(format!("{line}: durer {value}"));
            }
            count += 1;
        }
        assert!(count > 1000, "only {count} known answers");
        assert!(failures.is_empty(), "{}", failures.join("\n"));
    }
}
