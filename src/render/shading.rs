//! Local illumination at a surface point: ambient, emission, diffuse and highlights.
//!
//! In: a [`SurfaceSample`] (point, normal facing the viewer, pigment, finish), the scene's
//! lights and the [`World`] for shadow rays. Out: [`LocalLight`], split into the part that
//! the pigment's opacity scales and the highlights, which it does not. Holds: no
//! allocation; lights on the far side of the surface contribute nothing.
//!
//! Formulas measured against POV-Ray 3.7 renders (16-bit output, errors below 2e-5):
//! - ambient: `pigment · (ambient · ambient_light + emission)`.
//! - diffuse, per light with N·L > 0: `diffuse · (N·L)^brilliance · pigment · light`.
//! - phong: `phong · (R·L)^phong_size · light`, R the mirror direction of the viewing ray.
//! - specular: `specular · (N·H)^(1/roughness) · light`, H = normalize(L + V).
//! - metallic m tints both highlights: `light · (1 + m (1 − F) (pigment − 1))` with
//!   F = clamp(0.014567225 / (x − 1.12)² − 0.011612903, 0, 1), x = acos(N·L) / (π/2).
//! - light here is the light colour after fading, the spotlight cone and shadow filtering,
//!   tinted by `irid` (see [`super::iridescence`]).
//! - `shadowless` lights light diffusely but cause no highlights (as the manual says, and
//!   renders confirm).

use super::area_light::{point_random, AreaArray, Sampled};
use super::iridescence::{irid_thickness, iridescence};
use super::lights::{incoming, Incoming, SceneLight};
use super::optics::{highlight_tint, mirror};
use super::shadows::light_filter;
use crate::geometry::World;
use crate::{math::Colour, scene::LightGroup, texture::finish::Finish};
use glam::DVec3;
use std::ops::{Add, Div};

/// Salt of the random numbers behind `crand`.
const CRAND_SALT: u64 = 0x00c7_a9d0_5e11_3b27;

/// What the shading of one surface point needs to know.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceSample<'a> {
    /// The point in world space.
    pub point: DVec3,
    /// Unit surface normal, turned to face the incoming ray.
    pub normal: DVec3,
    /// Unit direction of the ray that hit the point.
    pub ray_direction: DVec3,
    /// The pigment at the point.
    pub pigment: Colour,
    /// The surface finish.
    pub finish: &'a Finish,
    /// `double_illuminate`: lights behind the surface light it as if in front.
    pub double_illuminate: bool,
    /// The light group of the surface: which lights light it.
    pub light_group: Option<LightGroup>,
    /// Area lights light the point from their centre, with one shadow ray, as at the hits
    /// of radiosity's gathering rays: POV-Ray's shadow-ray counts there do not grow with an
    /// area light's size (measured: 1×1 to 32×32 arrays add one test per gathering hit).
    pub area_lights_as_points: bool,
}

/// Light leaving a surface point towards the viewer, before transparency and reflection.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LocalLight {
    /// Ambient, emission and diffuse light: the part weighted by `1 − filter − transmit`.
    pub body: DVec3,
    /// Phong and specular highlights, which transparency does not weaken.
    pub highlights: DVec3,
}

impl Add for LocalLight {
    type Output = LocalLight;
    fn add(self, other: LocalLight) -> LocalLight {
        LocalLight {
            body: self.body + other.body,
            highlights: self.highlights + other.highlights,
        }
    }
}

impl Div<f64> for LocalLight {
    type Output = LocalLight;
    fn div(self, divisor: f64) -> LocalLight {
        LocalLight {
            body: self.body / divisor,
            highlights: self.highlights / divisor,
        }
    }
}

impl Sampled for LocalLight {
    fn differs_from(&self, other: &Self) -> bool {
        (self.body + self.highlights).differs_from(&(other.body + other.highlights))
    }
}

