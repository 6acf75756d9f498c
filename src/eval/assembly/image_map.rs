//! `image_map { .. }` and `bump_map { .. }` bodies: the file, its projection and options.
//!
//! In: the body items. Out: an [`ImageMap`] with the pixels decoded and made linear.
//! Holds: a missing or unreadable file is an error at the file name's span listing the
//! folders searched.
//!
//! Gamma (POV-Ray 3.7): an image's stored values are decoded with the `gamma` given in the
//! block (`gamma srgb` or a number), else with the sRGB transfer function (JPEG, TGA, GIF),
//! except for HDR files, which are linear already, PPM and PGM files, whose stored values
//! are used as they are under any `assumed_gamma` (measured), and PNG files that state no gamma (no `gAMA`, `sRGB`
//! or `iCCP` chunk) read under `#version` below 3.7, whose stored values are used as they
//! are (measured: a stored 85 gives 0.333333 at `assumed_gamma` 1 and 2.2 alike); then
//! raised to 1 / `assumed_gamma` to join the scene's
//! colours. In a legacy scene (no `assumed_gamma` and no `#version 3.7` yet when the image is
//! read) only a `gamma` given in the block decodes them (measured: a stored 32, 64, 128, 192
//! is written back unchanged with ambient 1 under any `assumed_gamma`, and as 4, 16, 64,
//! 145 with `gamma 2` in a legacy scene). `image_pattern` and `bump_map` use the stored values
//! whatever `gamma` says (measured: a stored 64 gives the pattern value 0.25098 with and
//! without `gamma 1.0`; bump tilts are linear in the stored grey levels).

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::raster::{load, RasterFormat, StoredEncoding};
use crate::syntax::ast::{BlockHead, Item};
use crate::{
    math::Transform,
    texture::{
        pattern::{Pattern, PatternKind},
        CompoundTexture, ImageGamma, ImageMap, ImageProjection, Texture,
    },
};
use std::sync::Arc;

impl Evaluator {
    /// An `image_pattern { .. }` block as a pattern; `None` for any other item.
    pub(crate) fn image_pattern(&mut self, item: &Item) -> EvalResult<Option<Pattern>> {
        let Item::Block(block) = item else {
            return Ok(None);
        };
        if !matches!(&block.head, BlockHead::Word(word) if &**word == "image_pattern") {
            return Ok(None);
        }
        let mut body = Stream::new(block.body.clone());
        let (image, _) =
            self.read_image(&mut body, block.head_span, ImageUse::StoredValues, None)?;
        Ok(Some(
            self.new_pattern(PatternKind::ImagePattern(Arc::new(image))),
        ))
    }

    /// Reads an `image_map` or `bump_map` body (`head_span` is the block's keyword), with
    /// the `bump_size` given inside it.
    pub(crate) fn eval_image_map(
        &mut self,
        stream: &mut Stream,
        head_span: Span,
    ) -> EvalResult<(ImageMap, Option<f64>)> {
        self.read_image(stream, head_span, ImageUse::Colours, None)
    }

    /// Reads a `material_map` body: the image (stored values, palette indices kept) and its
    /// textures (POV-Ray 3.7 rejects transformations inside the block).
    pub(crate) fn eval_material_map(
        &mut self,
        stream: &mut Stream,
        head_span: Span,
    ) -> EvalResult<CompoundTexture> {
        let mut materials = MaterialItems {
            textures: Vec::new(),
        };
        let (image, _) = self.read_image(
            stream,
            head_span,
            ImageUse::StoredValues,
            Some(&mut materials),
        )?;
        if materials.textures.is_empty() {
            return Err(self
                .runtime
                .error(head_span, "this `material_map` lists no textures")
                .with_label("expected `texture { .. }` entries after the file name")
                .into());
        }
        Ok(CompoundTexture::MaterialMap {
            image: Arc::new(image),
            textures: materials.textures,
            transform: Transform::IDENTITY,
        })
    }

    /// Reads a `bump_map` body (`head_span` is the block's keyword), with the `bump_size`
    /// given inside it; the heights are the stored values (measured: no gamma decoding).
    pub(crate) fn eval_bump_map(
        &mut self,
        stream: &mut Stream,
        head_span: Span,
    ) -> EvalResult<(ImageMap, Option<f64>)> {
        self.read_image(stream, head_span, ImageUse::StoredValues, None)
    }

