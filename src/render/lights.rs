//! Light leaving a source for a surface point: distance fading, spotlight cones and
//! cylinder beams, before anything blocks it.
//!
//! In: a [`LightSource`] and a world point (and the [`Scene`], whose lights are prepared
//! once). Out: [`Incoming`], the direction, colour and shadow-ray length of the light as it
//! arrives at the point, before shadows (see [`super::shadows`]). Holds: no allocation per
//! point.
//!
//! Rules measured against POV-Ray 3.7 renders (16-bit output, errors below 2e-5):
//! - fading: with `fade_distance` d₀ > 0 and `fade_power` p > 0 the light is multiplied by
//!   `2 / (1 + (d/d₀)^p)`; otherwise it does not weaken with distance.
//! - spotlight: with c = cos(angle between the axis and the direction to the point),
//!   cr = cos(radius), cf = cos(falloff) (cf raised to cr when falloff < radius): zero when
//!   c < cf; `c^tightness` when c ≥ cr; between, `c^tightness · s²(3 − 2s)` with
//!   s = (c − cf)/(cr − cf). A negative radius acts through its cosine. Zero when c ≤ 0,
//!   even with a falloff over 90 degrees.
//! - parallel lights: shadow rays run along the light's direction up to the plane through
//!   the light perpendicular to it; points beyond that plane are lit but never shadowed.
//!   Cylinder lights do the same along their axis (their shadows do not spread; measured
//!   with a sphere in a grazing beam).
//! - cylinder beam: with d the distance from the axis, `(1 − d/falloff)^tightness` times the
//!   smooth step from `falloff` down to `radius` (zero behind the light).
//! - area lights: see [`super::area_light`]; the diffuse and highlight directions are the
//!   centre's unless `area_illumination` is on.

use crate::geometry::World;
use crate::math::power;
use crate::scene::{Fog, LightPhotons, LightSource, Media, Scene, Spotlight};
use glam::DVec3;

/// A light ready for rendering: the source and what its shadow tests need.
pub struct SceneLight {
    /// The light as the scene gives it.
    pub source: LightSource,
    /// The `projected_through` object, ready for ray queries.
    pub projected_through: Option<World>,
    /// The atmospheric media that dim this light on its way (`media_attenuation on`).
    pub attenuating_media: Vec<Media>,
    /// The fogs that dim this light on its way (`media_attenuation on`).
    pub attenuating_fogs: Vec<Fog>,
    /// The light's photons block when it shoots refracted photons: photon targets that
    /// refract them block its shadow rays (their caustics stand for the light through them).
    pub photon_targets_block: Option<LightPhotons>,
}

/// The scene's lights, ready for rendering.
pub fn prepare_lights(scene: &Scene) -> Vec<SceneLight> {
    scene
        .lights
        .iter()
        .map(|source| SceneLight {
            source: source.clone(),
            projected_through: source
                .projected_through
                .as_ref()
                .map(|object| World::build_from_objects(vec![(**object).clone()])),
            attenuating_media: if source.media_attenuation {
                scene.atmosphere.media.clone()
            } else {
                Vec::new()
            },
            attenuating_fogs: if source.media_attenuation {
                scene.atmosphere.fogs.clone()
            } else {
                Vec::new()
            },
            photon_targets_block: (scene.settings.photons.is_some() && source.photons.refraction)
                .then_some(source.photons),
        })
        .collect()
}

/// Light from one source arriving at a surface point, before shadows.
#[derive(Clone, Copy, Debug)]
pub struct Incoming {
    /// Unit vector from the surface point towards the light.
    pub direction: DVec3,
    /// How far shadow rays run towards the light (for a parallel light, to the plane through
    /// the light perpendicular to its direction).
    pub distance: f64,
    /// Light colour after fading and the spotlight cone.
    pub colour: DVec3,
    /// Whether objects can shadow the point (not for points beyond a parallel light's plane).
    pub can_be_shadowed: bool,
}

