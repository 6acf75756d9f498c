//! The arithmetic of `julia_fractal`: complex functions with their derivatives, quaternion
//! products, and the duplex form of hypercomplex numbers.
//!
//! In: 4D points as [`DVec4`] (x real, then i, j, k) and complex numbers as [`DVec2`]
//! (re, im). Out: one map `h → f(h)` and its derivative, in either algebra. Holds: a
//! hypercomplex number x + yi + zj + wk is the pair a = (x + w) + (y − z)i, b = (x − w) +
//! (y + z)i of complex numbers, on which the algebra acts component by component, so a
//! complex function and its derivative apply to a and b separately; nothing allocates.

use crate::scene::JuliaFunction;
use glam::{DVec2, DVec4};

/// The complex product.
#[inline]
pub fn complex_mul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

/// The complex quotient (infinite or NaN for a zero divisor).
#[inline]
fn complex_div(a: DVec2, b: DVec2) -> DVec2 {
    let norm = b.length_squared();
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / norm
}

/// e^z.
fn complex_exp(z: DVec2) -> DVec2 {
    let (sin, cos) = z.y.sin_cos();
    z.x.exp() * DVec2::new(cos, sin)
}

/// The principal logarithm.
fn complex_ln(z: DVec2) -> DVec2 {
    DVec2::new(z.length().ln(), z.y.atan2(z.x))
}

/// The principal square root.
fn complex_sqrt(z: DVec2) -> DVec2 {
    let modulus = z.length();
    let re = (0.5 * (modulus + z.x)).max(0.0).sqrt();
    let im = (0.5 * (modulus - z.x)).max(0.0).sqrt();
    DVec2::new(re, if z.y < 0.0 { -im } else { im })
}

/// sin z.
fn complex_sin(z: DVec2) -> DVec2 {
    DVec2::new(z.x.sin() * z.y.cosh(), z.x.cos() * z.y.sinh())
}

/// cos z.
fn complex_cos(z: DVec2) -> DVec2 {
    DVec2::new(z.x.cos() * z.y.cosh(), -z.x.sin() * z.y.sinh())
}

/// sinh z.
fn complex_sinh(z: DVec2) -> DVec2 {
    DVec2::new(z.x.sinh() * z.y.cos(), z.x.cosh() * z.y.sin())
}

/// cosh z.
fn complex_cosh(z: DVec2) -> DVec2 {
    DVec2::new(z.x.cosh() * z.y.cos(), z.x.sinh() * z.y.sin())
}

/// Multiplies by i.
#[inline]
fn times_i(z: DVec2) -> DVec2 {
    DVec2::new(-z.y, z.x)
}

/// The complex number 1.
const ONE: DVec2 = DVec2::new(1.0, 0.0);

/// `function` at z and its derivative there.
pub fn complex_function(function: JuliaFunction, z: DVec2) -> (DVec2, DVec2) {
    let square = complex_mul(z, z);
    match function {
        JuliaFunction::Sqr => (square, 2.0 * z),
        JuliaFunction::Cube => (complex_mul(square, z), 3.0 * square),
        JuliaFunction::Exp => {
            let value = complex_exp(z);
            (value, value)
        }
        JuliaFunction::Reciprocal => (complex_div(ONE, z), -complex_div(ONE, square)),
        JuliaFunction::Sin => (complex_sin(z), complex_cos(z)),
        JuliaFunction::Cos => (complex_cos(z), -complex_sin(z)),
        JuliaFunction::Sinh => (complex_sinh(z), complex_cosh(z)),
        JuliaFunction::Cosh => (complex_cosh(z), complex_sinh(z)),
        JuliaFunction::Tan => {
            let cos = complex_cos(z);
            (
                complex_div(complex_sin(z), cos),
                complex_div(ONE, complex_mul(cos, cos)),
            )
        }
        JuliaFunction::Tanh => {
            let cosh = complex_cosh(z);
            (
                complex_div(complex_sinh(z), cosh),
                complex_div(ONE, complex_mul(cosh, cosh)),
            )
        }
        JuliaFunction::Asin => {
            // asin z = −i ln(iz + √(1 − z²)).
            let root = complex_sqrt(ONE - square);
            let value = -times_i(complex_ln(times_i(z) + root));
            (value, complex_div(ONE, root))
        }
        JuliaFunction::Acos => {
            // acos z = −i ln(z + i√(1 − z²)).
            let root = complex_sqrt(ONE - square);
            let value = -times_i(complex_ln(z + times_i(root)));
            (value, -complex_div(ONE, root))
        }
        JuliaFunction::Asinh => {
            // asinh z = ln(z + √(z² + 1)).
            let root = complex_sqrt(square + ONE);
            (complex_ln(z + root), complex_div(ONE, root))
        }
        JuliaFunction::Acosh => {
            // acosh z = ln(z + √(z + 1) √(z − 1)).
            let root = complex_mul(complex_sqrt(z + ONE), complex_sqrt(z - ONE));
            (complex_ln(z + root), complex_div(ONE, root))
        }
        JuliaFunction::Atan => {
            // atan z = (i / 2) ln((i + z) / (i − z)).
            let i = DVec2::Y;
            let value = 0.5 * times_i(complex_ln(complex_div(i + z, i - z)));
            (value, complex_div(ONE, ONE + square))
        }
        JuliaFunction::Atanh => {
            // atanh z = ln((1 + z) / (1 − z)) / 2.
            let value = 0.5 * complex_ln(complex_div(ONE + z, ONE - z));
            (value, complex_div(ONE, ONE - square))
        }
        JuliaFunction::Ln => (complex_ln(z), complex_div(ONE, z)),
        // 0^p is 0, as povray iterates it (measured with `inside`: the orbit of 0 stays).
        JuliaFunction::Power(_) if z == DVec2::ZERO => (DVec2::ZERO, DVec2::ZERO),
        JuliaFunction::Power(exponent) => {
            // z^p = e^(p ln z); its derivative is p z^p / z.
            let value = complex_exp(complex_mul(exponent, complex_ln(z)));
            (value, complex_div(complex_mul(exponent, value), z))
        }
    }
}