    /// Reads an image block's body for `purpose`; `materials` collects a `material_map`'s
    /// textures (other blocks reject them).
    fn read_image(
        &mut self,
        stream: &mut Stream,
        head_span: Span,
        purpose: ImageUse,
        mut materials: Option<&mut MaterialItems>,
    ) -> EvalResult<(ImageMap, Option<f64>)> {
        let mut bump_size = None;
        let mut format = RasterFormat::System;
        let mut file: Option<(String, Span)> = None;
        let mut projection = ImageProjection::Planar;
        let mut once = false;
        let mut interpolation = 0u8;
        let mut filter_all = 0.0;
        let mut transmit_all = 0.0;
        let mut gamma: Option<ImageGamma> = None;
        let mut use_index = false;
        let mut use_alpha = false;
        let mut palette_filter = Vec::new();
        let mut palette_transmit = Vec::new();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    w if RasterFormat::from_keyword(w).is_some() && file.is_none() => {
                        format = RasterFormat::from_keyword(w).unwrap_or(RasterFormat::System);
                    }
                    "map_type" => {
                        let kind = self.expect_float(stream, "a map type")?;
                        projection = match kind as i64 {
                            0 => ImageProjection::Planar,
                            1 => ImageProjection::Spherical,
                            2 => ImageProjection::Cylindrical,
                            5 => ImageProjection::Torus,
                            _ => {
                                return Err(self
                                    .runtime
                                    .error(
                                        *span,
                                        format!("`map_type {kind}` is not one of 0, 1, 2 or 5"),
                                    )
                                    .with_label("unsupported map type")
                                    .into())
                            }
                        };
                    }
                    "once" => once = true,
                    "interpolate" => interpolation = self.expect_float(stream, "2 or 4")? as u8,
                    "filter" | "transmit" => {
                        // Later settings win (measured): `all` replaces earlier entries.
                        let (all_amount, entries) = if &**word == "filter" {
                            (&mut filter_all, &mut palette_filter)
                        } else {
                            (&mut transmit_all, &mut palette_transmit)
                        };
                        match self.peek_item(stream)? {
                            Some(Item::Keyword(all, _)) if &*all == "all" => {
                                let _ = self.next_item(stream)?;
                                *all_amount = self.expect_float(stream, "a float")?;
                                entries.clear();
                            }
                            _ => {
                                let index = self.expect_float(stream, "a palette index")?;
                                self.skip_comma(stream)?;
                                let amount = self.expect_float(stream, "a float")?;
                                if !(0.0..256.0).contains(&index) {
                                    return Err(self
                                        .runtime
                                        .error(
                                            *span,
                                            format!("palette index {index} is outside 0 to 255"),
                                        )
                                        .with_label("no such palette entry")
                                        .into());
                                }
                                let index = index as u8;
                                entries.retain(|(entry, _)| *entry != index);
                                entries.push((index, amount));
                            }
                        }
                    }
                    "gamma" => {
                        let (value, value_span) = self.expect_value(stream, "a gamma")?;
                        let value = self.to_float(value, value_span)?;
                        gamma = Some(if value > 0.0 {
                            ImageGamma::Power(value)
                        } else {
                            ImageGamma::Srgb
                        });
                    }
                    "srgb" => gamma = Some(ImageGamma::Srgb),
                    "premultiplied" => {
                        let _ = self.optional_bool(stream)?;
                    }
                    "use_alpha" => use_alpha = self.optional_bool(stream)?,
                    "use_color" | "use_colour" => use_index = false,
                    "use_index" => use_index = true,
                    "bump_size" => bump_size = Some(self.expect_float(stream, "a float")?),
                    _ => return Err(self.unexpected_in(&item, "image_map")),
                },
                Item::Expr(expr) if file.is_none() => {
                    let value = self.eval_expr(expr)?;
                    match value {
                        Value::String(name) => file = Some((name.to_string(), expr.span())),
                        _ => return Err(self.unexpected_in(&item, "image_map")),
                    }
                }
                Item::Expr(expr) if materials.is_some() => match self.eval_expr(expr)? {
                    Value::Texture(texture) => {
                        if let Some(materials) = materials.as_deref_mut() {
                            materials.textures.push(Texture::clone(&texture));
                        }
                    }
                    _ => return Err(self.unexpected_in(&item, "material_map")),
                },
                Item::Block(block) if matches!(&block.head, BlockHead::Word(word) if &**word == "texture") =>
                {
                    let Some(materials) = materials.as_deref_mut() else {
                        return Err(self.unexpected_in(&item, "image_map"));
                    };
                    let mut body = Stream::new(block.body.clone());
                    materials.textures.push(self.eval_texture(&mut body)?);
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "image_map")),
            }
        }
        let Some((name, name_span)) = file else {
            return Err(self
                .runtime
                .error(head_span, "this image map names no image file")
                .with_label("expected a file name in quotes")
                .into());
        };
        let path = self
            .runtime
            .find_image(&name, name_span, "image file", format)?;
        let raster = load(&path, format).map_err(|message| {
            self.runtime
                .error(
                    name_span,
                    format!("cannot read image \"{name}\": {message}"),
                )
                .with_label("unreadable image")
        })?;
        let working_gamma = self.working_gamma();
        // PPM files, and PNG files stating no gamma in a scene older than 3.7, give their
        // stored values as scene colours under any `assumed_gamma` (measured: a stored
        // 100/255 in a `#version 3.6` scene renders as 100 at `assumed_gamma` 2.2 and as
        // 168, the same 100/255 displayed, at `assumed_gamma` 1).
        let legacy_png =
            self.runtime.version().0 < 3.7 && raster.encoding == StoredEncoding::UnstatedPng;
        let as_stored =
            gamma.is_none() && (raster.encoding == StoredEncoding::AsStored || legacy_png);
        let decoding = match gamma {
            _ if purpose == ImageUse::StoredValues || as_stored => ImageGamma::Linear,
            Some(gamma) => gamma,
            None if raster.encoding == StoredEncoding::Linear || working_gamma.is_none() => {
                ImageGamma::Linear
            }
            None => ImageGamma::Srgb,
        };
        // Into the scene's working gamma (none for stored values, PPM files without a
        // `gamma` and legacy scenes).
        let encoding = match working_gamma {
            Some(gamma) if purpose == ImageUse::Colours && gamma != 1.0 && !as_stored => {
                1.0 / gamma as f32
            }
            _ => 1.0,
        };
        let working = |value: f32| {
            let value = linear(value, decoding);
            if encoding == 1.0 {
                value
            } else {
                value.max(0.0).powf(encoding)
            }
        };
        // `use_alpha` on a file that stores no transparency reads its red channel
        // (measured): the alpha channel, which only `use_alpha` reads then, holds 1 − red.
        let red_as_alpha = use_alpha && raster.use_alpha_reads_red();
        let pixels = raster
            .pixels
            .iter()
            .map(|&[r, g, b, a]| {
                let a = if red_as_alpha { 1.0 - r } else { a };
                [working(r), working(g), working(b), a]
            })
            .collect();
        let image = ImageMap {
            width: raster.width,
            height: raster.height,
            pixels,
            projection,
            once,
            interpolation,
            filter_all,
            transmit_all,
            use_index,
            use_alpha,
            palette_indices: raster.palette_indices,
            palette_filter,
            palette_transmit,
            file: Some(Arc::new(crate::texture::ImageFile {
                path: path.clone(),
                format,
                gamma,
            })),
        };
        Ok((image, bump_size))
    }
}