/// The light `light` sends towards `point`, ignoring shadows; `None` when none arrives.
pub fn incoming(light: &LightSource, point: DVec3) -> Option<Incoming> {
    let offset = light.position - point;
    let distance = offset.length();
    if !(distance > 0.0 && distance.is_finite()) {
        return None;
    }
    // Cylinder lights, like parallel ones, send their light along the beam's axis.
    let cylinder_aim = light
        .spotlight
        .filter(|spot| spot.cylinder)
        .map(|spot| spot.point_at);
    let (direction, shadow_distance) = match light.parallel.or(cylinder_aim) {
        Some(point_at) => {
            let direction = (light.position - point_at).try_normalize()?;
            (direction, offset.dot(direction))
        }
        None => (offset / distance, distance),
    };
    let mut strength = fade_factor(light, distance);
    if let Some(spot) = &light.spotlight {
        strength *= if spot.cylinder {
            cylinder_factor(spot, light.position, point)
        } else {
            spotlight_factor(spot, light.position, offset / distance)
        };
    }
    if strength.is_nan() || strength <= 0.0 {
        return None;
    }
    let colour = light.colour * strength;
    colour.is_finite().then_some(Incoming {
        direction,
        distance: shadow_distance,
        colour,
        can_be_shadowed: !light.shadowless && shadow_distance > 0.0,
    })
}

/// POV-Ray's distance attenuation `2 / (1 + (d / fade_distance)^fade_power)`.
pub fn fade_factor(light: &LightSource, distance: f64) -> f64 {
    if light.fade_distance > 0.0 && light.fade_power > 0.0 {
        2.0 / (1.0 + power(distance / light.fade_distance, light.fade_power))
    } else {
        1.0
    }
}

/// The spotlight's intensity multiplier for light leaving towards `-to_light`.
pub fn spotlight_factor(spot: &Spotlight, position: DVec3, to_light: DVec3) -> f64 {
    let Some(axis) = (spot.point_at - position).try_normalize() else {
        return 0.0;
    };
    let cosine = -to_light.dot(axis);
    let cos_radius = spot.radius.to_radians().cos();
    let cos_falloff = spot.falloff.to_radians().cos().min(cos_radius);
    // Nothing behind the plane through the light across its axis, whatever the falloff
    // (measured: radius 90 falloff 135 lights a wall up to 86.4 degrees from the axis and
    // not at 90.7; the manual asks for angles below 90).
    if cosine.is_nan() || cosine < cos_falloff || cosine <= 0.0 {
        return 0.0;
    }
    let tight = if spot.tightness != 0.0 {
        power(cosine.max(0.0), spot.tightness)
    } else {
        1.0
    };
    if cosine >= cos_radius {
        return tight;
    }
    let s = (cosine - cos_falloff) / (cos_radius - cos_falloff);
    tight * s * s * (3.0 - 2.0 * s)
}

