//! Wave shapes, frequency and phase: how a pattern's raw value is reshaped before the map
//! lookup.
//!
//! In: a raw pattern value. Out: the value in [0, 1] that a colour map sees. Holds: pure;
//! non-finite results become 0.
//!
//! Measured against POV-Ray 3.7: the raw value becomes `fmod(v * frequency + phase,
//! 1.00001)` (plus 1 when negative; a frequency of 0 leaves it alone), then the shape:
//! ramp keeps it, triangle folds `2v` back from 1, sine is `(1 + sin 2πv) / 2`, scallop is
//! `|sin πv|`, cubic is `3v² − 2v³` and poly is `v^exponent`.

use std::f64::consts::PI;

/// The modulus of POV-Ray's value wrap, slightly above 1 so that 1 itself survives.
const WRAP_PERIOD: f64 = 1.00001;

/// A wave shape (`ramp_wave`, `triangle_wave`, ...).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WaveShape {
    /// The value unchanged (the default for most patterns).
    Ramp,
    /// Up from 0 to 1 and back down (marble, wood, spiral1, spiral2 by default).
    Triangle,
    /// A smooth sine from 0.5 up to 1, down to 0 and back.
    Sine,
    /// The absolute value of a half sine: arches.
    Scallop,
    /// `3v² − 2v³`: zero slope at both ends.
    Cubic,
    /// `v^exponent` (`poly_wave [exponent]`, default exponent 1).
    Poly(f64),
}

/// The wave settings of one pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wave {
    /// The shape applied last.
    pub shape: WaveShape,
    /// How many times the map repeats per unit of raw value (default 1; 0 disables the wrap).
    pub frequency: f64,
    /// Shift of the map (default 0).
    pub phase: f64,
}

impl Wave {
    /// A wave of the given shape with frequency 1 and phase 0.
    pub fn new(shape: WaveShape) -> Wave {
        Wave {
            shape,
            frequency: 1.0,
            phase: 0.0,
        }
    }

    /// The value a map sees for the raw pattern value `raw`.
    pub fn apply(&self, raw: f64) -> f64 {
        let mut value = raw;
        if self.frequency != 0.0 {
            value = (value * self.frequency + self.phase) % WRAP_PERIOD;
        }
        if value < 0.0 {
            value -= value.floor();
        }
        let shaped = match self.shape {
            WaveShape::Ramp => value,
            WaveShape::Triangle => {
                let doubled = 2.0 * value;
                if doubled > 1.0 {
                    2.0 - doubled
                } else {
                    doubled
                }
            }
            WaveShape::Sine => (1.0 + (2.0 * PI * value).sin()) * 0.5,
            WaveShape::Scallop => (PI * value).sin().abs(),
            WaveShape::Cubic => value * value * (3.0 - 2.0 * value),
            WaveShape::Poly(exponent) => value.powf(exponent),
        };
        if shaped.is_finite() {
            shaped
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-5
    }

    #[test]
    fn sine_wave_with_frequency_and_phase_matches_povray() {
        // Values printed by POV-Ray for `gradient x frequency 2 phase 0.1 sine_wave`.
        let wave = Wave {
            shape: WaveShape::Sine,
            frequency: 2.0,
            phase: 0.1,
        };
        assert!(close(wave.apply(0.05), 0.975528));
        assert!(close(wave.apply(0.5), 0.793867));
        assert!(close(wave.apply(0.95), 0.499969));
    }

    #[test]
    fn triangle_folds_and_negative_values_wrap() {
        let wave = Wave::new(WaveShape::Triangle);
        assert!(close(wave.apply(-1.3), 0.59998));
        assert!(close(wave.apply(0.25), 0.5));
        let ramp = Wave::new(WaveShape::Ramp);
        assert!(close(ramp.apply(-0.3), 0.7));
        assert_eq!(ramp.apply(1.0), 1.0);
        assert_eq!(ramp.apply(f64::NAN), 0.0);
    }

    #[test]
    fn shapes_at_known_points() {
        assert!(close(Wave::new(WaveShape::Scallop).apply(0.5), 1.0));
        assert!(close(Wave::new(WaveShape::Cubic).apply(0.5), 0.5));
        assert!(close(Wave::new(WaveShape::Cubic).apply(0.25), 0.15625));
        assert!(close(Wave::new(WaveShape::Poly(2.0)).apply(0.5), 0.25));
    }
}
