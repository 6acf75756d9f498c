//! Light arriving at a surface point: distance fading, spotlight cones and shadows.
//!
//! In: a [`LightSource`], a world point and the [`World`]. Out: the light's colour as it
//! arrives at the point (black when blocked). Holds: no allocation; shadow rays run
//! straight (refraction is ignored, as POV-Ray does without photons).
//!
//! Rules measured against POV-Ray 3.7 renders (16-bit output, errors below 2e-5):
//! - fading: with `fade_distance` d₀ > 0 and `fade_power` p > 0 the light is multiplied by
//!   `2 / (1 + (d/d₀)^p)`; otherwise it does not weaken with distance.
//! - spotlight: with c = cos(angle between the axis and the direction to the point),
//!   cr = cos(radius), cf = cos(falloff) (cf raised to cr when falloff < radius): zero when
//!   c < cf; `c^tightness` when c ≥ cr; between, `c^tightness · s²(3 − 2s)` with
//!   s = (c − cf)/(cr − cf). A negative radius acts through its cosine.
//! - shadows (see [`super::photons`] for photon targets): every surface between the point
//!   and the light that is not `no_shadow` multiplies the light by
//!   `filter · pigment + transmit` of its pigment at the crossing (no clamping; so a
//!   sphere of `rgbf <0.8,0.5,0.2,1>` passes 0.64, 0.25, 0.04); an opaque surface gives
//!   zero. The number of surfaces is not limited by
//!   `max_trace_level`. `shadowless` lights are never blocked. Surfaces closer than 1e-3 to
//!   the lit point are ignored. Interiors with `fade_distance` and a positive `fade_power`
//!   (unlike camera rays, which fade with 0 too) fade the light over the length the shadow
//!   ray runs inside them; interiors with `caustics` brighten it at each
//!   crossing (fake caustics, see [`fake_caustics`]).
//! - parallel lights: shadow rays run along the light's direction up to the plane through
//!   the light perpendicular to it; points beyond that plane are lit but never shadowed.
//!   Cylinder lights do the same along their axis (their shadows do not spread; measured
//!   with a sphere in a grazing beam).
//! - cylinder beam: with d the distance from the axis, `(1 − d/falloff)^tightness` times the
//!   smooth step from `falloff` down to `radius` (zero behind the light).
//! - area lights: see [`super::area_light`]; the diffuse and highlight directions are the
//!   centre's unless `area_illumination` is on.

use super::area_light::AreaArray;
use super::atmosphere::fog_transmittance;
use super::media::transmittance;
use super::reflection::interior_fade;
use super::texture::surface_pigment;
use crate::geometry::{Material, Ray, SurfaceHit, World};
use crate::texture::normal::perturbed_normal;
use crate::texture::pigment::hit_surface;
use crate::{
    math::Colour,
    scene::{Fog, LightPhotons, LightSource, Media, Scene, Spotlight},
};
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

/// What part of the light `arriving` at `point` gets there past shadows and through a
/// `projected_through` object; over the whole array of an area light when `array` is given.
pub fn light_filter(
    light: &SceneLight,
    world: &World,
    point: DVec3,
    arriving: &Incoming,
    array: Option<&AreaArray>,
) -> DVec3 {
    let Some(array) = array else {
        return filter_along(
            light,
            world,
            point,
            arriving.direction,
            arriving.distance,
            arriving.can_be_shadowed,
        );
    };
    array.average(&mut |position: DVec3| {
        let offset = position - point;
        let distance = offset.length();
        match offset.try_normalize() {
            Some(direction) => filter_along(
                light,
                world,
                point,
                direction,
                distance,
                arriving.can_be_shadowed,
            ),
            None => DVec3::ONE,
        }
    })
}

/// The light passing from `distance` away along `direction` to `point`: zero when a
/// `projected_through` object is not crossed; shadows count only up to that object.
fn filter_along(
    light: &SceneLight,
    world: &World,
    point: DVec3,
    direction: DVec3,
    distance: f64,
    can_be_shadowed: bool,
) -> DVec3 {
    let mut limit = distance;
    if let Some(through) = &light.projected_through {
        let ray = Ray {
            origin: point,
            direction,
        };
        match through.first_hit(&ray, SHADOW_EPSILON, distance) {
            Some(hit) => limit = hit.distance,
            None => return DVec3::ZERO,
        }
    }
    let mut filter = if can_be_shadowed {
        shadow_filter(world, point, direction, limit, light.photon_targets_block)
    } else {
        DVec3::ONE
    };
    if !light.attenuating_media.is_empty() && filter != DVec3::ZERO {
        filter *= transmittance(
            &light.attenuating_media,
            point,
            direction,
            (0.0, limit),
            false,
        );
    }
    for fog in &light.attenuating_fogs {
        filter *= fog_transmittance(fog, point, direction, limit);
    }
    filter
}

/// Shadow rays ignore surfaces closer than this to the lit point (measured in POV-Ray 3.7
/// with thin boxes and small spheres just off a lit plane: hits below 1e-3 do not shadow).
const SHADOW_EPSILON: f64 = 1e-3;

/// At most this many transparent surfaces are followed along one shadow ray.
const MAX_SHADOW_SURFACES: u32 = 10_000;

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
        2.0 / (1.0 + (distance / light.fade_distance).powf(light.fade_power))
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
    if cosine.is_nan() || cosine < cos_falloff {
        return 0.0;
    }
    let tight = if spot.tightness != 0.0 {
        cosine.max(0.0).powf(spot.tightness)
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
        (1.0 - from_axis / spot.falloff).powf(spot.tightness)
    } else {
        1.0
    };
    if spot.radius > 0.0 && from_axis > spot.radius && spot.falloff > spot.radius {
        let s = (spot.falloff - from_axis) / (spot.falloff - spot.radius);
        factor *= s * s * (3.0 - 2.0 * s);
    }
    factor
}

