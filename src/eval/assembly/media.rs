//! `media { }` and `density { }` blocks.
//!
//! In: the items of the block. Out: a [`Media`], or a density as a [`Pigment`] whose grey
//! value is the density (POV-Ray's densities are colours: a `color_map` tints the media).
//! Holds: values start from POV-Ray's defaults or from the identifier written first;
//! transformations move only the densities written before them (manual: "Media").

use super::appearance::{grey_ramp, modified_pattern};
use crate::eval::language::stream::Stream;
use crate::eval::language::value::AppearanceMap;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{BlockHead, Item};
use crate::{
    math::{Colour, Transform},
    scene::{Media, Scattering, ScatteringKind},
    texture::{Pigment, PigmentMap},
};
use std::rc::Rc;

/// The largest `samples`, `intervals` and `aa_level` accepted (POV-Ray's own limits are
/// similar; more only costs time).
const MAX_SAMPLES: f64 = 10_000.0;
const MAX_INTERVALS: f64 = 1_000.0;
const MAX_AA_LEVEL: f64 = 16.0;

impl Evaluator {
    /// `media { [Ident] method intervals samples ... absorption emission scattering density
    /// transforms }`.
    pub(crate) fn eval_media(&mut self, stream: &mut Stream) -> EvalResult<Media> {
        let mut media = Media::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "method" => {
                        let method = self.expect_float(stream, "a float")?;
                        if !(1.0..=3.0).contains(&method) {
                            return Err(self
                                .runtime
                                .error(*span, "the media `method` must be 1, 2 or 3")
                                .into());
                        }
                        media.method = method as u32;
                    }
                    "intervals" => {
                        let count = self.expect_float(stream, "a float")?;
                        media.intervals = count.clamp(1.0, MAX_INTERVALS) as u32;
                    }
                    "samples" => {
                        let min = self.expect_float(stream, "a float")?;
                        self.skip_comma(stream)?;
                        let max = match self.peek_item(stream)? {
                            Some(Item::Expr(_)) => self.expect_float(stream, "a float")?,
                            _ => min,
                        };
                        let min = min.clamp(1.0, MAX_SAMPLES) as u32;
                        media.samples = (min, (max.clamp(1.0, MAX_SAMPLES) as u32).max(min));
                    }
                    "confidence" => media.confidence = self.expect_float(stream, "a float")?,
                    "variance" => media.variance = self.expect_float(stream, "a float")?,
                    "ratio" => media.ratio = self.expect_float(stream, "a float")?,
                    "jitter" => media.jitter = self.expect_float(stream, "a float")?,
                    "aa_threshold" => media.aa_threshold = self.expect_float(stream, "a float")?,
                    "aa_level" => {
                        let level = self.expect_float(stream, "a float")?;
                        media.aa_level = level.clamp(0.0, MAX_AA_LEVEL) as u32;
                    }
                    "absorption" => media.absorption = self.expect_media_colour(stream)?,
                    "emission" => media.emission = self.expect_media_colour(stream)?,
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        media.transform(&t);
                    }
                    _ => return Err(self.unexpected_in(&item, "media")),
                },
                Item::Block(block) => {
                    let head = match &block.head {
                        BlockHead::Word(w) => &**w,
                        _ => "",
                    };
                    let mut body = Stream::new(block.body.clone());
                    match head {
                        "scattering" => media.scattering = Some(self.eval_scattering(&mut body)?),
                        "density" => media.densities.push(self.eval_density(&mut body)?),
                        "transform" => {
                            let t = self.eval_transform_block(&mut body)?;
                            media.transform(&t);
                        }
                        _ => return Err(self.unexpected_in(&item, "media")),
                    }
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Media(declared) => media = Rc::unwrap_or_clone(declared),
                    Value::Transform(t) => media.transform(&t),
                    _ => return Err(self.unexpected_in(&item, "media")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "media")),
            }
        }
        Ok(media)
    }

    /// A media colour (`absorption`, `emission`): its red, green and blue.
    fn expect_media_colour(&mut self, stream: &mut Stream) -> EvalResult<glam::DVec3> {
        let (value, span) = self.expect_value(stream, "a colour")?;
        Ok(self.to_colour(value, span)?.rgb_vec())
    }

    /// `scattering { type, colour [eccentricity e] [extinction x] }`.
    fn eval_scattering(&mut self, stream: &mut Stream) -> EvalResult<Scattering> {
        let (value, type_span) = self.expect_value(stream, "the scattering type (1 to 5)")?;
        let kind_number = self.to_float(value, type_span)?;
        self.skip_comma(stream)?;
        let colour = self.expect_media_colour(stream)?;
        let mut eccentricity = 0.0;
        let mut extinction = 1.0;
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) if &**word == "eccentricity" => {
                    eccentricity = self.expect_float(stream, "a float")?
                }
                Item::Keyword(word, _) if &**word == "extinction" => {
                    extinction = self.expect_float(stream, "a float")?
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "scattering")),
            }
        }
        let kind = match kind_number.round() as i64 {
            1 => ScatteringKind::Isotropic,
            2 => ScatteringKind::MieHazy,
            3 => ScatteringKind::MieMurky,
            4 => ScatteringKind::Rayleigh,
            5 => ScatteringKind::HenyeyGreenstein(eccentricity),
            _ => {
                return Err(self
                    .runtime
                    .error(type_span, "the scattering type must be 1 to 5")
                    .with_label(
                        "1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein",
                    )
                    .into())
            }
        };
        Ok(Scattering {
            kind,
            colour,
            extinction,
        })
    }

    /// `density { [Ident] [pattern] [modifiers] [color_map | density_map | density list] }`:
    /// constant 1 unless a pattern or colour says otherwise; a pattern without a map gives
    /// its value as the density.
    pub(crate) fn eval_density(&mut self, stream: &mut Stream) -> EvalResult<Pigment> {
        let mut density = Pigment::Solid(Colour::WHITE);
        let mut colour_map: Option<Vec<(f64, Colour)>> = None;
        while let Some(item) = self.next_item(stream)? {
            if let Some((spec, list)) = self.block_pattern(&item)? {
                let map = match (spec.block_count(), list) {
                    (Some(count), Some(mut list)) => {
                        PigmentMap::Blocks(self.density_list(&mut list, count)?)
                    }
                    _ => PigmentMap::Colours(grey_ramp()),
                };
                density = Pigment::Pattern {
                    pattern: Box::new(spec),
                    map,
                    transform: Transform::IDENTITY,
                };
                continue;
            }
            if let Item::Keyword(word, span) = &item {
                if let Some(spec) =
                    self.pattern_keyword_outside_normal(word, *span, stream, "density")?
                {
                    let map = match spec.block_count() {
                        Some(count) => PigmentMap::Blocks(self.density_list(stream, count)?),
                        None => PigmentMap::Colours(grey_ramp()),
                    };
                    density = Pigment::Pattern {
                        pattern: Box::new(spec),
                        map,
                        transform: Transform::IDENTITY,
                    };
                    continue;
                }
                if let Some(pattern) =
                    modified_pattern(&mut density, &self.scene.settings.scene_noise_generator)
                {
                    if self.pattern_modifier(word, *span, stream, pattern)? {
                        continue;
                    }
                }
                if matches!(
                    &**word,
                    "translate" | "rotate" | "scale" | "matrix" | "transform"
                ) {
                    let t = self.transform_keyword(word, *span, stream)?;
                    if let Pigment::Pattern { pattern, .. } = &mut density {
                        pattern.note_transform(&t);
                    }
                    density.transform(&t);
                    continue;
                }
                return Err(self.unexpected_in(&item, "density"));
            }
            match &item {
                Item::Block(block) => {
                    if let Some(pattern) =
                        modified_pattern(&mut density, &self.scene.settings.scene_noise_generator)
                    {
                        if self.pattern_block(block, pattern)? {
                            continue;
                        }
                    }
                    let head = match &block.head {
                        BlockHead::Word(w) => &**w,
                        _ => "",
                    };
                    let mut body = Stream::new(block.body.clone());
                    match head {
                        "color_map" | "colour_map" => {
                            colour_map = Some(self.eval_colour_map(&mut body)?)
                        }
                        "density_map" => {
                            let entries = self.eval_density_map(&mut body)?;
                            match &mut density {
                                Pigment::Pattern { map, transform, .. } => {
                                    let mut entries = entries;
                                    for (_, entry) in &mut entries {
                                        entry.transform(transform);
                                    }
                                    *map = PigmentMap::Pigments(entries);
                                }
                                _ => {
                                    return Err(self
                                        .runtime
                                        .error(
                                            block.head_span,
                                            "a `density_map` needs a pattern before it",
                                        )
                                        .with_label("no pattern in this density yet")
                                        .into())
                                }
                            }
                        }
                        "transform" => {
                            let t = self.eval_transform_block(&mut body)?;
                            density.transform(&t);
                        }
                        _ => return Err(self.unexpected_in(&item, "density")),
                    }
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Density(declared) => density = Rc::unwrap_or_clone(declared),
                    Value::ColourMap(map) => colour_map = Some((*map).clone()),
                    Value::Transform(t) => density.transform(&t),
                    value @ (Value::Colour(_) | Value::Float(_) | Value::Vector(_)) => {
                        density = Pigment::Solid(self.to_colour(value, expr.span())?)
                    }
                    _ => return Err(self.unexpected_in(&item, "density")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "density")),
            }
        }
        if let (
            Pigment::Pattern {
                map: PigmentMap::Colours(entries),
                ..
            },
            Some(map),
        ) = (&mut density, colour_map)
        {
            *entries = map;
        }
        Ok(density)
    }

    /// `density_map { [key density-body] .. }`.
    pub(super) fn eval_density_map(
        &mut self,
        stream: &mut Stream,
    ) -> EvalResult<Vec<(f64, Pigment)>> {
        self.eval_map(
            stream,
            "density_map",
            |this, body| this.eval_density(body),
            |map| match map {
                AppearanceMap::Densities(entries) => Some(entries.clone()),
                _ => None,
            },
        )
    }

    /// The densities of a block pattern (`checker density {..}, density {..}`); left-out
    /// ones are constant 0 and 1 alternately (so a bare `checker` alternates empty and full
    /// cells).
    fn density_list(&mut self, stream: &mut Stream, count: usize) -> EvalResult<Vec<Pigment>> {
        let mut blocks = Vec::with_capacity(count);
        for index in 0..count {
            if index > 0 {
                self.skip_comma(stream)?;
            }
            let given = match self.next_item(stream)? {
                Some(Item::Block(block)) if matches!(&block.head, BlockHead::Word(w) if &**w == "density") =>
                {
                    let mut body = Stream::new(block.body.clone());
                    Some(self.eval_density(&mut body)?)
                }
                Some(Item::Expr(expr)) => match self.eval_expr(&expr)? {
                    Value::Density(declared) => Some(Rc::unwrap_or_clone(declared)),
                    value => Some(Pigment::Solid(self.to_colour(value, expr.span())?)),
                },
                Some(other) => {
                    stream.push_back(other);
                    None
                }
                None => None,
            };
            let fallback = if index % 2 == 0 {
                Colour::BLACK
            } else {
                Colour::WHITE
            };
            blocks.push(given.unwrap_or(Pigment::Solid(fallback)));
        }
        Ok(blocks)
    }
}
