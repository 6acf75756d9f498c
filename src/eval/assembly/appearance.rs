//! Appearance blocks: texture, pigment, colour maps and `#default` (finish and interior
//! are in `finish.rs`).

use super::texture_maps::{change_top_layer, layered, top_layer};
use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::{AppearanceMap, Value};
use crate::eval::{EvalResult, Evaluator};
use crate::noise::SceneNoiseGenerator;
use crate::syntax::ast::{BlockHead, Expr, Item};
use crate::{
    math::{Colour, Transform},
    texture::{pattern::Pattern, BlendMap, CompoundTexture, Pigment, PigmentMap, Texture},
};
use std::rc::Rc;
use std::sync::Arc;

impl Evaluator {
    /// `texture { [Ident] pigment normal finish transforms }`, or a pattern of whole
    /// textures (`checker texture {..} texture {..}`, `PATTERN texture_map {..}`,
    /// `average texture_map {..}`, `tiles {..}`).
    pub(crate) fn eval_texture(&mut self, stream: &mut Stream) -> EvalResult<Texture> {
        let mut texture = self.scene.default_texture.clone();
        // A pattern of whole textures, with its map once given.
        let mut pattern: Option<(Pattern, Option<BlendMap<Texture>>, Span)> = None;
        let mut pattern_transform = Transform::IDENTITY;
        let mut average = false;
        let mut uv_mapping = false;
        // `no_bump_scale` written in the texture itself, anywhere in it: POV-Ray takes it for
        // the texture's normal (measured: `texture { no_bump_scale normal {..} scale 5 }`
        // renders as `normal { .. no_bump_scale }`).
        let mut no_bump_scale = None;
        // POV-Ray reads pigment, finish and normal identifiers written straight in the body
        // (`texture { P F N }`) only before any other item (measured: `texture { T P }` and
        // `texture { N P F }` render, `texture { scale 2 P }` is refused).
        let mut leading_identifiers = true;
        while let Some(item) = self.next_item(stream)? {
            // An identifier is evaluated once, here; any other value it holds is used below.
            let mut identifier_value = None;
            if let Item::Expr(expr @ Expr::Ident(..)) = &item {
                let value = self.eval_expr(expr)?;
                let span = item.span();
                if self.texture_part_identifier(&value, span, leading_identifiers, &mut texture)? {
                    continue;
                }
                identifier_value = Some(value);
            } else {
                leading_identifiers = false;
            }
            if let Some((spec, list)) = self.block_pattern(&item)? {
                let blocks = match (spec.block_count(), list) {
                    (Some(count), Some(mut list)) => self.texture_block_list(&mut list, count)?,
                    _ => None,
                };
                pattern = Some((spec, blocks.map(BlendMap::Blocks), item.span()));
                pattern_transform = Transform::IDENTITY;
                continue;
            }
            if let Item::Keyword(word, span) = &item {
                if &**word == "average" {
                    average = true;
                    continue;
                }
                if let Some(spec) =
                    self.pattern_keyword_outside_normal(word, *span, stream, "texture")?
                {
                    let blocks = match spec.block_count() {
                        Some(count) => self.texture_block_list(stream, count)?,
                        None => None,
                    };
                    pattern = Some((spec, blocks.map(BlendMap::Blocks), *span));
                    pattern_transform = Transform::IDENTITY;
                    continue;
                }
                if let Some((spec, _, _)) = &mut pattern {
                    if self.pattern_modifier(word, *span, stream, spec)? {
                        continue;
                    }
                }
            }
            if let Item::Block(block) = &item {
                if let Some((spec, _, _)) = &mut pattern {
                    if self.pattern_block(block, spec)? {
                        continue;
                    }
                }
            }
            if let Item::Keyword(word, span) = &item {
                if self.skipped_modifier_without_pattern(word, *span, stream, "texture")? {
                    continue;
                }
            }
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        if let Some((spec, map, _)) = &mut pattern {
                            spec.note_transform(&t);
                            pattern_transform = pattern_transform.then(&t);
                            if let Some(map) = map {
                                map.for_each_mut(|inner| inner.transform(&t));
                            }
                        }
                        texture.transform(&t);
                    }
                    "uv_mapping" => uv_mapping = true,
                    "no_bump_scale" => no_bump_scale = Some(self.optional_bool(stream)?),
                    _ => return Err(self.unexpected_in(&item, "texture")),
                },
                Item::Block(block) => {
                    let head = match &block.head {
                        BlockHead::Word(w) => *w,
                        _ => crate::syntax::symbol::Symbol::intern(""),
                    };
                    let mut body = Stream::new(block.body.clone());
                    match &*head {
                        // `pigment` and `finish` modify the texture's own (of a layered
                        // texture: its top layer's), as in POV-Ray (measured with a layered
                        // texture given a `pigment { octaves 3 }` and a finish).
                        "finish" => {
                            let base =
                                crate::texture::finish::Finish::clone(&top_layer(&texture).finish);
                            let finish = Arc::new(self.eval_finish(&mut body, Some(base))?);
                            change_top_layer(&mut texture, |top| top.finish = finish);
                        }
                        "pigment" => {
                            let base = top_layer(&texture).pigment.clone();
                            let pigment = self.eval_pigment_from(&mut body, base)?;
                            change_top_layer(&mut texture, |top| top.pigment = pigment);
                        }
                        "texture_map" => {
                            let entries = self.eval_texture_map(&mut body)?;
                            self.attach_texture_map(
                                &mut pattern,
                                entries,
                                average,
                                &pattern_transform,
                                &mut texture,
                                block.head_span,
                            )?;
                        }
                        "tiles" => {
                            let blocks = self.eval_tiles(&mut body, block.head_span)?;
                            pattern = Some((
                                self.new_pattern(crate::texture::pattern::PatternKind::Checker),
                                Some(BlendMap::Blocks(blocks)),
                                block.head_span,
                            ));
                            pattern_transform = Transform::IDENTITY;
                        }
                        "material_map" => {
                            let compound = self.eval_material_map(&mut body, block.head_span)?;
                            texture.compound = Some(Arc::new(compound));
                        }
                        _ => match self.eval_block(block)? {
                            Value::Pigment(p) => texture.pigment = Rc::unwrap_or_clone(p),
                            Value::Normal(n) => {
                                texture.normal = Some(Box::new(Rc::unwrap_or_clone(n)))
                            }
                            Value::Transform(t) => texture.transform(&t),
                            Value::Nothing => {}
                            _ => return Err(self.unexpected_in(&item, "texture")),
                        },
                    }
                }
                Item::Expr(expr) => {
                    match identifier_value.map_or_else(|| self.eval_expr(expr), Ok)? {
                        Value::Texture(t) => texture = (*t).clone(),
                        Value::Map(map) => {
                            if let AppearanceMap::Textures(entries) = &*map {
                                let entries = entries.clone();
                                self.attach_texture_map(
                                    &mut pattern,
                                    entries,
                                    average,
                                    &pattern_transform,
                                    &mut texture,
                                    expr.span(),
                                )?;
                            } else {
                                return Err(self.unexpected_in(&item, "texture"));
                            }
                        }
                        _ => return Err(self.unexpected_in(&item, "texture")),
                    }
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "texture")),
            }
        }
        if let Some((spec, map, span)) = pattern {
            let Some(map) = map else {
                return Err(self
                    .runtime
                    .error(
                        span,
                        "a texture pattern needs a `texture_map` or its block textures",
                    )
                    .with_label("pattern without textures")
                    .into());
            };
            texture.compound = Some(Arc::new(CompoundTexture::Pattern {
                pattern: spec,
                map,
                transform: pattern_transform,
            }));
        }
        if let Some(on) = no_bump_scale {
            change_top_layer(&mut texture, |top| {
                if let Some(normal) = &mut top.normal {
                    normal.no_bump_scale = on;
                }
            });
        }
        if uv_mapping {
            map_texture_by_uv(&mut texture);
        }
        Ok(texture)
    }

    /// A pigment, finish or normal identifier written straight inside `texture { }`:
    /// replaces that part of the texture (of a layered one, its top layer's) and answers
    /// true; false for any other value. POV-Ray takes them only before any other item.
    fn texture_part_identifier(
        &mut self,
        value: &Value,
        span: Span,
        leading: bool,
        texture: &mut Texture,
    ) -> EvalResult<bool> {
        let kind = match value {
            Value::Pigment(_) => "pigment",
            Value::Finish(_) => "finish",
            Value::Normal(_) => "normal",
            _ => return Ok(false),
        };
        if !leading {
            return Err(self
                .runtime
                .error(
                    span,
                    format!(
                        "a {kind} identifier inside `texture` must come before its other items"
                    ),
                )
                .with_label(format!("{kind} identifier after other items"))
                .with_help(format!(
                    "move it to the start of the texture, or write `{kind} {{ NAME }}`"
                ))
                .into());
        }
        match value {
            Value::Pigment(pigment) => {
                let pigment = Pigment::clone(pigment);
                change_top_layer(texture, |top| top.pigment = pigment);
            }
            Value::Finish(finish) => {
                let finish = Arc::new(crate::texture::finish::Finish::clone(finish));
                change_top_layer(texture, |top| top.finish = finish);
            }
            Value::Normal(normal) => {
                let normal = Some(Box::new(crate::texture::Normal::clone(normal)));
                change_top_layer(texture, |top| top.normal = normal);
            }
            _ => {}
        }
        Ok(true)
    }

    /// Stores a `texture_map`'s entries: into the pattern, or as an average.
    fn attach_texture_map(
        &mut self,
        pattern: &mut Option<(Pattern, Option<BlendMap<Texture>>, Span)>,
        entries: Vec<(f64, Texture)>,
        average: bool,
        pattern_transform: &Transform,
        texture: &mut Texture,
        span: Span,
    ) -> EvalResult<()> {
        if average {
            texture.compound = Some(Arc::new(CompoundTexture::Average(entries)));
            return Ok(());
        }
        match pattern {
            Some((_, map, _)) => {
                // The transformations written between the pattern and its map move the
                // map's textures too (measured).
                let mut entries = BlendMap::Entries(entries);
                entries.for_each_mut(|inner| inner.transform(pattern_transform));
                *map = Some(entries);
                Ok(())
            }
            None => Err(self
                .runtime
                .error(span, "a `texture_map` needs a pattern before it")
                .with_label("no pattern in this texture yet")
                .into()),
        }
    }

    /// The textures of a block pattern in a texture (`checker texture {..} texture {..}`);
    /// `None` when none are given (a `texture_map` follows instead).
    fn texture_block_list(
        &mut self,
        stream: &mut Stream,
        count: usize,
    ) -> EvalResult<Option<Vec<Texture>>> {
        let mut blocks = Vec::new();
        while blocks.len() < count {
            self.skip_comma(stream)?;
            match self.next_item(stream)? {
                Some(Item::Block(block)) if matches!(&block.head, BlockHead::Word(w) if &**w == "texture") =>
                {
                    let mut body = Stream::new(block.body.clone());
                    blocks.push(self.eval_texture(&mut body)?);
                }
                Some(Item::Expr(expr)) => match self.eval_expr(&expr)? {
                    Value::Texture(t) => blocks.push(Texture::clone(&t)),
                    _ => {
                        stream.push_back(Item::Expr(expr));
                        break;
                    }
                },
                Some(other) => {
                    stream.push_back(other);
                    break;
                }
                None => break,
            }
        }
        if blocks.is_empty() {
            return Ok(None);
        }
        while blocks.len() < count {
            blocks.push(self.scene.default_texture.clone());
        }
        Ok(Some(blocks))
    }

    /// `tiles { texture {..}.. tile2 texture {..}.. }`: a checker of two (layered) textures,
    /// the first where `checker` has its second colour (as POV-Ray renders it).
    fn eval_tiles(&mut self, stream: &mut Stream, span: Span) -> EvalResult<Vec<Texture>> {
        let mut tiles: [Vec<Texture>; 2] = [Vec::new(), Vec::new()];
        let mut current = 0;
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) if &**word == "tile2" => current = 1,
                Item::Block(block) if matches!(&block.head, BlockHead::Word(w) if &**w == "texture") =>
                {
                    let mut body = Stream::new(block.body.clone());
                    let texture = self.eval_texture(&mut body)?;
                    tiles[current].push(texture);
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Texture(t) => tiles[current].push(Texture::clone(&t)),
                    _ => return Err(self.unexpected_in(&item, "tiles")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "tiles")),
            }
        }
        // POV-Ray puts the first tile where the checker pattern has its second block.
        tiles.swap(0, 1);
        let mut result = Vec::with_capacity(2);
        for layers in tiles {
            match layers.len() {
                0 => {
                    return Err(self
                        .runtime
                        .error(span, "`tiles` needs a texture before and after `tile2`")
                        .with_label("missing tile texture")
                        .into())
                }
                1 => result.extend(layers),
                _ => result.push(layered(layers)),
            }
        }
        Ok(result)
    }

    /// `pigment { .. }`: a solid colour, checker or gradient with a colour map.
    pub(crate) fn eval_pigment(&mut self, stream: &mut Stream) -> EvalResult<Pigment> {
        let base = self.scene.default_texture.pigment.clone();
        self.eval_pigment_from(stream, base)
    }

    /// A `pigment { .. }` block that modifies `base` (the pigment of the texture it is
    /// written in); a pattern or pigment named in it replaces `base`.
    pub(crate) fn eval_pigment_from(
        &mut self,
        stream: &mut Stream,
        base: Pigment,
    ) -> EvalResult<Pigment> {
        let mut pigment = base;
        let mut colour_map: Option<Vec<(f64, Colour)>> = None;
        let mut average = false;
        let mut earlier_item = None;
        let mut uv_mapping = false;
        // A uv-mapped pigment named here takes no transformation (POV-Ray: only those in
        // the block that says `uv_mapping` apply).
        let mut sealed_uv = false;
        // Whether the item before (commas aside) was a colour: components after one modify
        // it (`pigment { Red green 0.5 }`); anywhere else they start a colour of their own
        // from black, as povray reads them (measured: `texture { T pigment { transmit 0.5
        // } }` and `pigment { P_ident transmit 0.5 }` are black with transmit 0.5, not
        // T's or P's colour made transparent).
        let mut colour_before = false;
        while let Some(item) = self.next_item(stream)? {
            let after_colour = std::mem::replace(&mut colour_before, false);
            if matches!(item, Item::Comma(_)) {
                colour_before = after_colour;
            }
            // `uv_mapping` and a first pigment identifier (`pigment { P bozo .. }`) may
            // precede the pattern; nothing else may (POV-Ray).
            let earlier = match &item {
                Item::Comma(_) => earlier_item,
                Item::Keyword(word, _) if &**word == "uv_mapping" => earlier_item,
                Item::Expr(Expr::Ident(..)) if earlier_item.is_none() => None,
                _ => earlier_item.replace(item.span()),
            };
            // A uv-mapped pigment named here is modified unwrapped and wrapped again at the end.
            if let Pigment::UvMapped(inner) = &mut pigment {
                pigment = std::mem::replace(&mut **inner, Pigment::Solid(Colour::BLACK));
                uv_mapping = true;
                sealed_uv = true;
            }
            if let Item::Keyword(word, _) = &item {
                if &**word == "average" {
                    // The average is the pigment's pattern from here on: turbulence, warps and
                    // transformations written before its map apply to it (measured).
                    average = true;
                    if !matches!(pigment, Pigment::Average { .. }) {
                        pigment = Pigment::Average {
                            entries: Vec::new(),
                            transform: Transform::IDENTITY,
                            warps: None,
                        };
                    }
                    continue;
                }
            }
            if let Item::Block(block) = &item {
                let head = match &block.head {
                    BlockHead::Word(w) => &**w,
                    _ => "",
                };
                if head == "pigment_map" {
                    let mut body = Stream::new(block.body.clone());
                    let entries = self.eval_pigment_map(&mut body)?;
                    self.attach_pigment_map(&mut pigment, entries, average, block.head_span)?;
                    continue;
                }
                if head == "image_map" {
                    let mut body = Stream::new(block.body.clone());
                    let (image, _) = self.eval_image_map(&mut body, block.head_span)?;
                    pigment = Pigment::Image {
                        image: Arc::new(image),
                        transform: Transform::IDENTITY,
                        warps: None,
                    };
                    continue;
                }
            }
            if let Some((spec, list)) = self.block_pattern(&item)? {
                let map = match (spec.block_count(), list) {
                    (Some(count), Some(mut list)) => {
                        PigmentMap::Blocks(self.block_list(&mut list, count, &spec)?)
                    }
                    _ => PigmentMap::Colours(grey_ramp()),
                };
                set_pattern(&mut pigment, spec, map);
                continue;
            }
            if let Item::Keyword(word, span) = &item {
                if let Some(spec) =
                    self.pattern_keyword_outside_normal(word, *span, stream, "pigment")?
                {
                    if let Some(earlier) = earlier {
                        return Err(self.pattern_not_first(word, *span, earlier));
                    }
                    let map = match spec.block_count() {
                        Some(count) => PigmentMap::Blocks(self.block_list(stream, count, &spec)?),
                        None => PigmentMap::Colours(default_colours(&spec)),
                    };
                    set_pattern(&mut pigment, spec, map);
                    continue;
                }
                if let Some(pattern) =
                    modified_pattern(&mut pigment, &self.scene.settings.scene_noise_generator)
                {
                    if self.pattern_modifier(word, *span, stream, pattern)? {
                        continue;
                    }
                }
            }
            if let Item::Block(block) = &item {
                if let Some(pattern) =
                    modified_pattern(&mut pigment, &self.scene.settings.scene_noise_generator)
                {
                    if self.pattern_block(block, pattern)? {
                        continue;
                    }
                }
            }
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        if sealed_uv {
                            continue;
                        }
                        match &mut pigment {
                            Pigment::Pattern { pattern, .. } => pattern.note_transform(&t),
                            Pigment::Image {
                                warps: Some(pattern),
                                ..
                            }
                            | Pigment::Average {
                                warps: Some(pattern),
                                ..
                            } => pattern.note_transform(&t),
                            _ => {}
                        }
                        pigment.transform(&t);
                    }
                    // Pattern modifiers on a pigment without a pattern change nothing, as in
                    // POV-Ray (which refuses a pattern written after them).
                    "frequency" | "phase" | "turbulence" | "octaves" | "omega" | "lambda"
                    | "agate_turb" => {
                        self.runtime.warn(
                            *span,
                            format!("`{word}` has no pattern to modify here; it is ignored"),
                        );
                        let _ = self.expect_value(stream, "a value")?;
                    }
                    "ramp_wave" | "triangle_wave" | "sine_wave" | "scallop_wave" | "cubic_wave" => {
                        self.runtime.warn(
                            *span,
                            format!("`{word}` has no pattern to modify here; it is ignored"),
                        );
                    }
                    "filter" | "transmit" => {
                        // Colour components given straight in the pigment modify its colour
                        // (`red 1`, which the grammar reads as a colour, is handled below).
                        let amount = self.expect_float(stream, "a float")?;
                        if let Pigment::Solid(colour) = &mut pigment {
                            if !after_colour {
                                *colour = Colour::BLACK;
                            }
                            set_colour_component(colour, word, amount);
                            colour_before = true;
                        }
                    }
                    "quick_color" | "quick_colour" => {
                        let _ = self.expect_value(stream, "a colour")?;
                    }
                    "uv_mapping" => uv_mapping = true,
                    "poly_wave" => {
                        self.runtime.warn(
                            *span,
                            "`poly_wave` has no pattern to modify here; it is ignored",
                        );
                        let _ = self.optional_bool(stream)?;
                    }
                    _ => return Err(self.unexpected_in(&item, "pigment")),
                },
                Item::Block(block) => {
                    let is_colour_map = matches!(&block.head, BlockHead::Word(w) if matches!(&**w, "color_map" | "colour_map"));
                    let value = self.eval_block(block)?;
                    match value {
                        Value::ColourMap(map) if is_colour_map => colour_map = Some((*map).clone()),
                        Value::Transform(t) if !sealed_uv => pigment.transform(&t),
                        Value::Transform(_) | Value::Nothing => {}
                        Value::Pigment(p) => pigment = Rc::unwrap_or_clone(p),
                        _ => return Err(self.unexpected_in(&item, "pigment")),
                    }
                }
                // `pigment { Red green 0.5 }`: components alone modify the colour.
                Item::Expr(Expr::Colour(literal)) if literal.is_components_only() => {
                    if let Pigment::Solid(colour) = &mut pigment {
                        if !after_colour {
                            *colour = Colour::BLACK;
                        }
                        self.apply_colour_components(colour, literal)?;
                        colour_before = true;
                    }
                }
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Pigment(p) => pigment = Rc::unwrap_or_clone(p),
                    Value::ColourMap(map) => colour_map = Some((*map).clone()),
                    Value::Map(map) if matches!(&*map, AppearanceMap::Pigments(_)) => {
                        if let AppearanceMap::Pigments(entries) = &*map {
                            let entries = entries.clone();
                            self.attach_pigment_map(&mut pigment, entries, average, expr.span())?;
                        }
                    }
                    value @ (Value::Colour(_) | Value::Float(_) | Value::Vector(_)) => {
                        pigment = Pigment::Solid(self.to_colour(value, expr.span())?);
                        colour_before = true;
                    }
                    // `pigment { function { .. } color_map { .. } }`: a function pattern.
                    Value::Function(literal) => {
                        let function = self.compile_function(&literal)?;
                        pigment = Pigment::Pattern {
                            pattern: Box::new(self.new_pattern(
                                crate::texture::pattern::PatternKind::Function(function),
                            )),
                            map: PigmentMap::Colours(grey_ramp()),
                            transform: Transform::IDENTITY,
                        };
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
        }
        if uv_mapping && pigment.uv_mapped().is_none() {
            pigment = Pigment::UvMapped(Box::new(pigment));
        }
        Ok(pigment)
    }

    /// Stores a `pigment_map`'s entries: into the pigment's pattern, or as an average.
    fn attach_pigment_map(
        &mut self,
        pigment: &mut Pigment,
        entries: Vec<(f64, Pigment)>,
        average: bool,
        span: Span,
    ) -> EvalResult<()> {
        if average {
            // The transformations written since `average` move the map's pigments too.
            let mut entries = entries;
            match pigment {
                Pigment::Average {
                    entries: old,
                    transform,
                    ..
                } => {
                    for (_, entry) in &mut entries {
                        entry.transform(transform);
                    }
                    *old = entries;
                }
                _ => {
                    *pigment = Pigment::Average {
                        entries,
                        transform: Transform::IDENTITY,
                        warps: None,
                    }
                }
            }
            return Ok(());
        }
        match pigment {
            Pigment::Pattern { map, transform, .. } => {
                // The transformations written between the pattern and its map move the
                // map's pigments too (measured).
                let mut entries = entries;
                for (_, entry) in &mut entries {
                    entry.transform(transform);
                }
                *map = PigmentMap::Pigments(entries);
                Ok(())
            }
            _ => Err(self
                .runtime
                .error(span, "a `pigment_map` needs a pattern before it")
                .with_label("no pattern in this pigment yet")
                .into()),
        }
    }

    /// The pigments of a block pattern (`checker A, B`, `hexagon A, B, C`, `brick A, B`).
    /// Missing ones take the pattern's default colours, or black once a `pigment { }` block
    /// was given (measured: `checker pigment { Green }` is green and black, `checker Green`
    /// green and povray's default green, `brick Green` green and the default red brick).
    fn block_list(
        &mut self,
        stream: &mut Stream,
        count: usize,
        pattern: &Pattern,
    ) -> EvalResult<Vec<Pigment>> {
        let defaults = pattern.default_block_colours();
        let mut blocks = Vec::with_capacity(count);
        let mut block_given = false;
        for index in 0..count {
            if index > 0 {
                self.skip_comma(stream)?;
            }
            let [r, g, b] = match defaults.get(index) {
                Some(&default) if !block_given => default,
                _ => [0.0; 3],
            };
            block_given |= matches!(self.peek_item(stream)?, Some(Item::Block(_)));
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
                            // `[0.2 Red green 0.3]`: components alone change the entry's
                            // colour (black when it has none yet).
                            Item::Expr(Expr::Colour(literal))
                                if literal.is_components_only() && !values.is_empty() =>
                            {
                                if values.len() < 2 {
                                    values.push((Value::Colour(Colour::BLACK), literal.span));
                                }
                                let last = values.len() - 1;
                                let (value, at) = values[last].clone();
                                let mut colour = self.to_colour(value, at)?;
                                self.apply_colour_components(&mut colour, literal)?;
                                values[last] = (Value::Colour(colour), at);
                            }
                            Item::Expr(e) => values.push((self.eval_expr(e)?, e.span())),
                            // `[0.2 Red filter 0.3]`: `filter` and `transmit` change the
                            // entry's colour (black when it has none yet).
                            Item::Keyword(word, span)
                                if matches!(&**word, "filter" | "transmit") =>
                            {
                                let amount = self.expect_float(&mut entry, "a float")?;
                                if values.len() < 2 {
                                    values.push((Value::Colour(Colour::BLACK), *span));
                                }
                                let last = values.len() - 1;
                                let (value, at) = values[last].clone();
                                let mut colour = self.to_colour(value, at)?;
                                set_colour_component(&mut colour, word, amount);
                                values[last] = (Value::Colour(colour), at);
                            }
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
                                .runtime
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
            let mut texture = self.scene.default_texture.clone();
            match value {
                Value::Texture(t) => texture = (*t).clone(),
                Value::Pigment(p) => texture.pigment = Rc::unwrap_or_clone(p),
                Value::Finish(f) => texture.finish = Arc::new(Rc::unwrap_or_clone(f)),
                Value::Normal(n) => texture.normal = Some(Box::new(Rc::unwrap_or_clone(n))),
                Value::Nothing => {}
                _ => return Err(self.unexpected_in(&item, "#default")),
            }
            self.scene.set_default_texture(texture);
        }
        Ok(())
    }
}

