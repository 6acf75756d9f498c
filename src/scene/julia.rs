//! Scene data of the `julia_fractal` shape: a 3D slice of a 4D Julia set.
//!
//! In: nothing (data definitions). Out: [`JuliaFractal`], [`JuliaAlgebra`], [`JuliaFunction`].
//! Holds: every value is final, with POV-Ray's defaults filled in; the parser has already
//! refused functions the algebra does not have and slices POV-Ray calls illegal.

use glam::{DVec2, DVec4};

/// `julia_fractal { <p> [algebra] [function] max_iteration n precision p slice <n>, d }`.
#[derive(Clone, Debug, PartialEq)]
pub struct JuliaFractal {
    /// The Julia parameter `p` of the iteration `h → f(h) + p` (x real, then i, j, k).
    pub parameter: DVec4,
    /// `quaternion` (default) or `hypercomplex`.
    pub algebra: JuliaAlgebra,
    /// The iterated function `f` (default `sqr`).
    pub function: JuliaFunction,
    /// Iterations before a point that has not escaped counts as inside (default 20).
    pub max_iteration: u32,
    /// The reciprocal of the smallest ray step (default 20; values below 1 act as 1).
    pub precision: f64,
    /// Normal of the 4D hyperplane the fractal is cut with (default `<0, 0, 0, 1>`); its
    /// fourth component is never zero.
    pub slice_normal: DVec4,
    /// Distance of the slicing hyperplane from the origin (default 0).
    pub slice_distance: f64,
}

/// The 4D algebra the iteration runs in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JuliaAlgebra {
    /// Quaternions: ij = k, jk = i, ki = j, anticommuting; only `sqr` and `cube`.
    Quaternion,
    /// Hypercomplex (bicomplex) numbers: commutative, ij = k, kk = 1; every function.
    Hypercomplex,
}

/// The function `f` of the iteration `h → f(h) + p`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JuliaFunction {
    /// h².
    Sqr,
    /// h³.
    Cube,
    /// e^h.
    Exp,
    /// 1 / h.
    Reciprocal,
    /// sin h.
    Sin,
    /// asin h.
    Asin,
    /// sinh h.
    Sinh,
    /// asinh h.
    Asinh,
    /// cos h.
    Cos,
    /// acos h.
    Acos,
    /// cosh h.
    Cosh,
    /// acosh h.
    Acosh,
    /// tan h.
    Tan,
    /// atan h.
    Atan,
    /// tanh h.
    Tanh,
    /// atanh h.
    Atanh,
    /// ln h.
    Ln,
    /// `pwr(x, y)`: h raised to the complex power x + yi.
    Power(DVec2),
}

impl Default for JuliaFractal {
    fn default() -> Self {
        JuliaFractal {
            parameter: DVec4::ZERO,
            algebra: JuliaAlgebra::Quaternion,
            function: JuliaFunction::Sqr,
            max_iteration: 20,
            precision: 20.0,
            slice_normal: DVec4::W,
            slice_distance: 0.0,
        }
    }
}
