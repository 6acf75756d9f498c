//! `light_source { .. }`: point lights, spotlights, cylinder, parallel and area lights and
//! their modifiers.
//!
//! In: the items of the block. Out: a [`LightSource`]. Holds: positions, `point_at`, area
//! axes and the `looks_like` object are transformed into world space as the block is read;
//! `looks_like` objects are moved to the light's position and cast no shadow.

use super::objects::apply_transform;
use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Block, BlockHead, Item};
use crate::{
    math::Transform,
    scene::{AreaLight, LightSource, Object, Spotlight},
};
use glam::DVec3;
use std::rc::Rc;
use std::sync::Arc;

/// POV-Ray's spotlight cone when none is given: `radius 30 falloff 45`.
const SPOTLIGHT_DEFAULT: (f64, f64) = (30.0, 45.0);

/// POV-Ray's cylinder beam when none is given: `radius 0.75 falloff 1`.
const CYLINDER_DEFAULT: (f64, f64) = (0.75, 1.0);

/// The largest number of point lights along one axis of an area light.
const MAX_AREA_SIZE: f64 = 257.0;

/// The area light modifiers a `light_source` block names, with where they were written.
#[derive(Default)]
struct AreaModifiers {
    jitter: bool,
    circular: Option<Span>,
    orient: Option<Span>,
    adaptive: Option<u32>,
    area_illumination: Option<(bool, Span)>,
}