/// The quaternion product `a b`.
#[inline]
pub fn quaternion_mul(a: DVec4, b: DVec4) -> DVec4 {
    DVec4::new(
        a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w,
        a.x * b.y + a.y * b.x + a.z * b.w - a.w * b.z,
        a.x * b.z - a.y * b.w + a.z * b.x + a.w * b.y,
        a.x * b.w + a.y * b.z - a.z * b.y + a.w * b.x,
    )
}

/// The quaternion square, h h.
#[inline]
pub fn quaternion_square(h: DVec4) -> DVec4 {
    let vector = DVec4::new(0.0, h.y, h.z, h.w);
    let real = h.x * h.x - vector.length_squared();
    2.0 * h.x * vector + DVec4::new(real, 0.0, 0.0, 0.0)
}

/// A hypercomplex number as its duplex pair (a, b) of complex numbers.
#[inline]
pub fn to_duplex(h: DVec4) -> (DVec2, DVec2) {
    (
        DVec2::new(h.x + h.w, h.y - h.z),
        DVec2::new(h.x - h.w, h.y + h.z),
    )
}

/// The hypercomplex number of a duplex pair.
#[inline]
pub fn from_duplex(a: DVec2, b: DVec2) -> DVec4 {
    DVec4::new(
        0.5 * (a.x + b.x),
        0.5 * (a.y + b.y),
        0.5 * (b.y - a.y),
        0.5 * (a.x - b.x),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The hypercomplex product computed from the basis rules ij = ji = k, jk = kj = −i,
    /// ik = ki = −j, ii = jj = −1, kk = 1.
    fn hypercomplex_mul(p: DVec4, q: DVec4) -> DVec4 {
        DVec4::new(
            p.x * q.x - p.y * q.y - p.z * q.z + p.w * q.w,
            p.x * q.y + p.y * q.x - p.z * q.w - p.w * q.z,
            p.x * q.z + p.z * q.x - p.y * q.w - p.w * q.y,
            p.x * q.w + p.w * q.x + p.y * q.z + p.z * q.y,
        )
    }

    #[test]
    fn duplex_form_multiplies_like_the_basis_rules() {
        let p = DVec4::new(0.3, -1.2, 0.7, 2.1);
        let q = DVec4::new(-0.4, 0.5, 1.3, -0.9);
        let (pa, pb) = to_duplex(p);
        let (qa, qb) = to_duplex(q);
        let product = from_duplex(complex_mul(pa, qa), complex_mul(pb, qb));
        assert!(product.abs_diff_eq(hypercomplex_mul(p, q), 1e-12));
        let (a, b) = to_duplex(p);
        assert!(from_duplex(a, b).abs_diff_eq(p, 1e-15));
    }

    #[test]
    fn quaternion_rules_hold() {
        let (i, j, k) = (DVec4::Y, DVec4::Z, DVec4::W);
        assert_eq!(quaternion_mul(i, j), k);
        assert_eq!(quaternion_mul(j, k), i);
        assert_eq!(quaternion_mul(k, i), j);
        assert_eq!(quaternion_mul(j, i), -k);
        let h = DVec4::new(0.3, -1.2, 0.7, 2.1);
        assert!(quaternion_square(h).abs_diff_eq(quaternion_mul(h, h), 1e-12));
    }

    #[test]
    fn derivatives_match_difference_quotients() {
        let functions = [
            JuliaFunction::Sqr,
            JuliaFunction::Cube,
            JuliaFunction::Exp,
            JuliaFunction::Reciprocal,
            JuliaFunction::Sin,
            JuliaFunction::Asin,
            JuliaFunction::Sinh,
            JuliaFunction::Asinh,
            JuliaFunction::Cos,
            JuliaFunction::Acos,
            JuliaFunction::Cosh,
            JuliaFunction::Acosh,
            JuliaFunction::Tan,
            JuliaFunction::Atan,
            JuliaFunction::Tanh,
            JuliaFunction::Atanh,
            JuliaFunction::Ln,
            JuliaFunction::Power(DVec2::new(2.5, 0.5)),
        ];
        let z = DVec2::new(0.37, 0.61);
        let step = 1e-6;
        for function in functions {
            let (_, derivative) = complex_function(function, z);
            let ahead = complex_function(function, z + DVec2::new(step, 0.0)).0;
            let behind = complex_function(function, z - DVec2::new(step, 0.0)).0;
            let quotient = (ahead - behind) / (2.0 * step);
            assert!(
                derivative.abs_diff_eq(quotient, 1e-6),
                "{function:?}: {derivative} vs {quotient}"
            );
        }
        let (value, _) = complex_function(JuliaFunction::Asin, complex_sin(z));
        assert!(value.abs_diff_eq(z, 1e-12));
        let (value, _) = complex_function(JuliaFunction::Acos, complex_cos(z));
        assert!(value.abs_diff_eq(z, 1e-12));
        let (value, _) = complex_function(
            JuliaFunction::Atan,
            complex_div(complex_sin(z), complex_cos(z)),
        );
        assert!(value.abs_diff_eq(z, 1e-12));
    }
}