/// The cylinder light's intensity multiplier at `point`: `(1 − d / falloff)^tightness`, d
/// the distance from the beam's axis, times the smooth step from `falloff` down to
/// `radius`; zero behind the light.
pub fn cylinder_factor(spot: &Spotlight, position: DVec3, point: DVec3) -> f64 {
    let Some(axis) = (spot.point_at - position).try_normalize() else {
        return 0.0;
    };
    let offset = point - position;
    let along = offset.dot(axis);
    if along.is_nan() || along <= 0.0 {
        return 0.0;
    }
    let from_axis = (offset - along * axis).length();
    if from_axis.is_nan() || from_axis >= spot.falloff {
        return 0.0;
    }
    let mut factor = if spot.tightness != 0.0 {
        power(1.0 - from_axis / spot.falloff, spot.tightness)
    } else {
        1.0
    };
    if spot.radius > 0.0 && from_axis > spot.radius && spot.falloff > spot.radius {
        let s = (spot.falloff - from_axis) / (spot.falloff - spot.radius);
        factor *= s * s * (3.0 - 2.0 * s);
    }
    factor
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spot(radius: f64, falloff: f64, tightness: f64) -> Spotlight {
        Spotlight {
            point_at: DVec3::new(0.0, -1.0, 0.0),
            radius,
            falloff,
            tightness,
            cylinder: false,
        }
    }

    /// The spotlight factor at `degrees` off the axis of a light at the origin aiming down.
    fn at_angle(spot: &Spotlight, degrees: f64) -> f64 {
        let a = degrees.to_radians();
        let towards_point = DVec3::new(a.sin(), -a.cos(), 0.0);
        spotlight_factor(spot, DVec3::ZERO, -towards_point)
    }

    #[test]
    fn spotlight_curve_matches_povray_samples() {
        // (radius, falloff, tightness, angle, value read from a POV-Ray 3.7 render)
        let samples = [
            (30.0, 45.0, 0.0, 11.3, 1.0),
            (30.0, 45.0, 0.0, 35.7, 0.7328),
            (30.0, 45.0, 0.0, 42.0, 0.1329),
            (20.0, 40.0, 3.0, 11.3, 0.9430),
            (20.0, 40.0, 3.0, 30.2, 0.3875),
            (0.0, 50.0, 10.0, 21.3, 0.4465),
            (-10.0, 50.0, 5.0, 40.2, 0.0749),
            (30.0, 20.0, 0.0, 28.8, 1.0),
            (30.0, 20.0, 0.0, 30.2, 0.0),
        ];
        for (radius, falloff, tightness, angle, expected) in samples {
            let got = at_angle(&spot(radius, falloff, tightness), angle);
            // The sample angles are rounded to 0.1 degree, hence the loose tolerance.
            assert!(
                (got - expected).abs() < 3e-3,
                "{radius} {falloff} {angle}: {got}"
            );
        }
        assert_eq!(at_angle(&spot(30.0, 45.0, 0.0), 120.0), 0.0);
        // A falloff over 90 degrees lights nothing behind the light (povray: 0 at 90.7).
        assert!(at_angle(&spot(90.0, 135.0, 0.0), 86.4) > 0.9);
        assert_eq!(at_angle(&spot(90.0, 135.0, 0.0), 90.7), 0.0);
        assert_eq!(at_angle(&spot(120.0, 170.0, 0.0), 100.0), 0.0);
    }

    #[test]
    fn cylinder_beam_matches_povray_samples() {
        // A beam straight down from y = 1000, sampled on the floor at distance d from the
        // axis (POV-Ray 3.7 renders, linear values).
        let beam = |radius, falloff, tightness| Spotlight {
            point_at: DVec3::ZERO,
            radius,
            falloff,
            tightness,
            cylinder: true,
        };
        let at = |spot: &Spotlight, d: f64| {
            cylinder_factor(spot, DVec3::new(0.0, 1000.0, 0.0), DVec3::new(d, 0.0, 0.0))
        };
        assert!((at(&beam(0.0, 4.0, 1.0), 3.95) - 0.0125).abs() < 1e-4);
        assert!((at(&beam(0.0, 4.0, 1.0), 0.05) - 0.9875).abs() < 1e-4);
        assert!((at(&beam(2.0, 4.0, 0.0), 3.95) - 0.00186).abs() < 1e-4);
        assert_eq!(at(&beam(2.0, 4.0, 0.0), 1.9), 1.0);
        assert_eq!(at(&beam(2.0, 4.0, 0.0), 4.1), 0.0);
    }

    #[test]
    fn fading() {
        let light = LightSource {
            fade_distance: 2.0,
            fade_power: 2.0,
            ..LightSource::point(DVec3::ZERO, DVec3::ONE)
        };
        assert_eq!(fade_factor(&light, 2.0), 1.0);
        assert!((fade_factor(&light, 4.0) - 0.4).abs() < 1e-15);
        let unfaded = LightSource {
            fade_power: 0.0,
            ..light
        };
        assert_eq!(fade_factor(&unfaded, 100.0), 1.0);
    }
}
