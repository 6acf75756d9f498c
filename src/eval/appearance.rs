//! Appearance blocks: texture, pigment, colour maps and `#default` (finish and interior
//! are in `finish.rs`).

use super::stream::Stream;
use super::value::Value;
use super::{EvalResult, Evaluator};
use crate::diag::Span;
use crate::scene::{Colour, Pattern, Pigment, PigmentMap, Texture, Transform};
use crate::syntax::ast::{BlockHead, Item};
use glam::DVec3;
use std::rc::Rc;

/// Patterns POV-Ray has that durer does not render yet (they fall back to their first colour).
const UNSUPPORTED_PATTERNS: &[&str] = &[
    "agate",
    "aoi",
    "average",
    "boxed",
    "bozo",
    "brick",
    "bumps",
    "cells",
    "crackle",
    "cylindrical",
    "density_file",
    "dents",
    "facets",
    "function",
    "granite",
    "hexagon",
    "image_map",
    "image_pattern",
    "julia",
    "leopard",
    "magnet",
    "mandel",
    "marble",
    "onion",
    "pavement",
    "pigment_pattern",
    "planar",
    "quilted",
    "radial",
    "ripples",
    "slope",
    "spherical",
    "spiral1",
    "spiral2",
    "spotted",
    "square",
    "tiling",
    "triangular",
    "waves",
    "wood",
    "wrinkles",
    "object",
];