/// The part of a light that passes a surface with this pigment: `filter · rgb + transmit`.
pub fn transmission(pigment: Colour) -> DVec3 {
    pigment.rgb_vec() * pigment.filter + DVec3::splat(pigment.transmit)
}

/// What fraction of the light from `distance` away along `direction` reaches `point`.
///
/// Light also fades through objects whose interior has `fade_distance` and a positive
/// `fade_power`, over the length between entering and leaving them (from the lit point when
/// it is inside). With `photon_targets_block` (the light's photons block), photon targets
/// that refract the light's photons are opaque.
pub fn shadow_filter(
    world: &World,
    point: DVec3,
    direction: DVec3,
    distance: f64,
    photon_targets_block: Option<LightPhotons>,
) -> DVec3 {
    let ray = Ray {
        origin: point,
        direction,
    };
    let mut filter = DVec3::ONE;
    let mut start = SHADOW_EPSILON;
    // Surfaces through the light itself do not shadow it (POV-Ray lights cornell.pov's walls
    // from lights lying in its ceiling's plane), whatever the rounding of their distance.
    let distance = distance - SHADOW_EPSILON;
    // The last object entered along the ray and where.
    let mut entered: Option<(u32, f64)> = None;
    for _ in 0..MAX_SHADOW_SURFACES {
        let Some(hit) = world.first_shadow_hit(&ray, start, distance) else {
            return filter;
        };
        let Some(material) = world.materials.get(hit.material as usize) else {
            return DVec3::ZERO;
        };
        if photon_targets_block.is_some_and(|light| material.photons.refracts_for(&light))
            && !material.no_image
            && material.photons.target().is_some()
            && !material.photons.pass_through()
        {
            return DVec3::ZERO;
        }
        filter *= hit_transmission(world, &hit, direction);
        if material.interior.caustics > 0.0 {
            filter *= fake_caustics(material, &hit, direction);
        }
        if direction.dot(hit.normal) < 0.0 {
            entered = Some((hit.material, hit.distance));
        } else {
            let (since, from_outside) = match entered {
                Some((id, at)) if id == hit.material => (at, true),
                Some(_) => (hit.distance, true),
                None => (0.0, false),
            };
            // Shadow rays fade only with a positive `fade_power`; camera rays also fade with
            // 0 (measured).
            if material.interior.fade_power > 0.0 {
                if let Some(kept) = interior_fade(&material.interior, hit.distance - since) {
                    filter *= kept;
                }
            }
            // Absorbing and scattering media inside the object cast shadows.
            if !material.interior.media.is_empty() {
                filter *= transmittance(
                    &material.interior.media,
                    point,
                    direction,
                    (since, hit.distance),
                    from_outside,
                );
            }
            entered = None;
        }
        if !filter.is_finite() || filter.abs().max_element() < 1e-12 {
            return DVec3::ZERO;
        }
        start = hit.distance + SHADOW_EPSILON;
    }
    DVec3::ZERO
}

/// The part of the light along `direction` that passes the surface at `hit`: through its
/// pigment there (uv-mapped pigments at the hit's uv coordinates), blended over the corner
/// textures of a mesh triangle whose corners differ.
fn hit_transmission(world: &World, hit: &SurfaceHit, direction: DVec3) -> DVec3 {
    let surface = hit_surface(hit.point, direction, hit.normal);
    let through = |material: u32| {
        world
            .materials
            .get(material as usize)
            .map_or(DVec3::ZERO, |material| {
                let texture = material.texture_facing(direction, hit.normal);
                transmission(surface_pigment(texture, hit, &surface))
            })
    };
    match &hit.corner_blend {
        Some(blend) => blend
            .materials
            .iter()
            .zip(blend.weights)
            .map(|(&material, weight)| through(material) * weight.max(0.0))
            .sum(),
        None => through(hit.material),
    }
}

/// The exponent of fake caustics per unit of `caustics` (measured: see [`fake_caustics`]).
const CAUSTICS_EXPONENT: f64 = 45.0;

/// How much brighter light gets crossing a surface with interior `caustics` c:
/// `1 + |cos a|^(45 c)`, a the angle between the shadow ray and the (perturbed) surface
/// normal, turned towards the lit point before a `normal { }` perturbs it (with the
/// other side, bumps under a light straight above come out darker than POV-Ray's; this
/// way they match exactly). Measured in POV-Ray 3.7 with tilted discs, boxes and spheres
/// under a light straight above: 1.502 at 10 degrees with c = 1 (0.842, 0.709, 0.252, 0.064 more for c =
/// 0.25, 0.5, 2, 4), 1.0016 at 30 degrees, 2 when the ray runs along the normal; every
/// crossed surface multiplies, filter and transmit alike.
fn fake_caustics(material: &Material, hit: &SurfaceHit, direction: DVec3) -> f64 {
    let mut normal = hit.normal;
    if let Some(perturbation) = &material.texture.normal {
        let facing = if direction.dot(normal) < 0.0 {
            normal
        } else {
            -normal
        };
        normal = perturbed_normal(perturbation, hit.point, hit.uv, facing);
    }
    let cosine = direction.dot(normal).abs().min(1.0);
    1.0 + cosine.powf(CAUSTICS_EXPONENT * material.interior.caustics)
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

    #[test]
    fn transmission_of_pigments() {
        let t = transmission(Colour::rgbft(0.8, 0.5, 0.2, 0.5, 0.3));
        assert!((t - DVec3::new(0.7, 0.55, 0.4)).length() < 1e-15);
        assert_eq!(transmission(Colour::rgb(0.8, 0.5, 0.2)), DVec3::ZERO);
    }
}
