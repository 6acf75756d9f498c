//! Light sources as POV-Ray defines them.
//!
//! In: nothing (data definitions). Out: [`LightSource`], [`Spotlight`], [`AreaLight`].
//! Holds: positions and directions in world space (in the carrying object's space for the
//! lights an object holds, `Object::lights`).

use super::Object;
use crate::math::Transform;
use glam::DVec3;
use std::sync::Arc;

/// A light source.
#[derive(Clone, Debug)]
pub struct LightSource {
    /// Position of the light.
    pub position: DVec3,
    /// Colour (intensity) of the light.
    pub colour: DVec3,
    /// A `shadowless` light is never blocked by objects.
    pub shadowless: bool,
    /// Spotlight cone (or cylinder), when the light is a spotlight or cylinder light.
    pub spotlight: Option<Spotlight>,
    /// `fade_distance`; 0 means no fading.
    pub fade_distance: f64,
    /// `fade_power`; 0 means no fading.
    pub fade_power: f64,
    /// `parallel`: the point the parallel light's rays run towards (`point_at`).
    pub parallel: Option<DVec3>,
    /// `area_light`: the array of point lights that softens shadows.
    pub area: Option<AreaLight>,
    /// `projected_through { object }`: light only passes where it crosses this object.
    pub projected_through: Option<Arc<Object>>,
    /// `looks_like { object }`: the light's visible shape, already at the light's position
    /// and marked `no_shadow`; evaluation adds it to the scene's objects.
    pub looks_like: Option<Arc<Object>>,
    /// `media_interaction` (default on): whether media scatter this light. durer has no
    /// media, so this changes nothing yet.
    pub media_interaction: bool,
    /// `media_attenuation` (default off): whether media along shadow rays dim this light.
    /// durer has no media, so this changes nothing yet.
    pub media_attenuation: bool,
    /// The id of the `light_group` the light was written in (it lights only that group's
    /// objects); `None` for a scene light.
    pub group: Option<u32>,
    /// The light's `photons { }` block: which photons it shoots.
    pub photons: super::LightPhotons,
}

impl LightSource {
    /// A plain point light of this colour at `position`.
    pub fn point(position: DVec3, colour: DVec3) -> LightSource {
        LightSource {
            position,
            colour,
            shadowless: false,
            spotlight: None,
            fade_distance: 0.0,
            fade_power: 0.0,
            parallel: None,
            area: None,
            projected_through: None,
            looks_like: None,
            media_interaction: true,
            media_attenuation: false,
            group: None,
            photons: super::LightPhotons::default(),
        }
    }

    /// The light moved by `t`: its position, aim, area axes, `looks_like` shape and
    /// `projected_through` object (a lamp union placed twice lights through each copy's
    /// shade, as povray renders it).
    pub fn transformed(&self, t: &Transform) -> LightSource {
        let mut light = self.clone();
        light.position = t.point_to_outer(light.position);
        if let Some(spot) = &mut light.spotlight {
            spot.point_at = t.point_to_outer(spot.point_at);
        }
        if let Some(target) = &mut light.parallel {
            *target = t.point_to_outer(*target);
        }
        if let Some(area) = &mut light.area {
            area.axis1 = t.vector_to_outer(area.axis1);
            area.axis2 = t.vector_to_outer(area.axis2);
        }
        if let Some(object) = &mut light.looks_like {
            let object = Arc::make_mut(object);
            object.transform_by(t);
        }
        if let Some(object) = &mut light.projected_through {
            Arc::make_mut(object).transform_by(t);
        }
        light
    }
}

/// The cone of a `spotlight`, or the beam of a `cylinder` light.
#[derive(Clone, Copy, Debug)]
pub struct Spotlight {
    /// The point the spotlight aims at.
    pub point_at: DVec3,
    /// Half-angle in degrees of the fully lit cone (default 30); for a cylinder light the
    /// radius of the fully lit beam (default 0.75).
    pub radius: f64,
    /// Half-angle in degrees where the light reaches zero (default 45); for a cylinder light
    /// the radius where it reaches zero (default 1).
    pub falloff: f64,
    /// Exponent sharpening the edge of the cone.
    pub tightness: f64,
    /// A `cylinder` light: the beam is bounded by a cylinder around the axis, not a cone.
    pub cylinder: bool,
}

/// `area_light <axis1>, <axis2>, size1, size2` and its modifiers.
#[derive(Clone, Copy, Debug)]
pub struct AreaLight {
    /// First edge of the light's rectangle (centred on the light's position).
    pub axis1: DVec3,
    /// Second edge of the rectangle.
    pub axis2: DVec3,
    /// Number of point lights along the first axis (at least 1).
    pub size1: u32,
    /// Number of point lights along the second axis (at least 1).
    pub size2: u32,
    /// `adaptive N`: subdivide the array at least N times, then only where corners differ;
    /// `None` tests every point light.
    pub adaptive: Option<u32>,
    /// `jitter`: each point light moves randomly within its cell.
    pub jitter: bool,
    /// `circular`: the rectangle is squashed into an ellipse.
    pub circular: bool,
    /// `orient`: the array turns to face each lit point.
    pub orient: bool,
    /// `area_illumination`: each point light also lights (diffuse and highlights) from its
    /// own position, not only from the centre.
    pub area_illumination: bool,
}
