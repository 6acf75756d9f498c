//! What lies along and beyond a ray: the sky sphere, fog layers and rainbows.
//!
//! In: the scene's [`Atmosphere`] and background, a ray and how far it went. Out: the
//! colour of a ray that hits nothing, and the colour seen through the atmosphere. Holds: no
//! allocation; a ray that hits nothing has travelled an infinite distance.
//!
//! Rules (POV-Ray 3.7 manual; the measured ones say so):
//! - sky sphere: pigments are looked up at the ray direction (moved into sky space by the
//!   inverse of the sky's transformations); layers are stacked, the last on top. In 3.7
//!   scenes each layer shows `1 − filter − transmit` of its colour and lets
//!   `filter · colour + transmit` of the layers below through; what passes every layer
//!   shows the background. Legacy scenes (no `#version`, or one below 3.7) stack them
//!   differently: each layer's `1 − filter − transmit` share is weighted by what reaches
//!   it, 1 for the top layer, below that the product of the filters above plus the
//!   product of their transmits (so between layers filter acts like transmit, and a
//!   filter layer above a transmit layer passes nothing); the background is weighted by
//!   the product of all filters times the product of all colours plus the product of all
//!   transmits. Both measured on single pixels with stacks of rgbf, rgbt and rgbft layers
//!   (legacy: exact for layers with filter or transmit; layers with both differ). The
//!   result is multiplied by `emission`.
//! - fog: with depth d, constant fog lets `a = exp(−d / distance)` through; ground fog
//!   uses the density integrated along the ray instead of d, with density 1 up to height
//!   `fog_offset` (along `up`) and `1 / (1 + ((h − offset) / alt)²)` above (measured: 0.8,
//!   0.5 and 0.2 at 0.5, 1 and 2 alts above the offset, not the manual's
//!   `1/(1 + (h − offset)/alt)²`; rays climbing through it match the integral
//!   `alt · atan((h − offset)/alt)`). With k = max(a, transmit), the colour C behind becomes
//!   `k · C · (1 − filter + filter · F) + (1 − k) · F` for fog colour F (measured on single
//!   pixels for rgb, rgbt, rgbf and rgbft fogs, thin and thick). A distance of zero turns
//!   the fog off. Several layers do not hide each other: the factors on C multiply and the
//!   `(1 − k) · F` terms add (measured with two fogs in either order). Turbulence
//!   multiplies the optical depth (constant or ground) by `1 − exp(−d / distance) ·
//!   min(1, turb_depth · T)`, T being the scene generator's scalar turbulence (octaves,
//!   omega, lambda) at the middle of the ray's path times the turbulence vector per axis,
//!   in world space whatever the fog's transformations; rays that hit nothing stay fully
//!   fogged (measured exact on 8-bit renders of constant and ground fogs, vector amounts,
//!   turb_depth, octaves, omega, lambda, both generators and transformed fogs).
//! - rainbow: the angle between the ray and the rainbow's direction indexes the colour map
//!   from `angle − width/2` (0) to `angle + width/2` (1); around the direction the arc
//!   spans `arc_angle` centred on `up`, fading to nothing between `falloff_angle/2` and
//!   `arc_angle/2` as `1 − smoothstep(t)` (measured along a white bow: 0.98, 0.92, 0.74,
//!   0.49, 0.26 a twelfth, a sixth, a third, a half, two thirds of the way); the colour is
//!   mixed in like a fog of the rainbow's `distance`, and the falloff weight w then blends
//!   that result with the colour behind (`(1 − w) · C + w · fogged`, so the weight also
//!   thins the bow's transmit floor). Jitter adds a hashed offset of up to `jitter` to the
//!   index. Unlike a fog's, the bow's filter is weighted by its share: with the part passed
//!   `p = max(exp(−d/distance), transmit)` and `w = 1 − p`, the colour behind C becomes
//!   `C · p · (1 − filter · w · (1 − R)) + w · R` (measured, 16-bit renders).

use super::antialias::unit_hash;
use crate::noise::NoiseGenerator;
use crate::texture::pigment::{colour_map_lookup, pigment_colour};
use crate::{
    math::Colour,
    scene::{Atmosphere, Fog, FogKind, FogTurbulence, Rainbow, SkySphere},
};
use glam::DVec3;

