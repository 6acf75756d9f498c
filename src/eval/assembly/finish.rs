//! Finish and interior blocks: `finish { .. }`, `reflection { .. }`, `irid { .. }`,
//! `interior { .. }`.
//!
//! In: the items of the block. Out: a [`Finish`] or [`Interior`]. Holds: values start from
//! the given base (or the default texture's finish) and keep POV-Ray's defaults otherwise.
//!
//! `albedo` amounts are converted to the peak amounts shading uses when the block ends
//! (measured in POV-Ray 3.7): diffuse `D (b + 1) / 2` with brilliance b; phong
//! `P (s + 1) / 2` with phong_size s; specular `S (n + 2) / (8 (1 − 2^(−(n + 2)/2)))` with
//! n = 1 / roughness.

use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{BlockHead, Item};
use crate::{
    scene::Interior,
    texture::finish::{Finish, Irid, Subsurface},
};
use glam::DVec3;
use std::rc::Rc;

/// Which amounts of a finish block were given as `albedo`.
#[derive(Clone, Copy, Default)]
struct Albedo {
    diffuse: bool,
    phong: bool,
    specular: bool,
}

impl Evaluator {
    /// `finish { .. }`, starting from `base` (an object's current finish) or the default.
    pub(crate) fn eval_finish(
        &mut self,
        stream: &mut Stream,
        base: Option<Finish>,
    ) -> EvalResult<Finish> {
        let mut finish = base.unwrap_or_else(|| Finish::clone(&self.scene.default_texture.finish));
        let mut albedo = Albedo::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "ambient" => finish.ambient = self.expect_rgb(stream)?,
                    "emission" => finish.emission = self.expect_rgb(stream)?,
                    "diffuse" => {
                        albedo.diffuse = self.skip_albedo(stream)?;
                        finish.diffuse = self.expect_float(stream, "a float")?;
                        // An optional second value is the backside diffuse.
                        if let Some(back) = self.optional_second_float(stream)? {
                            finish.diffuse_back = back;
                        }
                    }
                    "brilliance" => finish.brilliance = self.expect_float(stream, "a float")?,
                    "crand" => finish.crand = self.expect_float(stream, "a float")?,
                    "phong" => {
                        albedo.phong = self.skip_albedo(stream)?;
                        finish.phong = self.expect_float(stream, "a float")?
                    }
                    "phong_size" => finish.phong_size = self.expect_float(stream, "a float")?,
                    "specular" => {
                        albedo.specular = self.skip_albedo(stream)?;
                        finish.specular = self.expect_float(stream, "a float")?
                    }
                    "roughness" => finish.roughness = self.expect_float(stream, "a float")?,
                    "metallic" => finish.metallic = self.optional_finish_amount(stream)?,
                    "reflection" => {
                        finish.reflection = self.expect_rgb(stream)?;
                        finish.reflection_min = None;
                    }
                    "reflection_exponent" => {
                        finish.reflection_exponent = self.expect_float(stream, "a float")?
                    }
                    "reflect_metallic" => {
                        finish.reflect_metallic = self.optional_finish_amount(stream)?
                    }
                    "conserve_energy" => finish.conserve_energy = self.optional_bool(stream)?,
                    "irid_wavelength" => {
                        self.runtime.warn(
                            *span,
                            "`irid_wavelength` belongs in `global_settings`; it is ignored here",
                        );
                        let _ = self.expect_value(stream, "a colour")?;
                    }
                    "ior" | "refraction" | "caustics" | "fade_distance" | "fade_power" => {
                        self.runtime.warn(
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
                            self.eval_reflection_block(&mut body, &mut finish)?;
                            continue;
                        }
                        if &**w == "irid" {
                            let mut body = Stream::new(block.body.clone());
                            finish.irid = Some(self.eval_irid(&mut body, finish.irid)?);
                            continue;
                        }
                        if &**w == "subsurface" {
                            let mut body = Stream::new(block.body.clone());
                            finish.subsurface =
                                Some(self.eval_finish_subsurface(&mut body, finish.subsurface)?);
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
        apply_albedo(&mut finish, albedo);
        Ok(finish)
    }

    /// `reflection { [min,] max fresnel falloff exponent metallic }`.
    fn eval_reflection_block(
        &mut self,
        stream: &mut Stream,
        finish: &mut Finish,
    ) -> EvalResult<()> {
        let mut colours = Vec::new();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Expr(e) => {
                    let value = self.eval_expr(e)?;
                    colours.push(match value {
                        Value::Float(f) => DVec3::splat(f),
                        other => self.to_colour(other, e.span())?.rgb_vec(),
                    });
                }
                Item::Keyword(word, _) => match &**word {
                    "fresnel" => finish.fresnel = self.optional_bool(stream)?,
                    "falloff" => {
                        finish.reflection_falloff = self.expect_float(stream, "a float")?
                    }
                    "exponent" => {
                        finish.reflection_exponent = self.expect_float(stream, "a float")?
                    }
                    "metallic" => finish.reflect_metallic = self.optional_finish_amount(stream)?,
                    _ => return Err(self.unexpected_in(&item, "reflection")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "reflection")),
            }
        }
        match colours[..] {
            [] => {}
            [only] => {
                finish.reflection = only;
                finish.reflection_min = None;
            }
            [.., min, max] => {
                finish.reflection = max;
                finish.reflection_min = Some(min);
            }
        }
        Ok(())
    }

