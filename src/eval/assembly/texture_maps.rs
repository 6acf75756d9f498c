//! Maps of pigments, normals, textures and slopes, `normal { }` blocks, layered textures and
//! the appearance blocks that may be declared on their own.
//!
//! In: the items of a map block (`pigment_map { [key P] .. }`), a `normal` body, the extra
//! layers of a layered `#declare`. Out: sorted map entries, a [`Normal`], a layered
//! [`Texture`]. Holds: bad entries (no key, a key that is not a float, nothing after the key,
//! more than 256 entries) are errors at the entry's span.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::{AppearanceMap, Value};
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Block, BlockHead, Item};
use crate::{
    math::Transform,
    texture::{BlendMap, CompoundTexture, Normal, NormalSource, Pigment, SlopeEntry, Texture},
};
use std::rc::Rc;
use std::sync::Arc;

/// POV-Ray's limit on the entries of one map.
pub(crate) const MAX_MAP_ENTRIES: usize = 256;

/// Appearance blocks evaluated here when they stand on their own (in a `#declare` or as an
/// object modifier).
pub(crate) const APPEARANCE_BLOCKS: &[&str] = &[
    "normal",
    "pigment_map",
    "normal_map",
    "texture_map",
    "slope_map",
    "image_map",
    "bump_map",
];

impl Evaluator {
    /// A pattern modifier written in `normal` or `texture` before any pattern (which it would
    /// modify): warns, skips its operands and returns true; false for any other word.
    pub(crate) fn skipped_modifier_without_pattern(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
        owner: &str,
    ) -> EvalResult<bool> {
        match word {
            "turbulence" | "octaves" | "omega" | "lambda" | "frequency" | "phase"
            | "agate_turb" => {
                self.runtime.warn(
                    span,
                    format!("{owner} `{word}` is not supported yet; it is ignored"),
                );
                let _ = self.expect_value(stream, "a value")?;
                Ok(true)
            }
            "ramp_wave" | "triangle_wave" | "sine_wave" | "scallop_wave" | "cubic_wave" => {
                self.runtime.warn(
                    span,
                    format!("`{word}` is not supported yet; it is ignored"),
                );
                Ok(true)
            }
            "poly_wave" => {
                self.runtime
                    .warn(span, "`poly_wave` is not supported yet; it is ignored");
                let _ = self.optional_bool(stream)?;
                Ok(true)
            }
            _ => Ok(false),
        }
    }

    /// Evaluates one of [`APPEARANCE_BLOCKS`].
    pub(crate) fn eval_appearance_block(
        &mut self,
        head: &str,
        block: &Block,
        stream: &mut Stream,
    ) -> EvalResult<Value> {
        Ok(match head {
            "normal" => Value::Normal(Rc::new(self.eval_normal(stream)?)),
            "pigment_map" => Value::Map(Rc::new(AppearanceMap::Pigments(
                self.eval_pigment_map(stream)?,
            ))),
            "normal_map" => Value::Map(Rc::new(AppearanceMap::Normals(
                self.eval_normal_map(stream)?,
            ))),
            "texture_map" => Value::Map(Rc::new(AppearanceMap::Textures(
                self.eval_texture_map(stream)?,
            ))),
            "slope_map" => Value::Map(Rc::new(AppearanceMap::Slopes(self.eval_slope_map(stream)?))),
            "image_map" => {
                let (image, _) = self.eval_image_map(stream, block.head_span)?;
                Value::Pigment(Rc::new(Pigment::Image {
                    image: Arc::new(image),
                    transform: Transform::IDENTITY,
                    warps: None,
                }))
            }
            _ => {
                // bump_map on its own: a normal.
                let (image, bump_size) = self.eval_bump_map(stream, block.head_span)?;
                let mut normal = Normal::new(NormalSource::BumpMap(Arc::new(image)));
                normal.amount = bump_size.unwrap_or(1.0);
                Value::Normal(Rc::new(normal))
            }
        })
    }

    /// `pigment_map { [key pigment-body] .. }`, or a declared one.
    pub(crate) fn eval_pigment_map(
        &mut self,
        stream: &mut Stream,
    ) -> EvalResult<Vec<(f64, Pigment)>> {
        self.eval_map(
            stream,
            "pigment_map",
            |this, body| this.eval_pigment(body),
            |map| match map {
                AppearanceMap::Pigments(entries) => Some(entries.clone()),
                _ => None,
            },
        )
    }