/// Colours a ray gets from the atmosphere.
pub struct AtmosphereShader<'a> {
    atmosphere: &'a Atmosphere,
    background: DVec3,
    /// Stack sky sphere layers as POV-Ray does for scenes before 3.7.
    legacy_sky_layers: bool,
    /// The scene's `noise_generator`, which fog turbulence uses.
    noise_generator: NoiseGenerator,
}

impl<'a> AtmosphereShader<'a> {
    /// A shader for `atmosphere` in front of `background`.
    pub fn new(atmosphere: &'a Atmosphere, background: DVec3) -> AtmosphereShader<'a> {
        AtmosphereShader {
            atmosphere,
            background,
            legacy_sky_layers: false,
            noise_generator: NoiseGenerator::default(),
        }
    }

    /// The shader with fog turbulence read from `generator` (the scene's global
    /// `noise_generator`).
    pub fn with_noise_generator(mut self, generator: NoiseGenerator) -> AtmosphereShader<'a> {
        self.noise_generator = generator;
        self
    }

    /// The shader with sky sphere layers stacked the pre-3.7 way (`legacy`: the scene is a
    /// legacy scene, see `encoding::is_legacy_scene`) or the 3.7 way.
    pub fn with_legacy_sky_layers(mut self, legacy: bool) -> AtmosphereShader<'a> {
        self.legacy_sky_layers = legacy;
        self
    }

    /// The colour seen by a ray that hits nothing, looking along unit `direction`.
    pub fn sky(&self, direction: DVec3) -> DVec3 {
        match &self.atmosphere.sky_sphere {
            Some(sky) if self.legacy_sky_layers => {
                legacy_sky_colour(sky, direction, self.background)
            }
            Some(sky) => sky_colour(sky, direction, self.background),
            None => self.background,
        }
    }

    /// Whether fog or rainbows change colours along rays.
    pub fn is_clear(&self) -> bool {
        self.atmosphere.is_clear()
    }

    /// How the atmosphere changes the colour seen along a ray from `origin` along unit
    /// `direction` over `depth` (infinite for rays that hit nothing): the colour behind is
    /// multiplied by the first value and the second is added.
    pub fn along(&self, origin: DVec3, direction: DVec3, depth: f64) -> (DVec3, DVec3) {
        let mut keep = DVec3::ONE;
        let mut add = DVec3::ZERO;
        for fog in &self.atmosphere.fogs {
            let stir = fog.turbulence.as_ref().map(|t| (t, self.noise_generator));
            let share = fog_share(fog, origin, direction, depth, stir);
            mix_layer(&mut keep, &mut add, share, fog.colour);
        }
        for rainbow in &self.atmosphere.rainbows {
            if let Some((share, colour, weight)) = rainbow_share(rainbow, direction, depth) {
                // The arc's falloff weakens the whole layer, transparency included.
                let (layer_keep, layer_add) = rainbow_layer(share, colour);
                keep *= DVec3::splat(1.0 - weight) + weight * layer_keep;
                add += weight * layer_add;
            }
        }
        (keep, add)
    }
}

/// A rainbow's layer with fog share `share` and colour `colour`, as the factor on the colour
/// behind and the colour added. Unlike a fog's, the colour's filter acts in proportion to
/// the share (measured: a bow of filter 1 at a tiny share leaves the colour behind as it is).
fn rainbow_layer(share: f64, colour: Colour) -> (DVec3, DVec3) {
    if share <= 0.0 || share.is_nan() {
        return (DVec3::ONE, DVec3::ZERO);
    }
    let passed = (1.0 - share.min(1.0)).max(colour.transmit);
    let tint = colour.rgb_vec();
    let shown = 1.0 - passed;
    let filtered = DVec3::ONE - colour.filter * shown * (DVec3::ONE - tint);
    (passed * filtered, shown * tint)
}

/// Adds one fog-like layer with fog share `share` (1 − a) and colour `colour` to what `keep`
/// and `add` already describe (layers are independent of their order).
fn mix_layer(keep: &mut DVec3, add: &mut DVec3, share: f64, colour: Colour) {
    if share <= 0.0 || share.is_nan() {
        return;
    }
    let passed = (1.0 - share.min(1.0)).max(colour.transmit);
    let tint = colour.rgb_vec();
    let through = passed * (DVec3::splat(1.0 - colour.filter) + colour.filter * tint);
    let own = (1.0 - passed) * tint;
    *keep *= through;
    *add += own;
}

