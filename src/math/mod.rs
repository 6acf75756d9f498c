//! Leaf mathematics shared by every layer: colours, affine transformations and [`power`].
//!
//! In: nothing. Out: [`Colour`] (five channels: red, green, blue, filter, transmit) and
//! [`Transform`] (an affine map with its inverse). Holds: plain values; this module
//! imports nothing from the crate.

mod colour;
mod transform;

pub use colour::Colour;
pub use transform::Transform;

/// `base` raised to `exponent`, multiplied out for the exponents scenes use most (1 and 2:
/// `fade_power 2`, `tightness 1`) and `powf` otherwise. `powf` was 8% of a radiosity render
/// lit by spotlights (radiosity/cornell.pov, measured with perf).
#[inline]
pub fn power(base: f64, exponent: f64) -> f64 {
    if exponent == 1.0 {
        base
    } else if exponent == 2.0 {
        base * base
    } else {
        base.powf(exponent)
    }
}

#[cfg(test)]
mod tests {
    use super::power;

    #[test]
    fn power_agrees_with_powf() {
        for base in [0.0, 0.25, 0.5, 0.9, 1.0, 3.0, 1e-3, 123.456] {
            for exponent in [0.5, 1.0, 2.0, 3.0, 10.0] {
                let expected = f64::powf(base, exponent);
                let got = power(base, exponent);
                assert!(
                    (got - expected).abs() <= 1e-15 * expected.abs(),
                    "{base} {exponent}"
                );
            }
        }
    }
}