    /// `normal_map { [key normal-body] .. }`, or a declared one.
    pub(crate) fn eval_normal_map(
        &mut self,
        stream: &mut Stream,
    ) -> EvalResult<Vec<(f64, Normal)>> {
        self.eval_map(
            stream,
            "normal_map",
            |this, body| this.eval_normal(body),
            |map| match map {
                AppearanceMap::Normals(entries) => Some(entries.clone()),
                _ => None,
            },
        )
    }

    /// `texture_map { [key texture-body] .. }`, or a declared one.
    pub(crate) fn eval_texture_map(
        &mut self,
        stream: &mut Stream,
    ) -> EvalResult<Vec<(f64, Texture)>> {
        self.eval_map(
            stream,
            "texture_map",
            |this, body| this.eval_texture(body),
            |map| match map {
                AppearanceMap::Textures(entries) => Some(entries.clone()),
                _ => None,
            },
        )
    }

    /// `slope_map { [key <height, slope>] .. }`, or a declared one.
    pub(crate) fn eval_slope_map(&mut self, stream: &mut Stream) -> EvalResult<Vec<SlopeEntry>> {
        let entries = self.eval_map(
            stream,
            "slope_map",
            |this, body| {
                let point = this.expect_vector(body, "`<height, slope>`")?;
                this.expect_end(body, "slope_map entry")?;
                Ok((point.x, point.y))
            },
            |map| match map {
                AppearanceMap::Slopes(entries) => Some(
                    entries
                        .iter()
                        .map(|e| (e.key, (e.height, e.slope)))
                        .collect(),
                ),
                _ => None,
            },
        )?;
        Ok(entries
            .into_iter()
            .map(|(key, (height, slope))| SlopeEntry { key, height, slope })
            .collect())
    }

