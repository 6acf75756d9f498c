//! The fractal patterns: `mandel`, `julia` and `magnet`, with their interior and exterior
//! colouring types.
//!
//! In: a pattern-space point (only x and y are used: the complex number x + iy). Out: the
//! raw value. Holds: at most `iterations` steps per call, no allocation.
//!
//! Measured against POV-Ray 3.7: the orbit starts at z = c (Mandelbrot) or z = the point
//! (Julia); each step computes the next z first and then tests the bailout |z|² > 4, so a
//! point escaping on the first step gives exterior value 0. Magnet orbits start at 0 (mandel
//! form) and escape when |z|² > 10⁴ or when they converge, |z − 1|² < 10⁻⁴; the exterior
//! colourings see the last z.

use glam::DVec2;

/// Squared orbit radius past which a Mandelbrot or Julia point has escaped.
const BAILOUT_SQUARED: f64 = 4.0;

/// Squared orbit radius past which a magnet point has escaped.
const MAGNET_BAILOUT_SQUARED: f64 = 10_000.0;

/// A magnet orbit closer than this (squared) to 1, the maps' fixed point, counts as
/// escaped too.
const MAGNET_CONVERGED_SQUARED: f64 = 1e-4;

/// Which fractal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FractalKind {
    /// `mandel`: z → z^exponent + point.
    Mandelbrot,
    /// `julia c`: z → z^exponent + c, starting at the point.
    Julia(DVec2),
    /// `magnet 1|2 mandel`: the magnet map with the point as parameter.
    MagnetMandelbrot(MagnetType),
    /// `magnet 1|2 julia c`: the magnet map with parameter c, starting at the point.
    MagnetJulia(MagnetType, DVec2),
}

/// The two magnet formulas.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MagnetType {
    /// z → ((z² + c − 1) / (2z + c − 2))².
    One,
    /// z → ((z³ + 3(c−1)z + (c−1)(c−2)) / (3z² + 3(c−2)z + (c−1)(c−2) + 1))².
    Two,
}

/// How points inside or outside the set are coloured (`interior` / `exterior` TYPE,
/// FACTOR).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Colouring {
    /// Type number 0 to 8 (see the manual; 7 and 8 only for the exterior).
    pub kind: u32,
    /// Multiplier (or modulus for exterior types 7 and 8).
    pub factor: f64,
}

/// A fractal pattern with its settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal {
    /// Which fractal.
    pub kind: FractalKind,
    /// Maximum number of iterations (at least 1).
    pub iterations: u32,
    /// Exponent of the Mandelbrot and Julia maps (2 to 33, default 2).
    pub exponent: u32,
    /// Interior colouring (default type 0, factor 1).
    pub interior: Colouring,
    /// Exterior colouring (default type 1, factor 1).
    pub exterior: Colouring,
}

impl Fractal {
    /// A fractal with POV-Ray's default exponent and colourings.
    pub fn new(kind: FractalKind, iterations: u32) -> Fractal {
        Fractal {
            kind,
            iterations: iterations.max(1),
            exponent: 2,
            interior: Colouring {
                kind: 0,
                factor: 1.0,
            },
            exterior: Colouring {
                kind: 1,
                factor: 1.0,
            },
        }
    }

    /// The pattern's raw value at the complex number `(x, y)`.
    pub fn value(&self, x: f64, y: f64) -> f64 {
        let point = DVec2::new(x, y);
        let (mut z, parameter) = match self.kind {
            FractalKind::Mandelbrot => (point, point),
            FractalKind::Julia(c) => (point, c),
            FractalKind::MagnetMandelbrot(_) => (DVec2::ZERO, point),
            FractalKind::MagnetJulia(_, c) => (point, c),
        };
        let mut smallest = f64::INFINITY;
        for step in 0..self.iterations {
            let escaped = match self.kind {
                FractalKind::Mandelbrot | FractalKind::Julia(_) => {
                    z = power(z, self.exponent) + parameter;
                    z.length_squared() > BAILOUT_SQUARED
                }
                FractalKind::MagnetMandelbrot(kind) | FractalKind::MagnetJulia(kind, _) => {
                    z = magnet_step(z, parameter, kind);
                    z.length_squared() > MAGNET_BAILOUT_SQUARED
                        || (z - DVec2::X).length_squared() < MAGNET_CONVERGED_SQUARED
                }
            };
            let size = z.length_squared();
            if !size.is_finite() || escaped {
                return exterior_value(self.exterior, step, self.iterations, z);
            }
            smallest = smallest.min(size.sqrt());
        }
        interior_value(self.interior, smallest, z)
    }
}