/// The fraction of light that passes `fog` from `origin` over `depth` along unit
/// `direction` (lights with `media_attenuation` are dimmed so; turbulence is left out). A
/// path of no positive length (a point beyond a parallel light's plane) passes everything.
pub fn fog_transmittance(fog: &Fog, origin: DVec3, direction: DVec3, depth: f64) -> f64 {
    if depth.is_nan() || depth <= 0.0 {
        return 1.0;
    }
    1.0 - fog_share(fog, origin, direction, depth, None)
}

/// The fraction `1 − a` of fog between a ray's start and `depth`, stirred by the fog's
/// turbulence read from the given generator when `stir` is given.
fn fog_share(
    fog: &Fog,
    origin: DVec3,
    direction: DVec3,
    depth: f64,
    stir: Option<(&FogTurbulence, NoiseGenerator)>,
) -> f64 {
    if fog.distance == 0.0 || !fog.distance.is_finite() {
        return 0.0;
    }
    let distance = fog.distance.abs();
    let optical_depth = match fog.kind {
        FogKind::Constant => depth,
        FogKind::Ground { offset, altitude } => {
            let up = fog.up.normalize_or(glam::DVec3::Y);
            let start = origin.dot(up);
            let rise = direction.dot(up);
            ground_fog_depth(start, rise, depth, offset, altitude)
        }
    };
    let thinning = match stir {
        // An endless ray stays fully fogged: turbulence fades out with depth.
        Some((turbulence, generator)) if depth.is_finite() => {
            turbulent_thinning(turbulence, origin, direction, depth, distance, generator)
        }
        _ => 1.0,
    };
    1.0 - (-optical_depth * thinning / distance).exp()
}

/// The factor a fog's turbulence multiplies the optical depth of a ray by: `1 − k · min(1,
/// turb_depth · T)`, with T the scalar turbulence at the middle of the ray's path scaled
/// per axis by the turbulence amount, and `k = exp(−depth / distance)` (so distant fog is
/// hardly stirred).
fn turbulent_thinning(
    turbulence: &FogTurbulence,
    origin: DVec3,
    direction: DVec3,
    depth: f64,
    distance: f64,
    generator: NoiseGenerator,
) -> f64 {
    let point = (origin + direction * (depth / 2.0)) * turbulence.amount;
    let stir = crate::noise::turbulence(point, &turbulence.shape, generator);
    let nearness = (-depth / distance).exp();
    1.0 - nearness * (turbulence.depth * stir).min(1.0)
}

/// The density of ground fog integrated along a path of length `depth` that starts at
/// height `start` and climbs `rise` per unit of length.
fn ground_fog_depth(start: f64, rise: f64, depth: f64, offset: f64, altitude: f64) -> f64 {
    let altitude = altitude.abs();
    let density = |h: f64| {
        if h <= offset {
            1.0
        } else if altitude > 0.0 {
            1.0 / (1.0 + ((h - offset) / altitude).powi(2))
        } else {
            0.0
        }
    };
    // F(h): the integral of the density from `offset` to h.
    let cumulative = |h: f64| {
        if h <= offset {
            h - offset
        } else {
            altitude * ((h - offset) / altitude.max(f64::MIN_POSITIVE)).atan()
        }
    };
    if rise.abs() < 1e-10 {
        return density(start) * depth;
    }
    let end = start + rise * depth;
    if !end.is_finite() {
        // An endless ray: upwards only the thinning part remains, downwards it is dense.
        return if rise > 0.0 {
            (altitude * std::f64::consts::FRAC_PI_2 - cumulative(start)) / rise
        } else {
            f64::INFINITY
        };
    }
    (cumulative(end) - cumulative(start)) / rise
}