    /// The entries of a map block: `[key item]` entries whose item `parse_item` reads from
    /// the rest of the entry, or an identifier holding a map of the same kind
    /// (`declared` extracts its entries). Sorted by key.
    pub(super) fn eval_map<T>(
        &mut self,
        stream: &mut Stream,
        what: &str,
        parse_item: impl Fn(&mut Self, &mut Stream) -> EvalResult<T>,
        declared: impl Fn(&AppearanceMap) -> Option<Vec<(f64, T)>>,
    ) -> EvalResult<Vec<(f64, T)>> {
        let mut entries: Vec<(f64, T)> = Vec::new();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::MapEntry(inner, span) => {
                    if entries.len() == MAX_MAP_ENTRIES {
                        return Err(self
                            .runtime
                            .error(
                                *span,
                                format!("a `{what}` may have at most {MAX_MAP_ENTRIES} entries"),
                            )
                            .with_label("one entry too many")
                            .into());
                    }
                    let mut body = Stream::new(inner.clone());
                    let key = self.map_key(&mut body, *span, what)?;
                    self.skip_comma(&mut body)?;
                    if self.peek_item(&mut body)?.is_none() {
                        return Err(self
                            .runtime
                            .error(
                                *span,
                                format!("this `{what}` entry has a key but nothing after it"),
                            )
                            .with_label("expected `[key item]`")
                            .into());
                    }
                    entries.push((key, parse_item(self, &mut body)?));
                }
                Item::Expr(expr) => {
                    let value = self.eval_expr(expr)?;
                    match &value {
                        Value::Map(map) => match declared(map) {
                            Some(found) => entries = found,
                            None => return Err(self.unexpected_in(&item, what)),
                        },
                        _ => return Err(self.unexpected_in(&item, what)),
                    }
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, what)),
            }
        }
        entries.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(entries)
    }

    /// The key at the start of a map entry.
    fn map_key(&mut self, body: &mut Stream, span: Span, what: &str) -> EvalResult<f64> {
        match self.next_item(body)? {
            Some(Item::Expr(expr)) => {
                let value = self.eval_expr(&expr)?;
                match value {
                    Value::Float(key) => Ok(key),
                    // An `average` entry without its weight may start with a function pattern.
                    Value::Function(_) => {
                        body.push_back(Item::Expr(expr));
                        Ok(1.0)
                    }
                    other => Err(self
                        .runtime
                        .error(
                            expr.span(),
                            format!(
                                "a `{what}` entry starts with its key, a float, not {}",
                                other.type_name()
                            ),
                        )
                        .with_label("expected a float key")
                        .into()),
                }
            }
            // `average` maps may leave out an entry's weight (POV-Ray then weighs it 1).
            Some(other) if !matches!(other, Item::Comma(_)) => {
                body.push_back(other);
                Ok(1.0)
            }
            Some(other) => Err(self
                .runtime
                .error(
                    other.span(),
                    format!("a `{what}` entry starts with its key, a float"),
                )
                .with_label("expected a float key")
                .into()),
            None => Err(self
                .runtime
                .error(span, format!("empty `{what}` entry"))
                .with_label("expected `[key item]`")
                .into()),
        }
    }

    /// `normal { [N] PATTERN [bump_size] modifiers | bump_map {..} | average normal_map {..} }`.
    pub(crate) fn eval_normal(&mut self, stream: &mut Stream) -> EvalResult<Normal> {
        let mut normal = self
            .scene
            .default_texture
            .normal
            .clone()
            .map(|boxed| *boxed);
        // The bump size a pattern written next starts with: a `bump_size` written before
        // the pattern (or in `#default { normal { .. } }`) is kept, as in POV-Ray
        // (measured with normmap.pov).
        let mut preset_amount = normal.as_ref().map(|normal| normal.amount);
        let mut average = false;
        let mut pattern_started = false;
        let mut uv_mapping = false;
        while let Some(item) = self.next_item(stream)? {
            if let Some((spec, list)) = self.block_pattern(&item)? {
                let mut fresh = Normal::new(NormalSource::Pattern {
                    pattern: spec.clone(),
                    slope_map: None,
                });
                // `normal { function { .. } 0.5 }`: an amount may follow the pattern.
                fresh.amount = match self.optional_amount(stream)? {
                    Some(amount) => amount,
                    None => preset_amount.unwrap_or(fresh.amount),
                };
                if let (Some(count), Some(mut list)) = (spec.block_count(), list) {
                    let blocks = self.normal_block_list(&mut list, count)?;
                    if !blocks.is_empty() {
                        fresh.source = NormalSource::Map {
                            pattern: spec,
                            map: BlendMap::Blocks(blocks),
                        };
                    }
                }
                if let Some(amount) = self.optional_amount(stream)? {
                    fresh.amount = amount;
                }
                normal = Some(fresh);
                pattern_started = true;
                continue;
            }
            if let Item::Keyword(word, span) = &item {
                if &**word == "average" {
                    average = true;
                    continue;
                }
                if let Some(spec) = self.pattern_keyword(word, *span, stream)? {
                    let mut fresh = Normal::new(NormalSource::Pattern {
                        pattern: spec.clone(),
                        slope_map: None,
                    });
                    fresh.amount = preset_amount.unwrap_or(fresh.amount);
                    if let Some(count) = spec.block_count() {
                        let blocks = self.normal_block_list(stream, count)?;
                        if !blocks.is_empty() {
                            fresh.source = NormalSource::Map {
                                pattern: spec,
                                map: BlendMap::Blocks(blocks),
                            };
                        }
                    }
                    if let Some(amount) = self.optional_amount(stream)? {
                        fresh.amount = amount;
                    }
                    normal = Some(fresh);
                    pattern_started = true;
                    continue;
                }
                if let Some(Normal {
                    source:
                        NormalSource::Pattern { pattern, .. } | NormalSource::Map { pattern, .. },
                    ..
                }) = &mut normal
                {
                    if self.pattern_modifier(word, *span, stream, pattern)? {
                        continue;
                    }
                }
            }
            if let Item::Block(block) = &item {
                if let Some(Normal {
                    source:
                        NormalSource::Pattern { pattern, .. } | NormalSource::Map { pattern, .. },
                    ..
                }) = &mut normal
                {
                    if self.pattern_block(block, pattern)? {
                        continue;
                    }
                }
            }
            if let Item::Keyword(word, span) = &item {
                if self.skipped_modifier_without_pattern(word, *span, stream, "normal")? {
                    continue;
                }
            }
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        // A uv-mapped normal named here keeps its frame (see
                        // `Normal::transform`), so its pattern notes nothing either.
                        if let Some(normal) = normal.as_mut().filter(|normal| !normal.uv_mapped) {
                            if let NormalSource::Pattern { pattern, .. }
                            | NormalSource::Map { pattern, .. } = &mut normal.source
                            {
                                pattern.note_transform(&t);
                            }
                            normal.transform(&t);
                        }
                    }
                    "bump_size" => {
                        let amount = self.expect_float(stream, "a float")?;
                        preset_amount = Some(amount);
                        if let Some(normal) = &mut normal {
                            normal.amount = amount;
                        }
                    }
                    "accuracy" => {
                        let accuracy = self.expect_float(stream, "a float")?;
                        if let Some(normal) = &mut normal {
                            normal.accuracy = accuracy;
                        }
                    }
                    "no_bump_scale" => {
                        let on = self.optional_bool(stream)?;
                        if let Some(normal) = &mut normal {
                            normal.no_bump_scale = on;
                        }
                    }
                    "uv_mapping" => uv_mapping = true,
                    _ => return Err(self.unexpected_in(&item, "normal")),
                },
                Item::Block(block) => {
                    let head = match &block.head {
                        BlockHead::Word(w) => *w,
                        _ => crate::syntax::symbol::Symbol::intern(""),
                    };
                    let mut body = Stream::new(block.body.clone());
                    match &*head {
                        "normal_map" => {
                            let entries = self.eval_normal_map(&mut body)?;
                            normal = Some(self.normal_with_map(
                                normal,
                                entries,
                                average,
                                block.head_span,
                            )?);
                        }
                        "slope_map" => {
                            let entries = self.eval_slope_map(&mut body)?;
                            match &mut normal {
                                Some(Normal {
                                    source: NormalSource::Pattern { slope_map, .. },
                                    ..
                                }) => *slope_map = Some(entries),
                                _ => {
                                    return Err(self
                                        .runtime
                                        .error(
                                            block.head_span,
                                            "a `slope_map` needs a pattern before it",
                                        )
                                        .with_label("no pattern in this normal yet")
                                        .into())
                                }
                            }
                        }
                        "bump_map" => {
                            let (image, bump_size) =
                                self.eval_bump_map(&mut body, block.head_span)?;
                            let mut fresh = Normal::new(NormalSource::BumpMap(Arc::new(image)));
                            fresh.amount = bump_size.unwrap_or(1.0);
                            normal = Some(fresh);
                            pattern_started = true;
                        }
                        _ => match self.eval_block(block)? {
                            Value::Normal(n) => normal = Some(Rc::unwrap_or_clone(n)),
                            Value::Transform(t) => {
                                if let Some(normal) = &mut normal {
                                    normal.transform(&t);
                                }
                            }
                            _ => return Err(self.unexpected_in(&item, "normal")),
                        },
                    }
                }
                Item::Expr(expr) => {
                    let value = self.eval_expr(expr)?;
                    match value {
                        Value::Normal(n) => normal = Some(Rc::unwrap_or_clone(n)),
                        Value::Map(map) if matches!(&*map, AppearanceMap::Normals(_)) => {
                            if let AppearanceMap::Normals(entries) = &*map {
                                normal = Some(self.normal_with_map(
                                    normal,
                                    entries.clone(),
                                    average,
                                    expr.span(),
                                )?);
                            }
                        }
                        Value::Float(amount) if pattern_started => {
                            if let Some(normal) = &mut normal {
                                normal.amount = amount;
                            }
                        }
                        _ => return Err(self.unexpected_in(&item, "normal")),
                    }
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "normal")),
            }
        }
        let mut normal = match normal {
            Some(normal) => normal,
            None => {
                // No pattern: a normal that perturbs nothing, keeping its bump size for the
                // patterns of the normals that start from it.
                let mut flat = Normal::new(NormalSource::Average(Vec::new()));
                flat.amount = preset_amount.unwrap_or(flat.amount);
                flat
            }
        };
        normal.uv_mapped |= uv_mapping;
        Ok(normal)
    }

    /// The normal a `normal_map` turns `current` into: the map over its pattern, or an
    /// average of the entries.
    fn normal_with_map(
        &mut self,
        current: Option<Normal>,
        entries: Vec<(f64, Normal)>,
        average: bool,
        span: Span,
    ) -> EvalResult<Normal> {
        if average {
            return Ok(Normal::new(NormalSource::Average(entries)));
        }
        match current {
            Some(Normal {
                source: NormalSource::Pattern { pattern, .. } | NormalSource::Map { pattern, .. },
                transform,
                ..
            }) => {
                // The transformations written between the pattern and its map move the
                // map's normals too (measured).
                let mut map = BlendMap::Entries(entries);
                map.for_each_mut(|entry| entry.transform(&transform));
                let mut normal = Normal::new(NormalSource::Map { pattern, map });
                normal.transform = transform;
                Ok(normal)
            }
            _ => Err(self
                .runtime
                .error(span, "a `normal_map` needs a pattern before it")
                .with_label("no pattern in this normal yet")
                .into()),
        }
    }

    /// A float right after a normal's pattern: its bump size.
    fn optional_amount(&mut self, stream: &mut Stream) -> EvalResult<Option<f64>> {
        let mut item = self.next_item(stream)?;
        if let Some(Item::Comma(_)) = item {
            item = self.next_item(stream)?;
        }
        if let Some(Item::Expr(expr)) = &item {
            if let Value::Float(amount) = self.eval_expr(expr)? {
                return Ok(Some(amount));
            }
        }
        if let Some(item) = item {
            stream.push_back(item);
        }
        Ok(None)
    }

    /// The normals of a block pattern in a normal (`checker normal {..}, normal {..}`);
    /// empty when none are given.
    fn normal_block_list(&mut self, stream: &mut Stream, count: usize) -> EvalResult<Vec<Normal>> {
        let mut blocks = Vec::new();
        while blocks.len() < count {
            self.skip_comma(stream)?;
            let item = self.next_item(stream)?;
            let normal = match &item {
                Some(Item::Block(block)) if matches!(&block.head, BlockHead::Word(w) if &**w == "normal") => {
                    match self.eval_block(block)? {
                        Value::Normal(n) => Rc::unwrap_or_clone(n),
                        _ => {
                            return Err(self.unexpected_in(
                                item.as_ref().unwrap_or(&Item::Comma(block.span)),
                                "normal",
                            ))
                        }
                    }
                }
                Some(Item::Expr(expr)) => {
                    let value = self.eval_expr(expr)?;
                    match value {
                        Value::Normal(n) => Rc::unwrap_or_clone(n),
                        _ => {
                            stream.push_back(Item::Expr(expr.clone()));
                            break;
                        }
                    }
                }
                Some(other) => {
                    stream.push_back(other.clone());
                    break;
                }
                None => break,
            };
            blocks.push(normal);
        }
        if !blocks.is_empty() {
            while blocks.len() < count {
                blocks.push(Normal::new(NormalSource::Average(Vec::new())));
            }
        }
        Ok(blocks)
    }

    /// The texture a layered `#declare` (`T = texture {..} texture {..}`) makes of its first
    /// value and the extra layers.
    pub(crate) fn layer_textures(
        &mut self,
        first: Value,
        layers: &[Rc<Block>],
    ) -> EvalResult<Value> {
        if layers.is_empty() {
            return Ok(first);
        }
        let Value::Texture(bottom) = first else {
            return Err(self
                .runtime
                .error(layers[0].span, "only textures can be layered")
                .with_label("a layer after something that is not a texture")
                .into());
        };
        let mut stack = vec![Texture::clone(&bottom)];
        for layer in layers {
            match self.eval_block(layer)? {
                Value::Texture(t) => stack.push(Texture::clone(&t)),
                _ => {
                    return Err(self
                        .runtime
                        .error(layer.span, "expected a texture layer")
                        .into())
                }
            }
        }
        Ok(Value::Texture(Arc::new(layered(stack))))
    }
}

