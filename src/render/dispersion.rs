//! Dispersion: white light split into coloured bands, each refracted with its own index.
//!
//! In: the number of bands (`dispersion_samples`). Out: each band's exponent offset and
//! colour weight. Holds: band i of n has the index of refraction `ior · dispersion^(offset)`
//! with offsets spread evenly from −½ (red) to ½ (violet), since `dispersion` is the ratio of
//! the violet index to the red one; its colour is POV-Ray 3.7's simulated spectrum summed over
//! the band's share `[i/n, (i+1)/n]` of the spectrum.
//!
//! The spectrum was measured from POV-Ray 3.7: a 60-band dispersive slab refracting each band
//! onto a different spot of a half white, half black target, read from a 16-bit render (each
//! band that leaves the white half removes its colour). Its total is POV-Ray's slightly
//! tinted "white", `<0.9938, 1, 0.9962>`, not pure white.

use glam::DVec3;

/// The light of the spectrum from position `k/60` to its violet end (1), for k = 0..=60,
/// as measured from POV-Ray 3.7.
const SPECTRUM_REMAINING: [[f64; 3]; 61] = [
    [0.99380, 1.00000, 0.99620],
    [0.98164, 1.00000, 0.99620],
    [0.96374, 1.00000, 0.99620],
    [0.94066, 1.00000, 0.99620],
    [0.91278, 1.00000, 0.99620],
    [0.88055, 1.00000, 0.99620],
    [0.84451, 1.00000, 0.99620],
    [0.80470, 1.00000, 0.99620],
    [0.76207, 1.00000, 0.99620],
    [0.71705, 1.00000, 0.99620],
    [0.67004, 0.99873, 0.99620],
    [0.62158, 0.99294, 0.99620],
    [0.57220, 0.98170, 0.99620],
    [0.52215, 0.96477, 0.99620],
    [0.47218, 0.94318, 0.99620],
    [0.42260, 0.91736, 0.99620],
    [0.37397, 0.88754, 0.99620],
    [0.32679, 0.85428, 0.99620],
    [0.28141, 0.81781, 0.99620],
    [0.23868, 0.77821, 0.99620],
    [0.19879, 0.73637, 0.99620],
    [0.16229, 0.69250, 0.99620],
    [0.12953, 0.64710, 0.99620],
    [0.10094, 0.60043, 0.99620],
    [0.07710, 0.55300, 0.99620],
    [0.05913, 0.50504, 0.99620],
    [0.04686, 0.45704, 0.99620],
    [0.04076, 0.40940, 0.99620],
    [0.03951, 0.36251, 0.99600],
    [0.03951, 0.31670, 0.99248],
    [0.03951, 0.27240, 0.98399],
    [0.03951, 0.23021, 0.97050],
    [0.03951, 0.19034, 0.95270],
    [0.03951, 0.15309, 0.93104],
    [0.03951, 0.11893, 0.90579],
    [0.03951, 0.08817, 0.87720],
    [0.03951, 0.06120, 0.84559],
    [0.03951, 0.03902, 0.81100],
    [0.03951, 0.02144, 0.77406],
    [0.03951, 0.00880, 0.73510],
    [0.03951, 0.00150, 0.69439],
    [0.03951, 0.00000, 0.65226],
    [0.03951, 0.00000, 0.60900],
    [0.03951, 0.00000, 0.56483],
    [0.03951, 0.00000, 0.52020],
    [0.03951, 0.00000, 0.47539],
    [0.03951, 0.00000, 0.43079],
    [0.03951, 0.00000, 0.38660],
    [0.03951, 0.00000, 0.34321],
    [0.03951, 0.00000, 0.30092],
    [0.03917, 0.00000, 0.26014],
    [0.03751, 0.00000, 0.22104],
    [0.03450, 0.00000, 0.18404],
    [0.03050, 0.00000, 0.14928],
    [0.02580, 0.00000, 0.11720],
    [0.02065, 0.00000, 0.08843],
    [0.01547, 0.00000, 0.06293],
    [0.01054, 0.00000, 0.04105],
    [0.00610, 0.00000, 0.02310],
    [0.00249, 0.00000, 0.00932],
    [0.00000, 0.00000, 0.00000],
];

/// The light of the spectrum from position `t` (0 = red end, 1 = violet end) to its violet
/// end: the measured table, interpolated linearly.
fn remaining(t: f64) -> DVec3 {
    let last = SPECTRUM_REMAINING.len() - 1;
    let scaled = t.clamp(0.0, 1.0) * last as f64;
    let below = (scaled.floor() as usize).min(last - 1);
    let fraction = scaled - below as f64;
    let from = DVec3::from_array(SPECTRUM_REMAINING[below]);
    let to = DVec3::from_array(SPECTRUM_REMAINING[below + 1]);
    from.lerp(to, fraction)
}

/// The colour bands of a dispersive refraction.
pub struct Bands {
    count: u32,
}

impl Bands {
    /// The `count` bands.
    pub fn new(count: u32) -> Bands {
        Bands {
            count: count.max(1),
        }
    }

    /// The exponent offset and colour weight of band `index`.
    pub fn band(&self, index: u32) -> (f64, DVec3) {
        let count = f64::from(self.count);
        let start = f64::from(index) / count;
        let end = f64::from(index + 1) / count;
        let offset = (f64::from(index) + 0.5) / count - 0.5;
        (offset, remaining(start) - remaining(end))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_add_up_to_the_spectrum_and_run_red_to_violet() {
        let spectrum = DVec3::from_array(SPECTRUM_REMAINING[0]);
        for count in [2, 7, 20, 1000] {
            let bands = Bands::new(count);
            let total: DVec3 = (0..count).map(|index| bands.band(index).1).sum();
            assert!((total - spectrum).abs().max_element() < 1e-12, "{count}");
        }
        let (red_offset, red) = Bands::new(7).band(0);
        let (violet_offset, violet) = Bands::new(7).band(6);
        assert!(red_offset < 0.0 && violet_offset > 0.0);
        assert!(red.x > red.z && violet.z > violet.x);
    }

    #[test]
    fn two_bands_match_povray() {
        // Measured with dispersion_samples 2: the violet half of the spectrum.
        let (_, violet) = Bands::new(2).band(1);
        assert!(
            (violet - DVec3::new(0.0395, 0.2724, 0.984))
                .abs()
                .max_element()
                < 1e-3
        );
    }

    #[test]
    fn the_spectrum_never_increases_towards_violet() {
        for pair in SPECTRUM_REMAINING.windows(2) {
            assert!((0..3).all(|channel| pair[1][channel] <= pair[0][channel]));
        }
    }
}
