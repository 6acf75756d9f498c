//! Dispersion: white light split into coloured bands, each refracted with its own index.
//!
//! In: the number of bands (`dispersion_samples`). Out: each band's exponent offset and
//! colour weight. Holds: the weights of all bands add up to white, so a dispersive object
//! without bending looks like a plain one; band i of n has the index of refraction
//! `ior · dispersion^(offset)` with offsets spread evenly from −½ (red) to ½ (violet), since
//! `dispersion` is the ratio of the violet index to the red one.
//!
//! POV-Ray 3.7 samples a spectrum; durer approximates its colours by a hue ramp from red to
//! violet, so coloured fringes match in place but not exactly in tint.

use glam::DVec3;

/// Hue in degrees of the violet end of the spectrum (red is 0).
const VIOLET_HUE: f64 = 270.0;

/// The exponent offset and unnormalised colour of band `index` of `count`.
fn raw_band(index: u32, count: u32) -> (f64, DVec3) {
    let t = (f64::from(index) + 0.5) / f64::from(count.max(1));
    (t - 0.5, hue_colour(t * VIOLET_HUE))
}

/// The colour bands of a dispersive refraction: their weights are normalised once, so that
/// all `count` bands together give white.
pub struct Bands {
    count: u32,
    total: DVec3,
}

impl Bands {
    /// The `count` bands.
    pub fn new(count: u32) -> Bands {
        let total = (0..count).map(|index| raw_band(index, count).1).sum();
        Bands { count, total }
    }

    /// The exponent offset and colour weight of band `index`.
    pub fn band(&self, index: u32) -> (f64, DVec3) {
        let (offset, colour) = raw_band(index, self.count);
        let weight = DVec3::new(
            safe_ratio(colour.x, self.total.x),
            safe_ratio(colour.y, self.total.y),
            safe_ratio(colour.z, self.total.z),
        );
        (offset, weight)
    }
}

fn safe_ratio(part: f64, total: f64) -> f64 {
    if total > 0.0 {
        part / total
    } else {
        0.0
    }
}

/// A fully saturated colour of the given hue (degrees).
fn hue_colour(hue: f64) -> DVec3 {
    let sector = (hue / 60.0).rem_euclid(6.0);
    let x = 1.0 - ((sector % 2.0) - 1.0).abs();
    match sector as u32 {
        0 => DVec3::new(1.0, x, 0.0),
        1 => DVec3::new(x, 1.0, 0.0),
        2 => DVec3::new(0.0, 1.0, x),
        3 => DVec3::new(0.0, x, 1.0),
        4 => DVec3::new(x, 0.0, 1.0),
        _ => DVec3::new(1.0, 0.0, x),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_add_up_to_white_and_run_red_to_violet() {
        for count in [2, 7, 20] {
            let mut total = DVec3::ZERO;
            for index in 0..count {
                total += Bands::new(count).band(index).1;
            }
            assert!((total - DVec3::ONE).abs().max_element() < 1e-12, "{count}");
        }
        let (red_offset, red) = Bands::new(7).band(0);
        let (violet_offset, violet) = Bands::new(7).band(6);
        assert!(red_offset < 0.0 && violet_offset > 0.0);
        assert!(red.x > red.z && violet.z > violet.x);
    }
}