/// The rainbow's fog share, colour and arc weight for a ray along unit `direction`, if it is
/// in the bow.
fn rainbow_share(rainbow: &Rainbow, direction: DVec3, depth: f64) -> Option<(f64, Colour, f64)> {
    let axis = rainbow.direction.try_normalize()?;
    if rainbow.width <= 0.0 || rainbow.distance == 0.0 {
        return None;
    }
    let angle = direction.dot(axis).clamp(-1.0, 1.0).acos().to_degrees();
    let inner = rainbow.angle - rainbow.width / 2.0;
    let mut index = (angle - inner) / rainbow.width;
    if rainbow.jitter != 0.0 {
        let bits = direction.x.to_bits() ^ direction.y.to_bits().rotate_left(21);
        index += rainbow.jitter * (unit_hash(bits ^ direction.z.to_bits().rotate_left(42)) - 0.5);
    }
    if !(0.0..=1.0).contains(&index) {
        return None;
    }
    // Position around the axis, measured from `up`.
    let weight = match (rainbow.up - axis * rainbow.up.dot(axis)).try_normalize() {
        Some(up) if rainbow.arc_angle < 360.0 => {
            let side = axis.cross(up);
            let across = direction - axis * direction.dot(axis);
            let around = across.dot(side).atan2(across.dot(up)).to_degrees().abs();
            let (arc, falloff) = (rainbow.arc_angle / 2.0, rainbow.falloff_angle / 2.0);
            if around > arc {
                return None;
            }
            if around > falloff && arc > falloff {
                let t = (around - falloff) / (arc - falloff);
                1.0 - t * t * (3.0 - 2.0 * t)
            } else {
                1.0
            }
        }
        _ => 1.0,
    };
    let share = 1.0 - (-depth / rainbow.distance.abs()).exp();
    let colour = colour_map_lookup(&rainbow.colour_map, index);
    Some((share, colour, weight))
}

/// The sky sphere's colour in unit `direction`, over `background` (3.7 scenes).
fn sky_colour(sky: &SkySphere, direction: DVec3, background: DVec3) -> DVec3 {
    let point = sky.transform.point_to_inner(direction);
    let mut colour = DVec3::ZERO;
    let mut through = DVec3::ONE;
    for pigment in sky.pigments.iter().rev() {
        let layer = pigment_colour(pigment, point);
        let rgb = layer.rgb_vec();
        colour += through * (1.0 - layer.filter - layer.transmit) * rgb;
        through *= layer.filter * rgb + DVec3::splat(layer.transmit);
        if through.max_element() <= 0.0 {
            break;
        }
    }
    (colour + through * background) * sky.emission
}