impl Evaluator {
    /// The gamma of scene colours at this point of parsing, which image colours are
    /// converted to when the image is read (measured: povray uses the `assumed_gamma` and
    /// `#version` in force then, not at the end of parsing): the `assumed_gamma` given so
    /// far, else 1 under `#version 3.7`; `None` for a legacy scene, whose images are used as
    /// stored (decoded only by a `gamma` given in the block).
    fn working_gamma(&self) -> Option<f64> {
        match self.scene.settings.assumed_gamma {
            Some(gamma) if gamma > 0.0 && gamma.is_finite() => Some(gamma),
            _ if matches!(self.runtime.version(), (v, true) if v >= 3.7 - 1e-9) => Some(1.0),
            _ => None,
        }
    }
}

/// What a `material_map` body holds besides the image.
struct MaterialItems {
    /// The textures the pixels' indices choose from.
    textures: Vec<Texture>,
}

/// What an image block is read for.
#[derive(Clone, Copy, PartialEq, Eq)]
enum ImageUse {
    /// `image_map` and `bump_map`: colours made linear.
    Colours,
    /// `image_pattern` and `bump_map`: the stored values.
    StoredValues,
}

/// A stored channel value turned into linear light.
fn linear(value: f32, gamma: ImageGamma) -> f32 {
    match gamma {
        ImageGamma::Linear => value,
        ImageGamma::Power(exponent) => value.max(0.0).powf(exponent as f32),
        ImageGamma::Srgb => {
            if value <= 0.04045 {
                value / 12.92
            } else {
                ((value + 0.055) / 1.055).powf(2.4)
            }
        }
    }
}
