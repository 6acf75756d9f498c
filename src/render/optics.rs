//! Optics at a surface and inside an object: how much a surface reflects and lets
//! through, where mirrored and refracted rays go, and how light fades inside.
//!
//! In: a [`Finish`], an [`Interior`] or a pigment, directions and the angle of incidence.
//! Out: the reflection colour, the transmission `filter · pigment + transmit`, the tint
//! `metallic` gives highlights, mirrored and refracted directions, the fading of light over
//! a distance. Holds: pure functions, no allocation; the tracer, shadow rays, surfaces and
//! photons share them.
//!
//! Rules measured against POV-Ray 3.7 renders (16-bit output, errors below 2e-5):
//! - `reflection { min, max falloff f }`: `min + (max − min)(1 − cos θ)^f`, θ the angle of
//!   incidence; with a single colour the reflection is that colour at every angle.
//! - `fresnel`: `min + (max − min) F`, F the unpolarised Fresnel reflectance for the ratio
//!   of indices of refraction (min is black when only one colour is given), so
//!   `reflection { 1 fresnel }` with ior 1.5 reflects 0.04 head-on.
//! - `metallic m` in `reflection`: the colour is multiplied by
//!   `1 + m (1 − F′)(pigment − 1)`, F′ the empirical curve of metallic highlights.
//! - `exponent e`: the reflected light L becomes `L^(1/e)` per channel before scaling.
//! - `conserve_energy`: `filter` and `transmit` are multiplied by `1 − reflection` (per
//!   channel); ambient and diffuse light are not.
//! - interior fading over a distance d: `a = 1 / (1 + (d / fade_distance)^fade_power)`
//!   and light is multiplied by `a + (1 − a) fade_color`; for fade_power ≥ 1000 by
//!   `exp(−d (1 − fade_color) / fade_distance)` per channel; off when `fade_distance` is
//!   not positive. It dims only the light coming through the surface a ray inside meets
//!   and a total internal reflection, not the finish reflection nor the surface's light.

use crate::{math::Colour, scene::Interior, texture::finish::Finish};
use glam::DVec3;
use std::f64::consts::FRAC_PI_2;

/// `fade_power` from which POV-Ray fades exponentially.
const EXPONENTIAL_FADE_POWER: f64 = 1000.0;

/// The unpolarised Fresnel reflectance for light meeting a surface at `cos_incidence`,
/// passing from index n₁ to n₂ with `ratio` = n₁ / n₂ (1 on total internal reflection).
pub fn fresnel(cos_incidence: f64, ratio: f64) -> f64 {
    let cos_i = cos_incidence.clamp(0.0, 1.0);
    let sin_t_squared = ratio * ratio * (1.0 - cos_i * cos_i);
    if sin_t_squared >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t_squared).sqrt();
    let perpendicular = (ratio * cos_i - cos_t) / (ratio * cos_i + cos_t);
    let parallel = (cos_i - ratio * cos_t) / (cos_i + ratio * cos_t);
    let reflectance = 0.5 * (perpendicular * perpendicular + parallel * parallel);
    if reflectance.is_finite() {
        reflectance
    } else {
        1.0
    }
}

/// The reflection colour of `finish` at `cos_incidence`, for index ratio `ratio` (used by
/// `fresnel`) and the surface's `pigment`.
pub fn reflection_colour(finish: &Finish, cos_incidence: f64, ratio: f64, pigment: DVec3) -> DVec3 {
    let max = finish.reflection;
    let min = match finish.reflection_min {
        Some(min) => min,
        None if finish.fresnel => DVec3::ZERO,
        None => max,
    };
    let mut colour = if finish.fresnel {
        min + (max - min) * fresnel(cos_incidence, ratio)
    } else if min != max {
        let glancing = (1.0 - cos_incidence.clamp(0.0, 1.0)).powf(finish.reflection_falloff);
        min + (max - min) * glancing
    } else {
        max
    };
    if finish.reflect_metallic != 0.0 {
        colour *= highlight_tint(finish.reflect_metallic, cos_incidence, pigment);
    }
    colour
}

