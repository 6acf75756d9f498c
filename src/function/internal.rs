//! POV-Ray's built-in functions of functions.inc (`function { internal(N) }`), those durer
//! implements.
//!
//! In: the number N and the call's arguments `x, y, z, P0, P1, ..`. Out: the function's
//! value, each formula checked against values povray 3.7 prints with `#debug`.
//! Holds: pure functions; numbers durer does not implement are refused when compiled.

use crate::noise::{noise, NoiseGenerator};
use glam::DVec3;

/// One implemented internal function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Internal {
    /// 17, `f_ellipsoid(x,y,z, sx, sy, sz)`: |(sx x, sy y, sz z)|.
    Ellipsoid,
    /// 45, `f_paraboloid(x,y,z, strength)`: strength (y - x² - z²).
    Paraboloid,
    /// 47, `f_ph(x,y,z)`: the angle from the +y axis.
    Phi,
    /// 57, `f_r(x,y,z)`: the distance from the origin.
    Radius,
    /// 60, `f_rounded_box(x,y,z, radius, sx, sy, sz)`.
    RoundedBox,
    /// 61, `f_sphere(x,y,z, radius)`.
    Sphere,
    /// 68, `f_superellipsoid(x,y,z, e, n)`: 1 minus the superellipsoid's radius.
    Superellipsoid,
    /// 69, `f_th(x,y,z)`: the angle around the y axis, `atan2(x, z)`.
    Theta,
    /// 70, `f_torus(x,y,z, major, minor)`.
    Torus,
    /// 71, `f_torus2(x,y,z, strength, major, minor)`: the quartic torus field.
    Torus2,
    /// 76, `f_noise3d(x,y,z)`: solid noise in [0, 1] with the default generator.
    Noise3d,
    /// 78, `f_noise_generator(x,y,z, generator)`.
    NoiseGenerator,
}

/// The offset POV-Ray subtracts from `f_rounded_box`'s distance (measured).
const ROUNDED_BOX_OFFSET: f64 = 1e-6;

impl Internal {
    /// The internal function with POV-Ray's number, when durer implements it.
    pub fn from_number(number: f64) -> Option<Internal> {
        if number.fract() != 0.0 {
            return None;
        }
        Some(match number as i64 {
            17 => Internal::Ellipsoid,
            45 => Internal::Paraboloid,
            47 => Internal::Phi,
            57 => Internal::Radius,
            60 => Internal::RoundedBox,
            61 => Internal::Sphere,
            68 => Internal::Superellipsoid,
            69 => Internal::Theta,
            70 => Internal::Torus,
            71 => Internal::Torus2,
            76 => Internal::Noise3d,
            78 => Internal::NoiseGenerator,
            _ => return None,
        })
    }

    /// Number of arguments, `x, y, z` included.
    pub fn arity(self) -> usize {
        match self {
            Internal::Phi | Internal::Radius | Internal::Theta | Internal::Noise3d => 3,
            Internal::Paraboloid | Internal::Sphere | Internal::NoiseGenerator => 4,
            Internal::Superellipsoid | Internal::Torus => 5,
            Internal::Ellipsoid | Internal::Torus2 => 6,
            Internal::RoundedBox => 7,
        }
    }

    /// The value for the arguments `x, y, z, P0, ..` (missing ones read as 0).
    pub fn eval(self, arguments: &[f64]) -> f64 {
        let argument = |index: usize| arguments.get(index).copied().unwrap_or(0.0);
        let (x, y, z) = (argument(0), argument(1), argument(2));
        let point = DVec3::new(x, y, z);
        match self {
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
            Internal::NoiseGenerator => {
                let generator = NoiseGenerator::from_number(argument(3) as i64).unwrap_or_default();
                noise(point, generator)
            }
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
        assert!(Internal::from_number(25.0).is_none());
        assert!(Internal::from_number(61.5).is_none());
    }
}
