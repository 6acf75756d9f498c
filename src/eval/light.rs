//! `light_source { .. }`: point lights, spotlights and their modifiers.
//!
//! In: the items of the block. Out: a [`LightSource`]. Holds: positions are transformed into
//! world space as the block is read.

use super::stream::Stream;
use super::value::Value;
use super::{EvalResult, Evaluator};
use crate::scene::{LightSource, Spotlight};
use crate::syntax::ast::Item;
use glam::DVec3;
use std::rc::Rc;

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
                        LightSource {
                            position,
                            colour: colour.rgb_vec(),
                            shadowless: false,
                            spotlight: None,
                            fade_distance: 0.0,
                            fade_power: 0.0,
                        }
                    }
                }
            }
            _ => {
                return Err(self
                    .error(self.stream_end_span(), "expected the light's position")
                    .into())
            }
        };
        let mut spot = Spotlight {
            point_at: DVec3::Z,
            radius: 30.0,
            falloff: 45.0,
            tightness: 0.0,
        };
        let mut is_spot = light.spotlight.is_some();
        if let Some(s) = light.spotlight {
            spot = s;
        }
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    // `spotlight` and `shadowless` replace each other: the last one wins.
                    "spotlight" => {
                        is_spot = true;
                        light.shadowless = false;
                    }
                    "point_at" => spot.point_at = self.expect_vector(stream, "a vector")?,
                    "radius" => spot.radius = self.expect_float(stream, "an angle")?,
                    "falloff" => spot.falloff = self.expect_float(stream, "an angle")?,
                    "tightness" => spot.tightness = self.expect_float(stream, "a float")?,
                    "shadowless" => {
                        light.shadowless = true;
                        is_spot = false;
                    }
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
                        light.position = t.point_to_outer(light.position);
                        spot.point_at = t.point_to_outer(spot.point_at);
                    }
                    "media_interaction" | "media_attenuation" => {
                        let _ = self.optional_bool(stream)?;
                    }
                    "area_light" => {
                        self.warn(*span, "`area_light` is not supported yet; a point light at its centre is used");
                        for what in ["the first axis", "the second axis", "a size", "a size"] {
                            let _ = self.expect_value(stream, what)?;
                        }
                    }
                    "jitter" | "circular" | "orient" | "parallel" | "cylinder" => {
                        self.warn(
                            *span,
                            format!("light source `{word}` is not supported yet; it is ignored"),
                        );
                    }
                    "adaptive" | "area_illumination" => {
                        self.warn(
                            *span,
                            format!("light source `{word}` is not supported yet; it is ignored"),
                        );
                        let _ = self.optional_bool(stream)?;
                    }
                    _ => return Err(self.unexpected_in(&item, "light_source")),
                },
                Item::Block(block) => match self.eval_block(block)? {
                    Value::Transform(t) => {
                        light.position = t.point_to_outer(light.position);
                        spot.point_at = t.point_to_outer(spot.point_at);
                    }
                    Value::Nothing => {}
                    _ => return Err(self.unexpected_in(&item, "light_source")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "light_source")),
            }
        }
        light.spotlight = is_spot.then_some(spot);
        Ok(light)
    }
}