/// Sets the component a `filter` or `transmit` keyword names.
fn set_colour_component(colour: &mut Colour, keyword: &str, amount: f64) {
    if keyword == "filter" {
        colour.filter = amount;
    } else {
        colour.transmit = amount;
    }
}

/// Gives `pigment` the pattern `spec` with `map`. A pigment that already has a pattern (a
/// named pigment or the texture's, being modified) only changes its pattern: it keeps its
/// transformations and, when both patterns have continuous values, its colour or pigment
/// map when one was written (measured: `pigment { P gradient x }` with `P` a scaled granite
/// with a colour map is a scaled gradient with that map).
fn set_pattern(pigment: &mut Pigment, spec: Pattern, map: PigmentMap) {
    if let Pigment::Pattern {
        pattern,
        map: old_map,
        ..
    } = pigment
    {
        // A map the old pattern only had by default is not kept (measured: `pigment { P
        // bozo }` with `P` an agate takes bozo's own map).
        let written_map = match old_map {
            PigmentMap::Blocks(_) => false,
            PigmentMap::Colours(colours) => *colours != default_colours(pattern),
            PigmentMap::Pigments(_) => true,
        };
        let keeps_map = spec.block_count().is_none() && written_map;
        **pattern = spec;
        if !keeps_map {
            *old_map = map;
        }
        return;
    }
    *pigment = Pigment::Pattern {
        pattern: Box::new(spec),
        map,
        transform: Transform::IDENTITY,
    };
}