/// Reflected light after the finish's reflection `exponent`.
pub fn apply_exponent(seen: DVec3, exponent: f64) -> DVec3 {
    if exponent == 1.0 || exponent.is_nan() || exponent <= 0.0 {
        return seen;
    }
    let power = 1.0 / exponent;
    DVec3::new(
        seen.x.max(0.0).powf(power),
        seen.y.max(0.0).powf(power),
        seen.z.max(0.0).powf(power),
    )
}

/// What is left of light after travelling `distance` inside `interior` (`None` when the
/// interior does not fade light).
pub fn interior_fade(interior: &Interior, distance: f64) -> Option<DVec3> {
    if interior.fade_distance.is_nan() || interior.fade_distance <= 0.0 {
        return None;
    }
    let relative = distance / interior.fade_distance;
    if interior.fade_power >= EXPONENTIAL_FADE_POWER {
        let absorbed = relative * (DVec3::ONE - interior.fade_colour);
        let kept = DVec3::new(
            (-absorbed.x).exp(),
            (-absorbed.y).exp(),
            (-absorbed.z).exp(),
        );
        return Some(if kept.is_finite() { kept } else { DVec3::ZERO });
    }
    let kept = 1.0 / (1.0 + relative.powf(interior.fade_power));
    let kept = if kept.is_finite() { kept } else { 0.0 };
    Some(DVec3::splat(kept) + (1.0 - kept) * interior.fade_colour)
}

/// The part of a light that passes a surface with this pigment: `filter · rgb + transmit`.
pub fn transmission(pigment: Colour) -> DVec3 {
    pigment.rgb_vec() * pigment.filter + DVec3::splat(pigment.transmit)
}

/// `direction` mirrored about the plane with unit normal `normal`.
pub fn mirror(direction: DVec3, normal: DVec3) -> DVec3 {
    direction - 2.0 * direction.dot(normal) * normal
}

/// The factor `metallic` applies to highlight colours for light at this incidence.
pub(crate) fn highlight_tint(metallic: f64, cos_incidence: f64, pigment: DVec3) -> DVec3 {
    if metallic == 0.0 {
        return DVec3::ONE;
    }
    let x = cos_incidence.clamp(-1.0, 1.0).acos() / FRAC_PI_2;
    let fresnel = (0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903).clamp(0.0, 1.0);
    DVec3::ONE + metallic * (1.0 - fresnel) * (pigment - DVec3::ONE)
}

/// Camera, reflected and transmitted rays ignore surfaces closer than this to their start
/// (measured: POV-Ray 3.7 ignores planes, discs, triangles, boxes and spheres nearer than
/// 1e-4 to the camera or to the surface a secondary ray leaves).
pub const SURFACE_EPSILON: f64 = 1e-4;

/// An index of refraction usable in Snell's law (non-positive or NaN values become 1).
pub(super) fn sanitise_ior(ior: f64) -> f64 {
    if ior > 0.0 && ior.is_finite() {
        ior
    } else {
        1.0
    }
}