/// The value of an escaped point, `step` being the iteration it escaped on.
fn exterior_value(colouring: Colouring, step: u32, iterations: u32, z: DVec2) -> f64 {
    let factor = colouring.factor;
    let steps = step as f64;
    match colouring.kind {
        1 => steps / iterations as f64,
        7 if factor > 0.0 => (steps % factor) / factor,
        8 if factor > 0.0 => (steps % (factor + 1.0)) / factor,
        kind => orbit_value(kind, z, z.length()) * factor,
    }
}

/// The value of a point that never escaped.
fn interior_value(colouring: Colouring, smallest: f64, z: DVec2) -> f64 {
    let value = match colouring.kind {
        1 => smallest,
        kind => orbit_value(kind, z, z.length()),
    };
    value * colouring.factor
}

/// The colouring types shared by interior and exterior (0 and 2 to 6).
fn orbit_value(kind: u32, z: DVec2, size: f64) -> f64 {
    match kind {
        2 => z.x,
        3 => z.y,
        4 => z.x * z.x,
        5 => z.y * z.y,
        6 => size,
        _ => 1.0,
    }
}

/// Complex multiplication.
fn multiply(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

/// Complex division; a zero divisor gives infinity (which escapes).
fn divide(a: DVec2, b: DVec2) -> DVec2 {
    let denominator = b.length_squared();
    if denominator == 0.0 {
        return DVec2::splat(f64::INFINITY);
    }
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / denominator
}

/// `z` raised to a positive integer power by repeated squaring.
fn power(z: DVec2, exponent: u32) -> DVec2 {
    let mut result = DVec2::new(1.0, 0.0);
    let mut base = z;
    let mut remaining = exponent;
    while remaining > 0 {
        if remaining & 1 == 1 {
            result = multiply(result, base);
        }
        base = multiply(base, base);
        remaining >>= 1;
    }
    result
}

/// One step of a magnet map.
fn magnet_step(z: DVec2, c: DVec2, kind: MagnetType) -> DVec2 {
    let one = DVec2::new(1.0, 0.0);
    let quotient = match kind {
        MagnetType::One => divide(multiply(z, z) + c - one, 2.0 * z + c - 2.0 * one),
        MagnetType::Two => {
            let c1 = c - one;
            let c2 = c - 2.0 * one;
            let c1c2 = multiply(c1, c2);
            let z2 = multiply(z, z);
            let numerator = multiply(z2, z) + 3.0 * multiply(c1, z) + c1c2;
            let denominator = 3.0 * z2 + 3.0 * multiply(c2, z) + c1c2 + one;
            divide(numerator, denominator)
        }
    };
    multiply(quotient, quotient)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mandel_matches_povray() {
        // `mandel 20` as POV-Ray prints it at (x, y) of the probe points.
        let mandel = Fractal::new(FractalKind::Mandelbrot, 20);
        assert_eq!(mandel.value(-1.3, 0.4), 0.25);
        assert_eq!(mandel.value(-0.53, 0.09), 1.0);
        assert_eq!(mandel.value(0.24, -0.22), 1.0);
        assert_eq!(mandel.value(1.01, -0.53), 0.0);
    }

    #[test]
    fn magnet_escapes_and_converges_like_povray() {
        // POV-Ray's `magnet 1 mandel 30` (iterations / 30) and `magnet 2 mandel 30`.
        let one = Fractal::new(FractalKind::MagnetMandelbrot(MagnetType::One), 30);
        assert!((one.value(-1.7, 1.1) - 3.0 / 30.0).abs() < 1e-12);
        assert!((one.value(-0.94, 0.82) - 4.0 / 30.0).abs() < 1e-12);
        let two = Fractal::new(FractalKind::MagnetMandelbrot(MagnetType::Two), 30);
        assert!((two.value(-0.94, 0.82) - 2.0 / 30.0).abs() < 1e-12);
    }

    #[test]
    fn powers_and_magnets_stay_finite() {
        let z = DVec2::new(0.3, -0.7);
        let cubed = multiply(multiply(z, z), z);
        assert!((power(z, 3) - cubed).length() < 1e-12);
        let magnet = Fractal::new(FractalKind::MagnetMandelbrot(MagnetType::Two), 50);
        let value = magnet.value(1.0, 0.0);
        assert!(value.is_finite());
    }
}