/// The pattern that the pattern modifiers written in `pigment` change: the pattern of a
/// patterned pigment, or the pattern that carries an image map's or average's turbulence and
/// warps (made on first use, following the scene's noise generator `scene_noise`). `None`
/// for other pigments.
pub(super) fn modified_pattern<'a>(
    pigment: &'a mut Pigment,
    scene_noise: &SceneNoiseGenerator,
) -> Option<&'a mut Pattern> {
    let carrier = |kind| {
        let mut pattern = Pattern::new(kind);
        pattern.use_scene_noise_generator(scene_noise);
        Box::new(pattern)
    };
    match pigment {
        Pigment::Pattern { pattern, .. } => Some(pattern),
        Pigment::Image { image, warps, .. } => Some(warps.get_or_insert_with(|| {
            carrier(crate::texture::pattern::PatternKind::ImagePattern(
                image.clone(),
            ))
        })),
        // The pattern only carries the warps; its kind (any would do) is never evaluated.
        Pigment::Average { warps, .. } => {
            Some(warps.get_or_insert_with(|| carrier(crate::texture::pattern::PatternKind::Planar)))
        }
        _ => None,
    }
}

/// The colour map of a pigment that names `pattern` without one: the pattern's built-in map,
/// or else black to white.
fn default_colours(pattern: &Pattern) -> Vec<(f64, Colour)> {
    if pattern.default_colour_map.is_empty() {
        return grey_ramp();
    }
    let entries = pattern.default_colour_map.iter();
    entries
        .map(|&(key, [red, green, blue])| (key, Colour::rgb(red, green, blue)))
        .collect()
}

