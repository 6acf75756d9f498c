//! `fog`, `sky_sphere` and `rainbow` blocks.
//!
//! In: the items of one block. Out: an [`AtmosphericEffect`] with POV-Ray's defaults filled
//! in. Holds: transformations are folded into the effect (fog `up` and rainbow vectors are
//! transformed; the sky sphere keeps its transform for pattern lookups).

use crate::eval::language::stream::Stream;
use crate::eval::language::value::{AtmosphericEffect, Value};
use crate::eval::{EvalResult, Evaluator};
use crate::noise::TurbulenceShape;
use crate::syntax::ast::{BlockHead, Item};
use crate::{
    math::{Colour, Transform},
    scene::{Fog, FogKind, FogTurbulence, Rainbow, SkySphere},
};
use glam::DVec3;
use std::rc::Rc;

/// POV-Ray's rainbow distance when none is given: far enough that objects show no bow.
const DEFAULT_RAINBOW_DISTANCE: f64 = 1e7;

impl Evaluator {
    /// `fog { [FOG_IDENTIFIER] ITEMS }`.
    pub(crate) fn eval_fog(&mut self, stream: &mut Stream) -> EvalResult<Fog> {
        let mut fog = Fog {
            kind: FogKind::Constant,
            distance: 0.0,
            colour: Colour::BLACK,
            up: DVec3::Y,
            turbulence: None,
        };
        let mut fog_type = 1.0;
        let (mut offset, mut altitude) = (0.0, 0.0);
        let mut turbulence: Option<DVec3> = None;
        let mut depth = 0.5;
        let mut shape = TurbulenceShape::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "fog_type" => {
                        let (value, value_span) = self.expect_value(stream, "1 or 2")?;
                        fog_type = self.to_float(value, value_span)?;
                        if fog_type != 1.0 && fog_type != 2.0 {
                            return Err(self
                                .runtime
                                .error(value_span, format!("unknown fog_type {fog_type}"))
                                .with_label("expected 1 (constant) or 2 (ground fog)")
                                .into());
                        }
                    }
                    "distance" => fog.distance = self.expect_float(stream, "a distance")?,
                    "fog_offset" => offset = self.expect_float(stream, "a float")?,
                    "fog_alt" => altitude = self.expect_float(stream, "a float")?,
                    "turb_depth" => depth = self.expect_float(stream, "a float")?,
                    "turbulence" => turbulence = Some(self.expect_vector(stream, "a vector")?),
                    "octaves" => {
                        let octaves = self.expect_float(stream, "a float")?;
                        shape.octaves = octaves.clamp(1.0, 10.0) as u32;
                    }
                    "omega" => shape.omega = self.expect_float(stream, "a float")?,
                    "lambda" => shape.lambda = self.expect_float(stream, "a float")?,
                    "up" => fog.up = self.expect_vector(stream, "a vector")?,
                    "color" | "colour" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        fog.colour = self.to_colour(value, span)?;
                    }
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        transform_fog(&mut fog, &t);
                    }
                    _ => return Err(self.unexpected_in(&item, "fog")),
                },
                Item::Block(block) => match self.eval_block(block)? {
                    Value::Transform(t) => transform_fog(&mut fog, &t),
                    _ => return Err(self.unexpected_in(&item, "fog")),
                },
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Atmospheric(effect) => match &*effect {
                        AtmosphericEffect::Fog(declared) => {
                            fog = declared.clone();
                            if let FogKind::Ground {
                                offset: o,
                                altitude: a,
                            } = fog.kind
                            {
                                (fog_type, offset, altitude) = (2.0, o, a);
                            }
                            if let Some(t) = fog.turbulence {
                                (turbulence, depth, shape) = (Some(t.amount), t.depth, t.shape);
                            }
                        }
                        _ => return Err(self.unexpected_in(&item, "fog")),
                    },
                    value @ (Value::Colour(_) | Value::Vector(_) | Value::Float(_)) => {
                        fog.colour = self.to_colour(value, expr.span())?
                    }
                    _ => return Err(self.unexpected_in(&item, "fog")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "fog")),
            }
        }
        fog.kind = if fog_type == 2.0 {
            FogKind::Ground { offset, altitude }
        } else {
            FogKind::Constant
        };
        fog.turbulence = turbulence.map(|amount| FogTurbulence {
            amount,
            depth,
            shape,
        });
        Ok(fog)
    }

    /// `sky_sphere { [SKY_SPHERE_IDENTIFIER] pigment {..}.. [emission C] TRANSFORMATIONS }`.
    pub(crate) fn eval_sky_sphere(&mut self, stream: &mut Stream) -> EvalResult<SkySphere> {
        let mut sky = SkySphere {
            pigments: Vec::new(),
            emission: DVec3::ONE,
            transform: Transform::IDENTITY,
        };
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "emission" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        sky.emission = self.to_colour(value, span)?.rgb_vec();
                    }
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        sky.transform = sky.transform.then(&t);
                    }
                    _ => return Err(self.unexpected_in(&item, "sky_sphere")),
                },
                Item::Block(block) => {
                    let is_pigment = matches!(&block.head, BlockHead::Word(w) if &**w == "pigment");
                    match self.eval_block(block)? {
                        Value::Pigment(pigment) if is_pigment => {
                            sky.pigments.push(Rc::unwrap_or_clone(pigment))
                        }
                        Value::Transform(t) => sky.transform = sky.transform.then(&t),
                        _ => return Err(self.unexpected_in(&item, "sky_sphere")),
                    }
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Atmospheric(effect) => match &*effect {
                        AtmosphericEffect::SkySphere(declared) => sky = declared.clone(),
                        _ => return Err(self.unexpected_in(&item, "sky_sphere")),
                    },
                    _ => return Err(self.unexpected_in(&item, "sky_sphere")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "sky_sphere")),
            }
        }
        Ok(sky)
    }

    /// `rainbow { [RAINBOW_IDENTIFIER] ITEMS }`.
    pub(crate) fn eval_rainbow(&mut self, stream: &mut Stream) -> EvalResult<Rainbow> {
        let mut rainbow = Rainbow {
            direction: DVec3::Z,
            angle: 0.0,
            width: 0.0,
            distance: DEFAULT_RAINBOW_DISTANCE,
            colour_map: Vec::new(),
            jitter: 0.0,
            up: DVec3::Y,
            // A full circle by default (measured; the manual says 180).
            arc_angle: 360.0,
            falloff_angle: 360.0,
        };
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "direction" => rainbow.direction = self.expect_vector(stream, "a vector")?,
                    "angle" => rainbow.angle = self.expect_float(stream, "an angle")?,
                    "width" => rainbow.width = self.expect_float(stream, "an angle")?,
                    "distance" => rainbow.distance = self.expect_float(stream, "a distance")?,
                    "jitter" => rainbow.jitter = self.expect_float(stream, "a float")?,
                    "up" => rainbow.up = self.expect_vector(stream, "a vector")?,
                    "arc_angle" => rainbow.arc_angle = self.expect_float(stream, "an angle")?,
                    "falloff_angle" => {
                        rainbow.falloff_angle = self.expect_float(stream, "an angle")?
                    }
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        transform_rainbow(&mut rainbow, &t);
                    }
                    _ => return Err(self.unexpected_in(&item, "rainbow")),
                },
                Item::Block(block) => match self.eval_block(block)? {
                    Value::ColourMap(map) => rainbow.colour_map = (*map).clone(),
                    Value::Transform(t) => transform_rainbow(&mut rainbow, &t),
                    _ => return Err(self.unexpected_in(&item, "rainbow")),
                },
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Atmospheric(effect) => match &*effect {
                        AtmosphericEffect::Rainbow(declared) => rainbow = declared.clone(),
                        _ => return Err(self.unexpected_in(&item, "rainbow")),
                    },
                    Value::ColourMap(map) => rainbow.colour_map = (*map).clone(),
                    _ => return Err(self.unexpected_in(&item, "rainbow")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "rainbow")),
            }
        }
        Ok(rainbow)
    }
}

/// Applies a transformation to a fog: `up` turns with it (the turbulence stays in world
/// space, as POV-Ray's does).
fn transform_fog(fog: &mut Fog, t: &Transform) {
    fog.up = t.vector_to_outer(fog.up);
}

/// Applies a transformation to a rainbow's direction and up vectors.
fn transform_rainbow(rainbow: &mut Rainbow, t: &Transform) {
    rainbow.direction = t.vector_to_outer(rainbow.direction);
    rainbow.up = t.vector_to_outer(rainbow.up);
}