/// The light a surface sends to the viewer from ambient, emission and the light sources.
pub fn local_light(
    sample: &SurfaceSample,
    lights: &[SceneLight],
    ambient_light: DVec3,
    world: &World,
) -> LocalLight {
    let finish = sample.finish;
    let pigment = sample.pigment.rgb_vec();
    let mut total = LocalLight {
        body: pigment * (finish.ambient * ambient_light + finish.emission),
        highlights: DVec3::ZERO,
    };
    let has_highlights = finish.phong != 0.0 || finish.specular != 0.0;
    if finish.diffuse == 0.0 && finish.diffuse_back == 0.0 && !has_highlights {
        return total;
    }
    let terms = PointTerms::at(sample);
    for light in lights {
        if !LightGroup::lights(light.source.group, sample.light_group) {
            continue;
        }
        let Some(arriving) = incoming(&light.source, sample.point) else {
            continue;
        };
        let area = light
            .source
            .area
            .as_ref()
            .filter(|_| !sample.area_lights_as_points);
        let area_lit = area.filter(|area| area.area_illumination);
        if let Some(area) = area_lit {
            // Every point light of the array lights the surface from its own position.
            let array = AreaArray::new(area, light.source.position, sample.point);
            let share = arriving.colour;
            total = total
                + array.average(&mut |position: DVec3| {
                    let offset = position - sample.point;
                    let distance = offset.length();
                    let Some(direction) = offset.try_normalize() else {
                        return LocalLight::default();
                    };
                    // A point light behind the surface lights nothing: no shadow ray.
                    let cosine = sample.normal.dot(direction);
                    if !(cosine > 0.0 || (cosine < 0.0 && lights_back(sample))) {
                        return LocalLight::default();
                    }
                    let towards = Incoming {
                        direction,
                        distance,
                        colour: share,
                        can_be_shadowed: arriving.can_be_shadowed,
                    };
                    let filter = light_filter(light, world, sample.point, &towards, None);
                    lit_by(sample, pigment, &terms, direction, share * filter, light)
                });
            continue;
        }
        let cosine = sample.normal.dot(arriving.direction);
        if !(cosine > 0.0 || (cosine < 0.0 && lights_back(sample))) {
            continue;
        }
        let array = area.map(|area| AreaArray::new(area, light.source.position, sample.point));
        let filter = light_filter(light, world, sample.point, &arriving, array.as_ref());
        let colour = arriving.colour * filter;
        if colour == DVec3::ZERO {
            continue;
        }
        total = total + lit_by(sample, pigment, &terms, arriving.direction, colour, light);
    }
    total
}

/// The parts of the lighting that depend only on the surface point, computed once per
/// sample rather than per light or per area-light sample.
struct PointTerms {
    /// What `crand` takes off the diffuse light.
    grain: f64,
    /// The `irid` film thickness (0 without `irid`).
    irid_thickness: f64,
}

impl PointTerms {
    /// The terms at `sample`'s point.
    fn at(sample: &SurfaceSample) -> PointTerms {
        let finish = sample.finish;
        let grain = if finish.crand != 0.0 {
            finish.crand * point_random(sample.point, CRAND_SALT)
        } else {
            0.0
        };
        let irid_thickness = finish
            .irid
            .as_ref()
            .map_or(0.0, |irid| irid_thickness(irid, sample.point));
        PointTerms {
            grain,
            irid_thickness,
        }
    }
}

/// Whether light from behind the surface lights it.
fn lights_back(sample: &SurfaceSample) -> bool {
    sample.double_illuminate || sample.finish.diffuse_back != 0.0
}

/// Diffuse light and highlights from light of `colour` arriving along `to_light`
/// (shadows already applied).
fn lit_by(
    sample: &SurfaceSample,
    pigment: DVec3,
    terms: &PointTerms,
    to_light: DVec3,
    colour: DVec3,
    light: &SceneLight,
) -> LocalLight {
    let finish = sample.finish;
    let mut lit = LocalLight::default();
    let cosine = sample.normal.dot(to_light);
    if cosine.is_nan() || cosine == 0.0 {
        return lit;
    }
    let front = cosine > 0.0 || sample.double_illuminate;
    let colour = match &finish.irid {
        Some(irid) => {
            let cos_view = sample.normal.dot(-sample.ray_direction).abs();
            colour * iridescence(irid, terms.irid_thickness, cosine.abs(), cos_view)
        }
        None => colour,
    };
    let amount = if front {
        finish.diffuse
    } else {
        finish.diffuse_back
    };
    let cosine = cosine.abs();
    if amount != 0.0 {
        let falloff = if finish.brilliance == 1.0 {
            cosine
        } else {
            cosine.powf(finish.brilliance)
        };
        lit.body = (amount * falloff - terms.grain) * pigment * colour;
    }
    // POV-Ray: shadowless lights cause no highlights; nor does light from behind.
    let has_highlights = finish.phong != 0.0 || finish.specular != 0.0;
    if !has_highlights || light.source.shadowless || !front {
        return lit;
    }
    let normal = if sample.normal.dot(to_light) > 0.0 {
        sample.normal
    } else {
        -sample.normal
    };
    let tint = highlight_tint(finish.metallic, cosine, pigment);
    if finish.phong != 0.0 {
        let reflected_view = mirror(sample.ray_direction, normal);
        let phong_cosine = reflected_view.dot(to_light);
        if phong_cosine > 0.0 {
            lit.highlights += finish.phong * phong_cosine.powf(finish.phong_size) * colour * tint;
        }
    }
    if finish.specular != 0.0 {
        if let Some(half) = (to_light - sample.ray_direction).try_normalize() {
            let half_cosine = half.dot(normal);
            if half_cosine > 0.0 {
                let exponent = 1.0 / finish.roughness;
                lit.highlights += finish.specular * half_cosine.powf(exponent) * colour * tint;
            }
        }
    }
    lit
}