impl Evaluator {
    pub(crate) fn eval_light(&mut self, stream: &mut Stream) -> EvalResult<LightSource> {
        let mut light = match self.peek_item(stream)? {
            Some(Item::Expr(_)) => {
                let (value, span) = self.expect_value(stream, "a position")?;
                match value {
                    Value::Light(l) => Rc::unwrap_or_clone(l),
                    other => {
                        let position = self.to_vector3(other, span)?;
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        let colour = self.to_colour(value, span)?;
                        LightSource::point(position, colour.rgb_vec())
                    }
                }
            }
            _ => return Err(self.block_ended_early(stream, "expected the light's position")),
        };
        let mut spot = light.spotlight.unwrap_or(Spotlight {
            point_at: light.parallel.unwrap_or(DVec3::Z),
            radius: SPOTLIGHT_DEFAULT.0,
            falloff: SPOTLIGHT_DEFAULT.1,
            tightness: 0.0,
            cylinder: false,
        });
        let mut is_spot = light.spotlight.is_some();
        let mut cone_given = (false, false);
        let mut area_modifiers = AreaModifiers::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    // `spotlight`, `cylinder` and `shadowless` replace each other: the last
                    // one wins.
                    "spotlight" | "cylinder" => {
                        is_spot = true;
                        light.shadowless = false;
                        spot.cylinder = &**word == "cylinder";
                        let (radius, falloff) = if spot.cylinder {
                            CYLINDER_DEFAULT
                        } else {
                            SPOTLIGHT_DEFAULT
                        };
                        if !cone_given.0 {
                            spot.radius = radius;
                        }
                        if !cone_given.1 {
                            spot.falloff = falloff;
                        }
                    }
                    "point_at" => spot.point_at = self.expect_vector(stream, "a vector")?,
                    "radius" => {
                        spot.radius = self.expect_float(stream, "an angle")?;
                        cone_given.0 = true;
                    }
                    "falloff" => {
                        spot.falloff = self.expect_float(stream, "an angle")?;
                        cone_given.1 = true;
                    }
                    "tightness" => spot.tightness = self.expect_float(stream, "a float")?,
                    "shadowless" => {
                        light.shadowless = true;
                        is_spot = false;
                    }
                    "parallel" => light.parallel = Some(spot.point_at),
                    "fade_distance" => {
                        light.fade_distance = self.expect_float(stream, "a float")?
                    }
                    "fade_power" => light.fade_power = self.expect_float(stream, "a float")?,
                    "color" | "colour" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        light.colour = self.to_colour(value, span)?.rgb_vec();
                    }
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        transform_light(&mut light, &mut spot, &t);
                    }
                    // Stored for media; durer has none yet, so neither changes the picture.
                    "media_interaction" => light.media_interaction = self.optional_bool(stream)?,
                    "media_attenuation" => light.media_attenuation = self.optional_bool(stream)?,
                    "area_light" => light.area = Some(self.eval_area_light(stream, light.area)?),
                    "jitter" => area_modifiers.jitter = true,
                    "circular" => area_modifiers.circular = Some(*span),
                    "orient" => area_modifiers.orient = Some(*span),
                    "adaptive" => {
                        let level = self.expect_float(stream, "a float")?;
                        area_modifiers.adaptive = Some(level.clamp(0.0, 30.0) as u32);
                    }
                    "area_illumination" => {
                        let on = self.optional_bool(stream)?;
                        area_modifiers.area_illumination = Some((on, *span));
                    }
                    _ => return Err(self.unexpected_in(&item, "light_source")),
                },
                Item::Block(block) => match &block.head {
                    BlockHead::Word(w) if &**w == "looks_like" => {
                        let mut object = self.single_object(block, "looks_like")?;
                        // Light leaves the shape: it casts no shadow.
                        object.no_shadow = true;
                        apply_transform(&mut object, &Transform::translation(light.position));
                        light.looks_like = Some(Arc::new(object));
                    }
                    BlockHead::Word(w) if &**w == "photons" => {
                        let mut body = Stream::new(block.body.clone());
                        self.eval_light_photons(&mut body, &mut light.photons)?;
                    }
                    BlockHead::Word(w) if &**w == "projected_through" => {
                        let mut object = self.single_object(block, "projected_through")?;
                        // Only the shape matters; povray warns and drops a texture.
                        if object.texture.take().is_some() {
                            self.runtime.warn(
                                block.head_span,
                                "a `projected_through` object cannot have a texture; it is \
                                 removed",
                            );
                        }
                        light.projected_through = Some(Arc::new(object));
                    }
                    _ => match self.eval_block(block)? {
                        Value::Transform(t) => transform_light(&mut light, &mut spot, &t),
                        Value::Nothing => {}
                        _ => return Err(self.unexpected_in(&item, "light_source")),
                    },
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "light_source")),
            }
        }
        if light.parallel.is_some() {
            light.parallel = Some(spot.point_at);
        }
        light.spotlight = is_spot.then_some(spot);
        self.apply_area_modifiers(&mut light, area_modifiers);
        Ok(light)
    }

    /// Gives the area light the modifiers the block named, before or after `area_light`
    /// (as in POV-Ray). Without an area light, `jitter` and `adaptive` are ignored silently
    /// and the others with a warning, as POV-Ray does.
    fn apply_area_modifiers(&mut self, light: &mut LightSource, modifiers: AreaModifiers) {
        let Some(area) = &mut light.area else {
            let ignored = [
                ("circular", modifiers.circular),
                ("orient", modifiers.orient),
                (
                    "area_illumination",
                    modifiers.area_illumination.map(|(_, span)| span),
                ),
            ];
            for (word, span) in ignored {
                if let Some(span) = span {
                    self.runtime.warn(
                        span,
                        format!("`{word}` only affects an area light; it is ignored"),
                    );
                }
            }
            return;
        };
        area.jitter |= modifiers.jitter;
        area.circular |= modifiers.circular.is_some();
        area.orient |= modifiers.orient.is_some();
        if let Some(level) = modifiers.adaptive {
            area.adaptive = Some(level);
        }
        if let Some((on, _)) = modifiers.area_illumination {
            area.area_illumination = on;
        }
    }

    /// `area_light <axis1>, <axis2>, size1, size2` (modifiers already given are kept).
    fn eval_area_light(
        &mut self,
        stream: &mut Stream,
        previous: Option<AreaLight>,
    ) -> EvalResult<AreaLight> {
        let axis1 = self.expect_vector(stream, "the first axis")?;
        self.skip_comma(stream)?;
        let axis2 = self.expect_vector(stream, "the second axis")?;
        self.skip_comma(stream)?;
        let (size1, span1) = self.expect_value(stream, "the number of lights along axis 1")?;
        let size1 = self.to_float(size1, span1)?;
        self.skip_comma(stream)?;
        let (size2, span2) = self.expect_value(stream, "the number of lights along axis 2")?;
        let size2 = self.to_float(size2, span2)?;
        let mut sizes = [0u32; 2];
        for (slot, (size, span)) in sizes.iter_mut().zip([(size1, span1), (size2, span2)]) {
            if !(1.0..=MAX_AREA_SIZE).contains(&size) {
                return Err(self
                    .runtime
                    .error(
                        span,
                        format!("an area light needs 1 to {MAX_AREA_SIZE} lights per axis"),
                    )
                    .with_label(format!("this is {size}"))
                    .into());
            }
            *slot = size as u32;
        }
        let mut area = previous.unwrap_or(AreaLight {
            axis1,
            axis2,
            size1: 1,
            size2: 1,
            adaptive: None,
            jitter: false,
            circular: false,
            orient: false,
            area_illumination: false,
        });
        area.axis1 = axis1;
        area.axis2 = axis2;
        area.size1 = sizes[0];
        area.size2 = sizes[1];
        Ok(area)
    }

    /// The one object in a `looks_like { .. }` or `projected_through { .. }` block.
    fn single_object(&mut self, block: &Block, word: &str) -> EvalResult<Object> {
        let mut body = Stream::new(block.body.clone());
        // `looks_like { Lamp_Ident translate T }`, `projected_through { Shade scale 2 }`:
        // povray reads the block as an `object { .. }` body, so a declared object may be
        // followed by object modifiers (measured).
        if self.starts_with_declared_object(&mut body)? {
            if let Some(object) = self.eval_object("object", block, &mut body)? {
                return Ok(object);
            }
        }
        let mut found = None;
        while let Some(item) = self.next_item(&mut body)? {
            match &item {
                Item::Comma(_) => {}
                Item::Block(_) | Item::Expr(_) if found.is_none() => {
                    match self.item_value(&item)? {
                        Value::Object(object) => found = Some(Arc::unwrap_or_clone(object)),
                        _ => return Err(self.unexpected_in(&item, word)),
                    }
                }
                _ => return Err(self.unexpected_in(&item, word)),
            }
        }
        found.ok_or_else(|| {
            self.runtime
                .error(block.span, format!("`{word}` needs an object"))
                .with_label("no object inside")
                .into()
        })
    }
}

/// Moves a light (and its aim, area axes, `looks_like` and `projected_through` objects)
/// by `t`.
fn transform_light(light: &mut LightSource, spot: &mut Spotlight, t: &Transform) {
    light.position = t.point_to_outer(light.position);
    spot.point_at = t.point_to_outer(spot.point_at);
    if let Some(area) = &mut light.area {
        area.axis1 = t.vector_to_outer(area.axis1);
        area.axis2 = t.vector_to_outer(area.axis2);
    }
    if let Some(object) = &mut light.looks_like {
        apply_transform(Arc::make_mut(object), t);
    }
    // The `projected_through` object moves with the light too, when it was given before
    // the transformation, as povray renders it (`light_source { .. projected_through
    // { A } translate T }` lights through A moved by T).
    if let Some(object) = &mut light.projected_through {
        apply_transform(Arc::make_mut(object), t);
    }
}
