//! Iridescence (`finish { irid { amount thickness T } }`): thin-film interference tinting
//! the light a surface receives.
//!
//! In: the finish's [`Irid`], the surface point, the cosines of the light and of the
//! viewer with the surface normal. Out: the factor each light's colour is multiplied by, for diffuse light and
//! highlights alike (ambient is untouched). Holds: no allocation.
//!
//! Rule measured in POV-Ray 3.7 (16-bit linear renders of a lit plane, lights and viewer at
//! 0, 30 and 60 degrees, thicknesses 0.02 to 1, amounts 0.5 and 1): channel c gets
//! `1 + amount · cos(2π · thickness · (cos_light + cos_view) / λ_c)` with wavelengths
//! λ = `irid_wavelength` as written, or (0.70, 0.52, 0.48) without one (measured). Swapping the light and the
//! viewer gives the same colour. `turbulence` u varies the thickness to
//! `thickness · (1 + u · (2 · turbulence(point) − 1))`, with POV-Ray's scalar noise
//! turbulence of 5 octaves (omega 0.5, lambda 2) at the world point (measured by inverting
//! the interference colour of a lit plane; textures/pigments/irid.pov then matches exactly).

use crate::noise::{turbulence, TurbulenceShape};
use crate::texture::finish::Irid;
use glam::DVec3;
use std::f64::consts::TAU;

/// The film thickness of `irid` at world `point`: its `thickness`, varied by `turbulence`
/// around it (turbulence 0.5 is the middle).
/// It depends only on the point, so shading computes it once per surface sample.
pub fn irid_thickness(irid: &Irid, point: DVec3) -> f64 {
    if irid.turbulence != 0.0 {
        let shape = TurbulenceShape {
            octaves: 5,
            ..TurbulenceShape::default()
        };
        let stir = turbulence(point, &shape, irid.noise_generator.get());
        irid.thickness * (1.0 + irid.turbulence * (2.0 * stir - 1.0))
    } else {
        irid.thickness
    }
}

/// The factor on a light's colour for `irid` with film `thickness` (see [`irid_thickness`]),
/// with `cos_light` and `cos_view` the (non-negative) cosines between the surface normal and
/// the directions to the light and to the viewer.
pub fn iridescence(irid: &Irid, thickness: f64, cos_light: f64, cos_view: f64) -> DVec3 {
    let path = TAU * thickness * (cos_light + cos_view);
    let phase = DVec3::splat(path) / irid.wavelengths.get();
    let factor = DVec3::ONE + irid.amount * DVec3::new(phase.x.cos(), phase.y.cos(), phase.z.cos());
    if factor.is_finite() {
        factor
    } else {
        DVec3::ONE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn irid(amount: f64, thickness: f64) -> Irid {
        Irid {
            amount,
            thickness,
            turbulence: 0.0,
            wavelengths: Default::default(),
            noise_generator: Default::default(),
        }
    }

    /// POV-Ray 3.7's colours (over plain diffuse) for light and viewer along the normal,
    /// and for a light at 60 degrees seen from 30 degrees.
    #[test]
    fn matches_povray_measurements() {
        let close = |a: DVec3, b: DVec3| (a - b).abs().max_element() < 1e-4;
        let head_on = iridescence(&irid(1.0, 0.5), 0.5, 1.0, 1.0);
        assert!(
            close(head_on, DVec3::new(0.09903, 1.88546, 1.86603)),
            "{head_on}"
        );
        let half = iridescence(&irid(0.5, 0.5), 0.5, 1.0, 1.0);
        assert!(close(half, DVec3::new(0.54953, 1.44274, 1.43303)), "{half}");
        let cos30 = 30f64.to_radians().cos();
        let slanted = iridescence(&irid(1.0, 0.5), 0.5, 0.5, cos30);
        assert!(
            close(slanted, DVec3::new(1.98835, 0.61158, 0.11495)),
            "{slanted}"
        );
        assert_eq!(
            iridescence(&irid(1.0, 0.0), 0.0, 0.3, 0.9),
            DVec3::splat(2.0)
        );
    }
}
