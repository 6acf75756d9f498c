//! Finish and interior blocks: `finish { .. }`, `reflection { .. }`, `interior { .. }`.
//!
//! In: the items of the block. Out: a [`Finish`] or [`Interior`]. Holds: values start from
//! the given base (or the default texture's finish) and keep POV-Ray's defaults otherwise.

use super::stream::Stream;
use super::value::Value;
use super::{EvalResult, Evaluator};
use crate::scene::{Finish, Interior};
use crate::syntax::ast::{BlockHead, Item};
use glam::DVec3;
use std::rc::Rc;

impl Evaluator {
    /// `finish { .. }`, starting from `base` (an object's current finish) or the default.
    pub(crate) fn eval_finish(
        &mut self,
        stream: &mut Stream,
        base: Option<Finish>,
    ) -> EvalResult<Finish> {
        let mut finish = base.unwrap_or_else(|| self.default_texture.finish.clone());
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "ambient" => finish.ambient = self.expect_rgb(stream)?,
                    "emission" => finish.emission = self.expect_rgb(stream)?,
                    "diffuse" => {
                        self.skip_albedo(stream)?;
                        finish.diffuse = self.expect_float(stream, "a float")?;
                        // An optional second value is the backside diffuse.
                        self.skip_optional_float(stream)?;
                    }
                    "brilliance" => finish.brilliance = self.expect_float(stream, "a float")?,
                    "phong" => {
                        self.skip_albedo(stream)?;
                        finish.phong = self.expect_float(stream, "a float")?
                    }
                    "phong_size" => finish.phong_size = self.expect_float(stream, "a float")?,
                    "specular" => {
                        self.skip_albedo(stream)?;
                        finish.specular = self.expect_float(stream, "a float")?
                    }
                    "roughness" => finish.roughness = self.expect_float(stream, "a float")?,
                    "metallic" => {
                        finish.metallic = match self.peek_item(stream)? {
                            Some(Item::Expr(_)) => self.expect_float(stream, "a float")?,
                            _ => 1.0,
                        }
                    }
                    "reflection" => finish.reflection = self.expect_rgb(stream)?,
                    "crand" | "reflection_exponent" | "irid_wavelength" => {
                        self.warn(
                            *span,
                            format!("finish `{word}` is not supported yet; it is ignored"),
                        );
                        let _ = self.expect_value(stream, "a value")?;
                    }
                    "conserve_energy" => {
                        let _ = self.optional_bool(stream)?;
                    }
                    "ior" | "refraction" | "caustics" | "fade_distance" | "fade_power" => {
                        self.warn(
                            *span,
                            format!("`{word}` inside `finish` is obsolete; put it in `interior`"),
                        );
                        let _ = self.expect_value(stream, "a value")?;
                    }
                    _ => return Err(self.unexpected_in(&item, "finish")),
                },
                Item::Block(block) => {
                    if let BlockHead::Word(w) = &block.head {
                        if &**w == "reflection" {
                            let mut body = Stream::new(block.body.clone());
                            finish.reflection = self.eval_reflection_block(&mut body)?;
                            continue;
                        }
                        if matches!(&**w, "irid" | "subsurface") {
                            self.warn(
                                block.head_span,
                                format!("`{w}` is not supported yet; it is ignored"),
                            );
                            continue;
                        }
                    }
                    return Err(self.unexpected_in(&item, "finish"));
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Finish(f) => finish = Rc::unwrap_or_clone(f),
                    _ => return Err(self.unexpected_in(&item, "finish")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "finish")),
            }
        }
        Ok(finish)
    }

    /// `reflection { [min,] max fresnel falloff exponent metallic }`: durer uses the
    /// maximum as a constant reflection for now.
    fn eval_reflection_block(&mut self, stream: &mut Stream) -> EvalResult<DVec3> {
        let mut values = Vec::new();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Expr(e) => {
                    let value = self.eval_expr(e)?;
                    values.push(self.to_colour(value, e.span())?.rgb_vec());
                }
                Item::Keyword(word, span) => {
                    self.warn(
                        *span,
                        format!("reflection `{word}` is not supported yet; it is ignored"),
                    );
                    if matches!(&**word, "falloff" | "exponent") {
                        let _ = self.expect_value(stream, "a value")?;
                    } else {
                        let _ = self.optional_bool(stream)?;
                    }
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "reflection")),
            }
        }
        Ok(values.last().copied().unwrap_or(DVec3::ZERO))
    }

    fn expect_rgb(&mut self, stream: &mut Stream) -> EvalResult<DVec3> {
        let (value, span) = self.expect_value(stream, "a float or colour")?;
        Ok(match value {
            Value::Float(f) => DVec3::splat(f),
            other => self.to_colour(other, span)?.rgb_vec(),
        })
    }

    fn skip_albedo(&mut self, stream: &mut Stream) -> EvalResult<()> {
        match self.next_item(stream)? {
            Some(Item::Keyword(w, _)) if &*w == "albedo" => {}
            Some(other) => stream.push_back(other),
            None => {}
        }
        Ok(())
    }

    fn skip_optional_float(&mut self, stream: &mut Stream) -> EvalResult<()> {
        match self.next_item(stream)? {
            Some(Item::Comma(_)) => {
                let _ = self.expect_float(stream, "a float")?;
            }
            Some(other) => stream.push_back(other),
            None => {}
        }
        Ok(())
    }

    /// `interior { ior .. }`.
    pub(crate) fn eval_interior(&mut self, stream: &mut Stream) -> EvalResult<Interior> {
        let mut interior = Interior::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "ior" => interior.ior = self.expect_float(stream, "a float")?,
                    "caustics" | "dispersion" | "dispersion_samples" | "fade_distance"
                    | "fade_power" | "fade_color" | "fade_colour" => {
                        self.warn(
                            *span,
                            format!("interior `{word}` is not supported yet; it is ignored"),
                        );
                        let _ = self.expect_value(stream, "a value")?;
                    }
                    _ => return Err(self.unexpected_in(&item, "interior")),
                },
                Item::Block(block) if matches!(&block.head, BlockHead::Word(w) if &**w == "media") =>
                {
                    self.warn(
                        block.head_span,
                        "`media` is not supported yet; it is ignored",
                    );
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Interior(i) => interior = Rc::unwrap_or_clone(i),
                    _ => return Err(self.unexpected_in(&item, "interior")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "interior")),
            }
        }
        Ok(interior)
    }
}