/// The refracted direction for a unit `direction` meeting a surface whose unit `normal`
/// faces it, with index ratio `ratio` = n₁/n₂; `None` on total internal reflection.
pub fn refract(direction: DVec3, normal: DVec3, ratio: f64) -> Option<DVec3> {
    let cos_in = -direction.dot(normal);
    let k = 1.0 - ratio * ratio * (1.0 - cos_in * cos_in);
    if k < 0.0 {
        return None;
    }
    (ratio * direction + (ratio * cos_in - k.sqrt()) * normal).try_normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fresnel_matches_povray_renders() {
        // reflection { 1 fresnel } with ior 1.5 at 0, 30, 60 and 80 degrees.
        for (degrees, expected) in [
            (0.0, 0.04),
            (30.0, 0.04152),
            (60.0, 0.08919),
            (80.0, 0.3877),
        ] {
            let cosine = f64::to_radians(degrees).cos();
            assert!(
                (fresnel(cosine, 1.0 / 1.5) - expected).abs() < 2e-5,
                "{degrees}"
            );
        }
        // Leaving glass beyond the critical angle: everything is reflected.
        assert_eq!(fresnel(0.3, 1.5), 1.0);
    }

    #[test]
    fn variable_reflection_matches_povray_renders() {
        let finish = Finish {
            reflection: DVec3::splat(0.9),
            reflection_min: Some(DVec3::splat(0.1)),
            ..Finish::default()
        };
        let at = |degrees: f64, finish: &Finish| {
            reflection_colour(finish, degrees.to_radians().cos(), 1.0, DVec3::ONE).x
        };
        assert!((at(30.0, &finish) - 0.20719).abs() < 2e-5);
        assert!((at(60.0, &finish) - 0.5).abs() < 2e-5);
        let squared = Finish {
            reflection_falloff: 2.0,
            ..finish.clone()
        };
        assert!((at(60.0, &squared) - 0.3).abs() < 2e-5);
        let metallic = Finish {
            reflection: DVec3::splat(0.5),
            reflect_metallic: 1.0,
            ..Finish::default()
        };
        let tinted = reflection_colour(&metallic, 0.5, 1.0, DVec3::new(1.0, 0.5, 0.2));
        assert!(
            (tinted - DVec3::new(0.5, 0.26482, 0.1237))
                .abs()
                .max_element()
                < 2e-5
        );
    }

    #[test]
    fn exponent_and_fading() {
        assert!((apply_exponent(DVec3::splat(0.25), 0.5).x - 0.0625).abs() < 1e-15);
        let interior = Interior {
            fade_distance: 1.0,
            fade_power: 2.0,
            fade_colour: DVec3::new(1.0, 0.5, 0.0),
            ..Interior::default()
        };
        let kept = interior_fade(&interior, 2.0).unwrap();
        assert!((kept - DVec3::new(1.0, 0.6, 0.2)).abs().max_element() < 1e-12);
        assert!(interior_fade(&Interior::default(), 2.0).is_none());
    }

    #[test]
    fn transmission_of_pigments() {
        let t = transmission(Colour::rgbft(0.8, 0.5, 0.2, 0.5, 0.3));
        assert!((t - DVec3::new(0.7, 0.55, 0.4)).length() < 1e-15);
        assert_eq!(transmission(Colour::rgb(0.8, 0.5, 0.2)), DVec3::ZERO);
    }

    #[test]
    fn metallic_tint_matches_povray_samples() {
        // Ratio of the metallic to the plain phong highlight read from POV-Ray 3.7 renders
        // of pigment <0.9, 0.5, 0.2>, at N·L = 0.764 (metallic 1) and 0.9952 (metallic 0.5).
        let pigment = DVec3::new(0.9, 0.5, 0.2);
        let tint = highlight_tint(1.0, 0.7639342218884229, pigment);
        assert!(
            (tint - DVec3::new(0.90204395, 0.51025608, 0.21641104))
                .abs()
                .max_element()
                < 1e-4
        );
        let tint = highlight_tint(0.5, 0.9951868832137065, pigment);
        assert!(
            (tint - DVec3::new(0.95006992, 0.750368, 0.60057197))
                .abs()
                .max_element()
                < 1e-4
        );
        assert_eq!(highlight_tint(0.0, 0.5, pigment), DVec3::ONE);
    }

    #[test]
    fn mirror_reverses_normal_component() {
        let reflected = mirror(DVec3::new(1.0, -1.0, 0.0), DVec3::Y);
        assert_eq!(reflected, DVec3::new(1.0, 1.0, 0.0));
    }

    #[test]
    fn snell_at_a_flat_interface() {
        // 30 degrees incidence from air into glass of index 1.5.
        let incidence = 30f64.to_radians();
        let direction = DVec3::new(incidence.sin(), -incidence.cos(), 0.0);
        let bent = refract(direction, DVec3::Y, 1.0 / 1.5).unwrap();
        let sin_out = bent.x;
        assert!((sin_out - incidence.sin() / 1.5).abs() < 1e-15);
        assert!(bent.y < 0.0);
        // Leaving glass at 60 degrees is beyond the critical angle of 41.8 degrees.
        let steep = DVec3::new(60f64.to_radians().sin(), -60f64.to_radians().cos(), 0.0);
        assert!(refract(steep, DVec3::Y, 1.5).is_none());
        assert_eq!(refract(DVec3::NEG_Y, DVec3::Y, 1.5), Some(DVec3::NEG_Y));
    }

    #[test]
    fn odd_ior_values_are_tamed() {
        assert_eq!(sanitise_ior(f64::NAN), 1.0);
        assert_eq!(sanitise_ior(-2.0), 1.0);
        assert_eq!(sanitise_ior(1.5), 1.5);
    }
}