impl Evaluator {
    /// `texture { [Ident] pigment finish normal transforms }`.
    pub(crate) fn eval_texture(&mut self, stream: &mut Stream) -> EvalResult<Texture> {
        let mut texture = self.default_texture.clone();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        transform_pigment(&mut texture.pigment, &t);
                    }
                    "uv_mapping" => {
                        self.warn(*span, "`uv_mapping` is not supported yet; it is ignored");
                    }
                    w if w == "gradient" || w == "checker" || UNSUPPORTED_PATTERNS.contains(&w) => {
                        self.warn(*span, format!("texture patterns (`{w}` in `texture`) are not supported yet; it is ignored"));
                        if w == "gradient" {
                            let _ = self.expect_value(stream, "a direction")?;
                        }
                    }
                    "turbulence" | "octaves" | "omega" | "lambda" | "frequency" | "phase" => {
                        self.warn(
                            *span,
                            format!("texture `{word}` is not supported yet; it is ignored"),
                        );
                        let _ = self.expect_value(stream, "a value")?;
                    }
                    _ => return Err(self.unexpected_in(&item, "texture")),
                },
                Item::Block(block) => {
                    if let BlockHead::Word(w) = &block.head {
                        if &**w == "finish" {
                            let mut body = Stream::new(block.body.clone());
                            texture.finish =
                                self.eval_finish(&mut body, Some(texture.finish.clone()))?;
                            continue;
                        }
                    }
                    match self.eval_block(block)? {
                        Value::Pigment(p) => texture.pigment = Rc::unwrap_or_clone(p),
                        Value::Transform(t) => transform_pigment(&mut texture.pigment, &t),
                        Value::Nothing => {} // a left-out block such as `normal`
                        _ => return Err(self.unexpected_in(&item, "texture")),
                    }
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Texture(t) => texture = (*t).clone(),
                    _ => return Err(self.unexpected_in(&item, "texture")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "texture")),
            }
        }
        Ok(texture)
    }

    /// `pigment { .. }`: a solid colour, checker or gradient with a colour map.
    pub(crate) fn eval_pigment(&mut self, stream: &mut Stream) -> EvalResult<Pigment> {
        let mut pigment = self.default_texture.pigment.clone();
        let mut colour_map: Option<Vec<(f64, Colour)>> = None;
        let mut frequency = 1.0;
        let mut phase = 0.0;
        while let Some(item) = self.next_item(stream)? {
            if let Item::Keyword(word, span) = &item {
                if let Some(spec) = self.pattern_keyword(word, *span, stream)? {
                    let map = match spec.block_count() {
                        Some(count) => PigmentMap::Blocks(self.block_list(stream, count)?),
                        None => PigmentMap::Colours(grey_ramp()),
                    };
                    pigment = Pigment::Pattern {
                        pattern: spec,
                        map,
                        transform: Transform::IDENTITY,
                    };
                    continue;
                }
                if let Pigment::Pattern { pattern, .. } = &mut pigment {
                    if self.pattern_modifier(word, *span, stream, pattern)? {
                        continue;
                    }
                }
            }
            if let Item::Block(block) = &item {
                if let Pigment::Pattern { pattern, .. } = &mut pigment {
                    if self.pattern_block(block, pattern)? {
                        continue;
                    }
                }
            }
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        if let Pigment::Pattern { pattern, .. } = &mut pigment {
                            pattern.note_transform(&t);
                        }
                        transform_pigment(&mut pigment, &t);
                    }
                    "frequency" => frequency = self.expect_float(stream, "a float")?,
                    "phase" => phase = self.expect_float(stream, "a float")?,
                    "turbulence" | "octaves" | "omega" | "lambda" => {
                        self.warn(
                            *span,
                            format!("pigment `{word}` is not supported yet; it is ignored"),
                        );
                        let _ = self.expect_value(stream, "a value")?;
                    }
                    "ramp_wave" | "triangle_wave" | "sine_wave" | "scallop_wave" | "cubic_wave" => {
                        self.warn(
                            *span,
                            format!("`{word}` is not supported yet; it is ignored"),
                        );
                    }
                    "red" | "green" | "blue" | "filter" | "transmit" | "gray" | "grey" => {
                        // Colour components given straight in the pigment modify its colour.
                        let amount = self.expect_float(stream, "a float")?;
                        if let Pigment::Solid(colour) = &mut pigment {
                            match &**word {
                                "red" => colour.red = amount,
                                "green" => colour.green = amount,
                                "blue" => colour.blue = amount,
                                "filter" => colour.filter = amount,
                                "transmit" => colour.transmit = amount,
                                _ => {
                                    colour.red = amount;
                                    colour.green = amount;
                                    colour.blue = amount;
                                }
                            }
                        }
                    }
                    "quick_color" | "quick_colour" => {
                        let _ = self.expect_value(stream, "a colour")?;
                    }
                    "agate_turb" => {
                        self.warn(*span, "`agate_turb` is not supported yet; it is ignored");
                        let _ = self.expect_value(stream, "a value")?;
                    }
                    "uv_mapping" => {
                        self.warn(*span, "`uv_mapping` is not supported yet; it is ignored");
                    }
                    "poly_wave" => {
                        self.warn(*span, "`poly_wave` is not supported yet; it is ignored");
                        let _ = self.optional_bool(stream)?;
                    }
                    w if UNSUPPORTED_PATTERNS.contains(&w) => {
                        self.warn(
                            *span,
                            format!("pattern `{w}` is not supported yet; its first colour is used"),
                        );
                        // Patterns with a required operand.
                        if matches!(w, "agate" | "brick" | "hexagon" | "checker") {
                        } else if matches!(w, "mandel" | "julia" | "magnet") {
                            let _ = self.expect_value(stream, "a value")?;
                        }
                        pigment = Pigment::Pattern {
                            pattern: Pattern::new(crate::pattern::PatternKind::Gradient(
                                DVec3::ZERO,
                            )),
                            map: PigmentMap::Colours(grey_ramp()),
                            transform: Transform::IDENTITY,
                        };
                    }
                    _ => return Err(self.unexpected_in(&item, "pigment")),
                },
                Item::Block(block) => {
                    let is_colour_map = matches!(&block.head, BlockHead::Word(w) if matches!(&**w, "color_map" | "colour_map"));
                    let value = self.eval_block(block)?;
                    match value {
                        Value::ColourMap(map) if is_colour_map => colour_map = Some((*map).clone()),
                        Value::Transform(t) => transform_pigment(&mut pigment, &t),
                        Value::Pigment(p) => pigment = Rc::unwrap_or_clone(p),
                        Value::Nothing => {}
                        _ => return Err(self.unexpected_in(&item, "pigment")),
                    }
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Pigment(p) => pigment = Rc::unwrap_or_clone(p),
                    Value::ColourMap(map) => colour_map = Some((*map).clone()),
                    value @ (Value::Colour(_) | Value::Float(_) | Value::Vector(_)) => {
                        pigment = Pigment::Solid(self.to_colour(value, expr.span())?)
                    }
                    _ => return Err(self.unexpected_in(&item, "pigment")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "pigment")),
            }
        }
        if let Pigment::Pattern {
            map: PigmentMap::Colours(entries),
            ..
        } = &mut pigment
        {
            if let Some(map) = colour_map {
                *entries = map;
            }
            if frequency != 1.0 || phase != 0.0 {
                for (value, _) in entries.iter_mut() {
                    *value = (*value - phase) / frequency;
                }
                // Frequency and phase reshape the value → colour lookup; approximate by
                // remapping the map entries (exact for frequency 1).
            }
        }
        Ok(pigment)
    }

    /// The optional pigments of a block pattern (`checker A, B`), POV-Ray's default
    /// colours (blue, green, red, ...) for the ones left out.
    fn block_list(&mut self, stream: &mut Stream, count: usize) -> EvalResult<Vec<Pigment>> {
        const DEFAULTS: [(f64, f64, f64); 3] = [(0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)];
        let mut blocks = Vec::with_capacity(count);
        for index in 0..count {
            if index > 0 {
                self.skip_comma(stream)?;
            }
            let (r, g, b) = DEFAULTS[index.min(DEFAULTS.len() - 1)];
            let given = self.optional_pigment(stream)?;
            blocks.push(given.unwrap_or(Pigment::Solid(Colour::rgb(r, g, b))));
        }
        Ok(blocks)
    }

    /// An optional colour or pigment operand (for `checker`).
    fn optional_pigment(&mut self, stream: &mut Stream) -> EvalResult<Option<Pigment>> {
        match self.next_item(stream)? {
            Some(Item::Expr(expr)) => {
                let value = self.eval_expr(&expr)?;
                Ok(Some(match value {
                    Value::Pigment(p) => Rc::unwrap_or_clone(p),
                    other => Pigment::Solid(self.to_colour(other, expr.span())?),
                }))
            }
            Some(Item::Block(block)) if matches!(&block.head, BlockHead::Word(w) if &**w == "pigment") => {
                match self.eval_block(&block)? {
                    Value::Pigment(p) => Ok(Some(Rc::unwrap_or_clone(p))),
                    _ => Ok(None),
                }
            }
            Some(other) => {
                stream.push_back(other);
                Ok(None)
            }
            None => Ok(None),
        }
    }

    /// `color_map { [v colour] .. }`, also the old `[v1, v2 colour1 colour2]` form.
    pub(crate) fn eval_colour_map(
        &mut self,
        stream: &mut Stream,
    ) -> EvalResult<Vec<(f64, Colour)>> {
        let mut entries: Vec<(f64, Colour)> = Vec::new();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::MapEntry(inner, span) => {
                    let mut entry = Stream::new(inner.clone());
                    let mut values: Vec<(Value, Span)> = Vec::new();
                    while let Some(part) = self.next_item(&mut entry)? {
                        match &part {
                            Item::Comma(_) => {}
                            Item::Expr(e) => values.push((self.eval_expr(e)?, e.span())),
                            _ => return Err(self.unexpected_in(&part, "color_map entry")),
                        }
                    }
                    match values.len() {
                        2 => {
                            let (v, s) = values[0].clone();
                            let at = self.to_float(v, s)?;
                            let (c, s) = values[1].clone();
                            entries.push((at, self.to_colour(c, s)?));
                        }
                        4 => {
                            let mut floats = Vec::new();
                            let mut colours = Vec::new();
                            for (i, (v, s)) in values.into_iter().enumerate() {
                                if i < 2 {
                                    floats.push(self.to_float(v, s)?);
                                } else {
                                    colours.push(self.to_colour(v, s)?);
                                }
                            }
                            entries.push((floats[0], colours[0]));
                            entries.push((floats[1], colours[1]));
                        }
                        _ => {
                            return Err(self
                                .error(*span, "expected `[value colour]` in a colour map")
                                .into())
                        }
                    }
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::ColourMap(map) => entries = (*map).clone(),
                    _ => return Err(self.unexpected_in(&item, "color_map")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "color_map")),
            }
        }
        entries.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(entries)
    }

    /// `#default { texture | pigment | finish }`.
    pub(crate) fn run_default(&mut self, items: Rc<[Item]>) -> EvalResult<()> {
        let mut stream = Stream::new(items);
        while let Some(item) = self.next_item(&mut stream)? {
            let value = match &item {
                Item::Block(block) => self.eval_block(block)?,
                Item::Comma(_) => continue,
                _ => return Err(self.unexpected_in(&item, "#default")),
            };
            let mut texture = self.default_texture.clone();
            match value {
                Value::Texture(t) => texture = (*t).clone(),
                Value::Pigment(p) => texture.pigment = Rc::unwrap_or_clone(p),
                Value::Finish(f) => texture.finish = Rc::unwrap_or_clone(f),
                Value::Nothing => {}
                _ => return Err(self.unexpected_in(&item, "#default")),
            }
            self.set_default_texture(texture);
        }
        Ok(())
    }
}

/// POV-Ray's map for a pattern without one: black to white.
fn grey_ramp() -> Vec<(f64, Colour)> {
    vec![(0.0, Colour::BLACK), (1.0, Colour::WHITE)]
}

/// Applies a transformation to a pigment's pattern space (nested block pigments too).
pub(crate) fn transform_pigment(pigment: &mut Pigment, t: &Transform) {
    if let Pigment::Pattern { transform, map, .. } = pigment {
        *transform = transform.then(t);
        if let PigmentMap::Blocks(blocks) = map {
            for block in blocks {
                transform_pigment(block, t);
            }
        }
    }
}