/// One texture made of layers (bottom first); layers that are layered themselves are
/// flattened.
pub(crate) fn layered(layers: Vec<Texture>) -> Texture {
    let mut flat = Vec::with_capacity(layers.len());
    for layer in layers {
        match layer.compound.as_deref() {
            Some(CompoundTexture::Layered(inner)) => flat.extend(inner.iter().cloned()),
            _ => flat.push(layer),
        }
    }
    Texture {
        compound: Some(Arc::new(CompoundTexture::Layered(flat))),
        ..Texture::default()
    }
}

/// Applies `change` to the layer that `pigment`, `normal` and `finish` given to an object
/// modify: the top layer of a layered texture, else the texture itself.
pub(crate) fn change_top_layer(texture: &mut Texture, change: impl FnOnce(&mut Texture)) {
    if let Some(compound) = texture.compound.as_mut() {
        if let CompoundTexture::Layered(layers) = Arc::make_mut(compound) {
            if let Some(top) = layers.last_mut() {
                change(top);
            }
            return;
        }
    }
    change(texture);
}

/// The finish of the layer [`change_top_layer`] changes.
pub(crate) fn top_layer_finish(texture: &Texture) -> &crate::texture::finish::Finish {
    &top_layer(texture).finish
}

/// The layer [`change_top_layer`] changes.
pub(crate) fn top_layer(texture: &Texture) -> &Texture {
    match texture.compound.as_deref() {
        Some(CompoundTexture::Layered(layers)) => match layers.last() {
            Some(top) => top_layer(top),
            None => texture,
        },
        _ => texture,
    }
}
