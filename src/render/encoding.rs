//! From a traced (linear) colour to the 8-bit value POV-Ray 3.7 writes in its PNG.
//!
//! In: the scene's [`GlobalSettings`] and traced colour channels. Out: bytes. Holds: every
//! input, including NaN and infinities, maps to a byte without panicking.
//!
//! The rule, measured on ramps of 1024 grey levels (all 1024 matched exactly):
//! - traced values are never decoded on input; scene colours, lights and finishes are used
//!   as written. Only the final pixel value `v` is converted.
//! - with `assumed_gamma G`: `byte = round(255 * srgb(clip(v)^G))`, where `srgb` is the exact
//!   sRGB transfer curve (linear below 0.0031308, else `1.055 x^(1/2.4) - 0.055`). So with
//!   `G = 1`, 0.5 is written as 188; with `G = 2.2`, 0.5 is written as 128.
//! - without `assumed_gamma`: when the `#version` in force at the end of parsing is at least
//!   3.7 the scene behaves as `assumed_gamma 1`; otherwise (no `#version` at all, or an older
//!   one) the value is written unchanged: `byte = round(255 * clip(v))` (0.5 → 128).
//! - `clip` clamps to [0, 1]; rounding is to nearest (`floor(255 v + 0.5)`).

use crate::scene::GlobalSettings;

/// How traced values are turned into the bytes of the output file.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OutputEncoding {
    /// Legacy scenes: the clipped value is written as is.
    Unchanged,
    /// The clipped value is raised to the given working gamma, then sRGB-encoded.
    Srgb {
        /// The scene's `assumed_gamma` (1 for linear scene colours).
        assumed_gamma: f64,
    },
}

impl OutputEncoding {
    /// The encoding POV-Ray 3.7 uses for a scene with these settings.
    pub fn for_settings(settings: &GlobalSettings) -> OutputEncoding {
        match settings.assumed_gamma {
            Some(gamma) if gamma.is_finite() && gamma > 0.0 => OutputEncoding::Srgb {
                assumed_gamma: gamma,
            },
            Some(_) => OutputEncoding::Srgb { assumed_gamma: 1.0 },
            None if is_legacy_scene(settings) => OutputEncoding::Unchanged,
            None => OutputEncoding::Srgb { assumed_gamma: 1.0 },
        }
    }

    /// The output byte for one traced colour channel.
    pub fn encode(&self, value: f64) -> u8 {
        self.encode_to(value, 255.0) as u8
    }

    /// One traced colour channel as an integer sample from 0 to `max` (255 for 8-bit files,
    /// 65535 for 16-bit ones): the same curve at another depth.
    pub fn encode_to(&self, value: f64, max: f64) -> u32 {
        let clipped = if value.is_nan() {
            0.0
        } else {
            value.clamp(0.0, 1.0)
        };
        let encoded = match *self {
            OutputEncoding::Unchanged => clipped,
            OutputEncoding::Srgb { assumed_gamma } => {
                let linear = if assumed_gamma == 1.0 {
                    clipped
                } else {
                    clipped.powf(assumed_gamma)
                };
                srgb_from_linear(linear)
            }
        };
        (encoded * max + 0.5).floor().clamp(0.0, max) as u32
    }

    /// One traced colour channel as linear light, not clamped, for floating-point files
    /// (measured from `povray`'s Radiance output: `assumed_gamma 1` writes the value, 2.2
    /// writes its 2.2nd power, a legacy scene the sRGB-decoded value). Negative and NaN
    /// values are 0.
    pub fn to_linear(&self, value: f64) -> f64 {
        if value.is_nan() || value <= 0.0 {
            return 0.0;
        }
        match *self {
            OutputEncoding::Unchanged => srgb_to_linear(value),
            OutputEncoding::Srgb { assumed_gamma } => value.powf(assumed_gamma),
        }
    }
}

/// The inverse sRGB transfer function (extended beyond 1 by the same power curve).
fn srgb_to_linear(encoded: f64) -> f64 {
    if encoded <= 0.04045 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// Whether POV-Ray treats the scene as written for a version before 3.7: no `#version` at
/// all, or a `#version` below 3.7 in force at the end of parsing. Such scenes keep legacy
/// gamma handling (when they give no `assumed_gamma`) and legacy transparency weighting.
pub fn is_legacy_scene(settings: &GlobalSettings) -> bool {
    !settings.version_declared || settings.language_version < 3.7 - 1e-9
}

/// The sRGB transfer function for a linear value in [0, 1].
fn srgb_from_linear(linear: f64) -> f64 {
    if linear <= 0.0031308 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings(gamma: Option<f64>, version: f64, declared: bool) -> GlobalSettings {
        GlobalSettings {
            assumed_gamma: gamma,
            language_version: version,
            version_declared: declared,
            ..GlobalSettings::default()
        }
    }

    #[test]
    fn choice_of_encoding_follows_povray() {
        let srgb1 = OutputEncoding::Srgb { assumed_gamma: 1.0 };
        assert_eq!(
            OutputEncoding::for_settings(&settings(None, 3.7, false)),
            OutputEncoding::Unchanged
        );
        assert_eq!(
            OutputEncoding::for_settings(&settings(None, 3.7, true)),
            srgb1
        );
        assert_eq!(
            OutputEncoding::for_settings(&settings(None, 3.6, true)),
            OutputEncoding::Unchanged
        );
        assert_eq!(
            OutputEncoding::for_settings(&settings(Some(1.0), 3.6, true)),
            srgb1
        );
        assert_eq!(
            OutputEncoding::for_settings(&settings(Some(2.2), 3.7, true)),
            OutputEncoding::Srgb { assumed_gamma: 2.2 }
        );
    }

    #[test]
    fn measured_values() {
        let srgb1 = OutputEncoding::Srgb { assumed_gamma: 1.0 };
        let srgb22 = OutputEncoding::Srgb { assumed_gamma: 2.2 };
        // Values read from POV-Ray 3.7 renders of an ambient-only surface.
        assert_eq!(srgb1.encode(0.5), 188);
        assert_eq!(srgb22.encode(0.5), 128);
        assert_eq!(OutputEncoding::Unchanged.encode(0.5), 128);
        // First entries of the measured 1024-level ramp ((k + 0.5) / 1024).
        assert_eq!(srgb1.encode(0.5 / 1024.0), 2);
        assert_eq!(srgb1.encode(16.5 / 1024.0), 34);
        assert_eq!(srgb1.encode(32.5 / 1024.0), 50);
        for encoding in [srgb1, srgb22, OutputEncoding::Unchanged] {
            assert_eq!(encoding.encode(2.0), 255);
            assert_eq!(encoding.encode(-1.0), 0);
            assert_eq!(encoding.encode(f64::NAN), 0);
            assert_eq!(encoding.encode(f64::INFINITY), 255);
            assert_eq!(encoding.encode_to(1.0, 65535.0), 65535);
        }
        // povray's Radiance file: 0.5 and 2.0 under gamma 1, 2.2 and a legacy scene.
        assert_eq!(srgb1.to_linear(2.0), 2.0);
        assert!((srgb22.to_linear(2.0) - 4.5948).abs() < 1e-3);
        assert!((OutputEncoding::Unchanged.to_linear(2.0) - 4.9538).abs() < 1e-3);
        assert_eq!(srgb1.to_linear(f64::NAN), 0.0);
    }
}