/// The sky sphere's colour in unit `direction`, over `background` (scenes before 3.7).
fn legacy_sky_colour(sky: &SkySphere, direction: DVec3, background: DVec3) -> DVec3 {
    let point = sky.transform.point_to_inner(direction);
    let mut colour = DVec3::ZERO;
    // What reaches a layer from the layers above it: 1 for the top one, then the product
    // of their filters plus the product of their transmits.
    let mut through = 1.0;
    let mut filter_product = 1.0;
    let mut transmit_product = 1.0;
    let mut filter_colour = DVec3::ONE;
    for pigment in sky.pigments.iter().rev() {
        let layer = pigment_colour(pigment, point);
        let rgb = layer.rgb_vec();
        colour += through * (1.0 - layer.filter - layer.transmit) * rgb;
        filter_product *= layer.filter;
        transmit_product *= layer.transmit;
        filter_colour *= rgb;
        through = filter_product + transmit_product;
        if through <= 0.0 {
            break;
        }
    }
    let to_background = filter_product * filter_colour + DVec3::splat(transmit_product);
    (colour + to_background * background) * sky.emission
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Transform;

    fn fog(kind: FogKind, colour: Colour) -> Fog {
        Fog {
            kind,
            distance: 10.0,
            colour,
            up: DVec3::Y,
            turbulence: None,
        }
    }

    #[test]
    fn constant_fog_at_its_distance() {
        let atmosphere = Atmosphere {
            fogs: vec![fog(FogKind::Constant, Colour::rgb(1.0, 0.0, 0.0))],
            ..Atmosphere::default()
        };
        let shader = AtmosphereShader::new(&atmosphere, DVec3::ZERO);
        let (keep, add) = shader.along(DVec3::ZERO, DVec3::Z, 10.0);
        let a = (-1.0f64).exp();
        assert!((keep - DVec3::splat(a)).length() < 1e-12);
        assert!((add - DVec3::new(1.0 - a, 0.0, 0.0)).length() < 1e-12);
        let (keep, add) = shader.along(DVec3::ZERO, DVec3::Z, f64::INFINITY);
        assert_eq!((keep, add), (DVec3::ZERO, DVec3::X));
    }

    #[test]
    fn ground_fog_density_integrates() {
        // Level at the offset: full density.
        assert_eq!(ground_fog_depth(0.0, 0.0, 5.0, 0.0, 1.0), 5.0);
        // Level one alt above the offset: half density.
        assert_eq!(ground_fog_depth(1.0, 0.0, 5.0, 0.0, 1.0), 2.5);
        // Straight up from 3 below the offset, 10 units: 3 + atan(7).
        let climb = ground_fog_depth(-3.0, 1.0, 10.0, 0.0, 1.0);
        assert!((climb - (3.0 + 7f64.atan())).abs() < 1e-12);
        // Endlessly up from the offset: alt · π/2.
        let endless = ground_fog_depth(0.0, 1.0, f64::INFINITY, 0.0, 2.0);
        assert!((endless - std::f64::consts::PI).abs() < 1e-12);
    }

    #[test]
    fn turbulence_thins_near_fog_only() {
        let turbulence = FogTurbulence {
            amount: DVec3::splat(0.7),
            depth: 0.5,
            shape: crate::noise::TurbulenceShape::default(),
        };
        let generator = NoiseGenerator::default();
        let near = turbulent_thinning(&turbulence, DVec3::ZERO, DVec3::Z, 1.0, 10.0, generator);
        assert!(near > 0.0 && near < 1.0);
        let far = turbulent_thinning(&turbulence, DVec3::ZERO, DVec3::Z, 500.0, 10.0, generator);
        assert!((far - 1.0).abs() < 1e-12);
        let flat = FogTurbulence {
            depth: 0.0,
            ..turbulence
        };
        let even = turbulent_thinning(&flat, DVec3::ZERO, DVec3::Z, 1.0, 10.0, generator);
        assert_eq!(even, 1.0);
    }

    #[test]
    fn transmit_leaves_light_through_the_fog() {
        let atmosphere = Atmosphere {
            fogs: vec![fog(
                FogKind::Constant,
                Colour::rgbft(1.0, 1.0, 1.0, 0.0, 0.3),
            )],
            ..Atmosphere::default()
        };
        let shader = AtmosphereShader::new(&atmosphere, DVec3::ZERO);
        let (keep, _) = shader.along(DVec3::ZERO, DVec3::Z, f64::INFINITY);
        assert!((keep - DVec3::splat(0.3)).length() < 1e-12);
        // Thinner fog than the transmit floor changes nothing.
        let (keep, _) = shader.along(DVec3::ZERO, DVec3::Z, 1.0);
        assert!((keep - DVec3::splat((-0.1f64).exp())).length() < 1e-12);
    }

    #[test]
    fn sky_layers_show_through() {
        let sky = SkySphere {
            pigments: vec![
                crate::texture::Pigment::Solid(Colour::rgb(0.0, 0.0, 1.0)),
                crate::texture::Pigment::Solid(Colour::rgbft(1.0, 0.0, 0.0, 0.0, 0.5)),
            ],
            emission: DVec3::ONE,
            transform: Transform::IDENTITY,
        };
        let colour = sky_colour(&sky, DVec3::Y, DVec3::ZERO);
        assert!((colour - DVec3::new(0.5, 0.0, 0.5)).length() < 1e-12);
    }

    /// POV-Ray 3.7 on one pixel of a legacy scene: two grey rgbf 0.5 layers over
    /// background <0.2, 0.4, 0.6> give 0.388, 0.4, 0.412; a filter layer over a transmit
    /// layer hides the background.
    #[test]
    fn legacy_sky_filter_layers_stack_as_measured() {
        let grey_filter = crate::texture::Pigment::Solid(Colour::rgbft(0.5, 0.5, 0.5, 0.5, 0.0));
        let grey_transmit = crate::texture::Pigment::Solid(Colour::rgbft(0.5, 0.5, 0.5, 0.0, 0.5));
        let background = DVec3::new(0.2, 0.4, 0.6);
        let sky = |pigments| SkySphere {
            pigments,
            emission: DVec3::ONE,
            transform: Transform::IDENTITY,
        };
        let filters = sky(vec![grey_filter.clone(), grey_filter.clone()]);
        let colour = legacy_sky_colour(&filters, DVec3::Y, background);
        assert!((colour - DVec3::new(0.3875, 0.4, 0.4125)).length() < 1e-12);
        let mixed = sky(vec![grey_transmit, grey_filter]);
        let colour = legacy_sky_colour(&mixed, DVec3::Y, background);
        assert!((colour - DVec3::splat(0.375)).length() < 1e-12);
    }
}