    /// `irid { amount thickness T turbulence U }`.
    fn eval_irid(&mut self, stream: &mut Stream, base: Option<Irid>) -> EvalResult<Irid> {
        let mut irid = base.unwrap_or(Irid {
            amount: 0.0,
            thickness: 0.0,
            turbulence: 0.0,
            wavelengths: self.scene.settings.scene_irid_wavelengths.clone(),
            noise_generator: self.scene.settings.scene_noise_generator.clone(),
        });
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Expr(e) => {
                    let value = self.eval_expr(e)?;
                    irid.amount = self.to_float(value, e.span())?;
                }
                Item::Keyword(word, _) => match &**word {
                    "thickness" => irid.thickness = self.expect_float(stream, "a float")?,
                    "turbulence" => irid.turbulence = self.expect_float(stream, "a float")?,
                    _ => return Err(self.unexpected_in(&item, "irid")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "irid")),
            }
        }
        Ok(irid)
    }

    /// `subsurface { translucency C anisotropy G }` in a finish (both colours or floats;
    /// an empty block is allowed, as POV-Ray parses it).
    fn eval_finish_subsurface(
        &mut self,
        stream: &mut Stream,
        base: Option<Subsurface>,
    ) -> EvalResult<Subsurface> {
        let mut subsurface = base.unwrap_or(Subsurface {
            translucency: DVec3::ZERO,
            anisotropy: DVec3::ZERO,
        });
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) => match &**word {
                    "translucency" => subsurface.translucency = self.expect_rgb(stream)?,
                    "anisotropy" => subsurface.anisotropy = self.expect_rgb(stream)?,
                    _ => return Err(self.unexpected_in(&item, "subsurface")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "subsurface")),
            }
        }
        Ok(subsurface)
    }

    fn expect_rgb(&mut self, stream: &mut Stream) -> EvalResult<DVec3> {
        let (value, span) = self.expect_value(stream, "a float or colour")?;
        Ok(match value {
            Value::Float(f) => DVec3::splat(f),
            other => self.to_colour(other, span)?.rgb_vec(),
        })
    }

    /// Skips an `albedo` keyword; tells whether there was one.
    fn skip_albedo(&mut self, stream: &mut Stream) -> EvalResult<bool> {
        match self.next_item(stream)? {
            Some(Item::Keyword(w, _)) if &*w == "albedo" => return Ok(true),
            Some(other) => stream.push_back(other),
            None => {}
        }
        Ok(false)
    }

    /// `, value` after a first value, if there is one.
    fn optional_second_float(&mut self, stream: &mut Stream) -> EvalResult<Option<f64>> {
        match self.next_item(stream)? {
            Some(Item::Comma(_)) => Ok(Some(self.expect_float(stream, "a float")?)),
            // Without the comma too (`diffuse 0.8 0`, Blender's exporter; povray reads it).
            Some(Item::Expr(expr)) => {
                let value = self.eval_expr(&expr)?;
                Ok(Some(self.to_float(value, expr.span())?))
            }
            Some(other) => {
                stream.push_back(other);
                Ok(None)
            }
            None => Ok(None),
        }
    }

    /// An optional amount after a keyword such as `metallic` (1 when left out).
    fn optional_finish_amount(&mut self, stream: &mut Stream) -> EvalResult<f64> {
        match self.peek_item(stream)? {
            Some(Item::Expr(_)) => self.expect_float(stream, "a float"),
            _ => Ok(1.0),
        }
    }

    /// `interior { ior dispersion dispersion_samples fade_distance fade_power fade_color
    /// caustics }`.
    pub(crate) fn eval_interior(&mut self, stream: &mut Stream) -> EvalResult<Interior> {
        let mut interior = Interior::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) => match &**word {
                    "ior" => interior.ior = self.expect_float(stream, "a float")?,
                    "dispersion" => interior.dispersion = self.expect_float(stream, "a float")?,
                    "dispersion_samples" => {
                        let samples = self.expect_float(stream, "a float")?;
                        interior.dispersion_samples = samples.clamp(2.0, 1000.0) as u32;
                    }
                    "fade_distance" => {
                        interior.fade_distance = self.expect_float(stream, "a float")?
                    }
                    "fade_power" => interior.fade_power = self.expect_float(stream, "a float")?,
                    "fade_color" | "fade_colour" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        interior.fade_colour = self.to_colour(value, span)?.rgb_vec();
                    }
                    "caustics" => interior.caustics = self.expect_float(stream, "a float")?,
                    _ => return Err(self.unexpected_in(&item, "interior")),
                },
                Item::Block(block) if matches!(&block.head, BlockHead::Word(w) if &**w == "media") =>
                {
                    let mut body = Stream::new(block.body.clone());
                    interior.media.push(self.eval_media(&mut body)?);
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

/// Converts the amounts given as `albedo` into peak amounts.
fn apply_albedo(finish: &mut Finish, albedo: Albedo) {
    if albedo.diffuse {
        finish.diffuse *= (finish.brilliance + 1.0) / 2.0;
    }
    if albedo.phong {
        finish.phong *= (finish.phong_size + 1.0) / 2.0;
    }
    if albedo.specular {
        let exponent = 1.0 / finish.roughness;
        let scale = (exponent + 2.0) / (8.0 * (1.0 - (-(exponent + 2.0) / 2.0).exp2()));
        if scale.is_finite() {
            finish.specular *= scale;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn albedo_conversions_match_povray_measurements() {
        let mut finish = Finish {
            diffuse: 0.5,
            brilliance: 2.0,
            phong: 0.1,
            phong_size: 10.0,
            specular: 0.1,
            roughness: 0.1,
            ..Finish::default()
        };
        apply_albedo(
            &mut finish,
            Albedo {
                diffuse: true,
                phong: true,
                specular: true,
            },
        );
        assert!((finish.diffuse - 0.75).abs() < 1e-12);
        assert!((finish.phong - 0.55).abs() < 1e-12);
        // POV-Ray 3.7 renders 0.1524 (roughness 0.1) and 0.2751 (roughness 0.05).
        assert!((finish.specular - 0.1524).abs() < 1e-4);
        let mut default_roughness = Finish {
            specular: 0.1,
            ..Finish::default()
        };
        let only_specular = Albedo {
            specular: true,
            ..Albedo::default()
        };
        apply_albedo(&mut default_roughness, only_specular);
        assert!((default_roughness.specular - 0.2751).abs() < 1e-4);
    }
}