/// POV-Ray's map for a pattern without one: black to white.
pub(super) fn grey_ramp() -> Vec<(f64, Colour)> {
    vec![(0.0, Colour::BLACK), (1.0, Colour::WHITE)]
}

/// Applies a texture's `uv_mapping` to the pigments and normals of the texture and of the
/// textures it is made of.
pub(crate) fn map_texture_by_uv(texture: &mut Texture) {
    if let Some(normal) = &mut texture.normal {
        normal.uv_mapped = true;
    }
    if !matches!(texture.pigment, Pigment::Solid(_) | Pigment::UvMapped(_)) {
        let pigment = std::mem::replace(&mut texture.pigment, Pigment::Solid(Colour::BLACK));
        texture.pigment = Pigment::UvMapped(Box::new(pigment));
    }
    if let Some(compound) = &mut texture.compound {
        match Arc::make_mut(compound) {
            CompoundTexture::Layered(layers) => layers.iter_mut().for_each(map_texture_by_uv),
            CompoundTexture::Pattern { map, .. } => map.for_each_mut(map_texture_by_uv),
            CompoundTexture::Average(entries) => entries
                .iter_mut()
                .for_each(|(_, entry)| map_texture_by_uv(entry)),
            CompoundTexture::MaterialMap { textures, .. } => {
                textures.iter_mut().for_each(map_texture_by_uv)
            }
        }
    }
}
