//! `height_field { png "file" | function W, H { .. } [smooth] [water_level W] [hierarchy B] }`.
//!
//! In: the item stream after the brace. Out: [`Shape::HeightField`] with its grid of heights.
//! Holds: heights are what POV-Ray makes of the file (measured with `trace`): a 16-bit value
//! over 65536, where an 8-bit grey level g counts as 257 g, an 8-bit colour pixel as
//! 256 red + green and a 16-bit colour pixel as 0.297 red + 0.589 green + 0.114 blue of its
//! 16-bit levels, cut toward zero (measured with PNG and PPM files); a palette PNG pixel as 256 times its palette index, whatever the colour;
//! a function is sampled at x = column / (W - 1), y = row / (H - 1) (row 0 at z = 1), and its
//! 16-bit level wraps around (see [`function_level`]). A missing file is a diagnostic listing
//! the folders searched.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::raster::{Raster, RasterFormat};
use crate::scene::{HeightField, HeightFieldSource, Shape};
use crate::syntax::ast::{Expr, FunctionLiteral, Item};
use std::rc::Rc;
use std::sync::Arc;

/// Most grid points a height field may have (guards huge allocations).
const GRID_LIMIT: f64 = 16e6;
/// The 16-bit scale of POV-Ray's height values.
const FULL_SCALE: f64 = 65535.0;
/// Heights are 16-bit values divided by this.
const HEIGHT_DIVISOR: f64 = 65536.0;

impl Evaluator {
    /// Reads a height field's source and modifiers.
    pub(crate) fn eval_height_field(
        &mut self,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Shape> {
        let first = self.next_item(stream)?;
        let (columns, rows, heights, source) = match first {
            Some(Item::Expr(Expr::Function(literal))) => self.height_function(&literal)?,
            Some(Item::Keyword(word, keyword_span)) => {
                let Some(format) = RasterFormat::from_keyword(&word) else {
                    return Err(self
                        .runtime
                        .error(keyword_span, format!("`{word}` is not an image format"))
                        .with_help("use png, pgm, ppm, tga, gif, pot, jpeg, hdr or sys")
                        .into());
                };
                let (name, name_span) = self.expect_file_name(stream)?;
                self.height_image(&name, name_span, format)?
            }
            Some(Item::Expr(expr)) => {
                let name_span = expr.span();
                match self.eval_expr(&expr)? {
                    Value::String(name) => {
                        self.height_image(&name, name_span, RasterFormat::System)?
                    }
                    other => {
                        return Err(self
                            .runtime
                            .error(
                                name_span,
                                format!("expected a file name, found {}", other.type_name()),
                            )
                            .into())
                    }
                }
            }
            _ => {
                return Err(self
                    .runtime
                    .error(span, "expected an image file or `function W, H { .. }`")
                    .into())
            }
        };
        let mut field = HeightField {
            columns,
            rows,
            heights,
            smooth: false,
            water_level: 0.0,
            source: Some(source),
        };
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) => match &**word {
                    "smooth" => field.smooth = true,
                    "water_level" => {
                        field.water_level = self.expect_float(stream, "the water level")?
                    }
                    "hierarchy" | "premultiplied" => {
                        self.optional_bool(stream)?;
                    }
                    "gamma" => {
                        self.expect_float(stream, "the gamma")?;
                    }
                    _ => {
                        stream.push_back(item);
                        break;
                    }
                },
                Item::Comma(_) => {}
                _ => {
                    stream.push_back(item);
                    break;
                }
            }
        }
        Ok(Shape::HeightField(Arc::new(field)))
    }

    /// Reads the file name after a format keyword.
    fn expect_file_name(&mut self, stream: &mut Stream) -> EvalResult<(Rc<str>, Span)> {
        let (value, span) = self.expect_value(stream, "the file name")?;
        match value {
            Value::String(name) => Ok((name, span)),
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected the file name, found {}", other.type_name()),
                )
                .into()),
        }
    }

    /// The grid of an image file.
    fn height_image(
        &mut self,
        name: &str,
        span: Span,
        format: RasterFormat,
    ) -> EvalResult<(usize, usize, Vec<f64>, HeightFieldSource)> {
        let path = self
            .runtime
            .find_image(name, span, "height field image", format)?;
        let raster = crate::raster::load(&path, format).map_err(|message| {
            self.runtime
                .error(
                    span,
                    format!("cannot read height field image \"{name}\": {message}"),
                )
                .with_label("unreadable image")
        })?;
        if raster.width < 2 || raster.height < 2 {
            return Err(self
                .runtime
                .error(span, "a height field image needs at least 2 by 2 pixels")
                .into());
        }
        let (columns, rows, heights) = image_heights(&raster);
        Ok((
            columns,
            rows,
            heights,
            HeightFieldSource::Image { path, format },
        ))
    }

    /// The grid of `function W, H { .. }`.
    fn height_function(
        &mut self,
        literal: &Rc<FunctionLiteral>,
    ) -> EvalResult<(usize, usize, Vec<f64>, HeightFieldSource)> {
        let [width, height] = literal.resolution.as_slice() else {
            return Err(self
                .runtime
                .error(
                    literal.span,
                    "a height field's function needs its resolution",
                )
                .with_help("write `function WIDTH, HEIGHT { .. }`")
                .into());
        };
        let columns = self.eval_float(width)?.floor();
        let rows = self.eval_float(height)?.floor();
        if !(columns >= 2.0 && rows >= 2.0 && columns * rows <= GRID_LIMIT) {
            return Err(self
                .runtime.error(
                    literal.span,
                    format!("a height field's resolution must be at least 2 by 2 and at most {GRID_LIMIT} points, found {columns} by {rows}"),
                )
                .into());
        }
        let function = self.compile_function(literal)?;
        let (columns, rows) = (columns as usize, rows as usize);
        let mut heights = vec![0.0; columns * rows];
        for row in 0..rows {
            // Grid row 0 is at z = 0, which is the function's y = 1.
            let y = 1.0 - row as f64 / (rows - 1) as f64;
            for column in 0..columns {
                let x = column as f64 / (columns - 1) as f64;
                let value = function.eval(&[x, y, 0.0]);
                heights[row * columns + column] = function_level(value) / HEIGHT_DIVISOR;
            }
        }
        let source = HeightFieldSource::Function {
            function,
            columns,
            rows,
        };
        Ok((columns, rows, heights, source))
    }
}

/// The 16-bit level POV-Ray makes of a function value (measured with `trace`): the value
/// times 65535 in single precision, cut toward zero and wrapped into 0 to 65535, so 1.1 is
/// low again and -0.1 high; values that are not finite give 0.
fn function_level(value: f64) -> f64 {
    let scaled = value as f32 * FULL_SCALE as f32;
    if !scaled.is_finite() {
        return 0.0;
    }
    (scaled.trunc() as i64).rem_euclid(HEIGHT_DIVISOR as i64) as f64
}

/// The heights of an image, grid row 0 being the image's bottom row.
fn image_heights(raster: &Raster) -> (usize, usize, Vec<f64>) {
    let (columns, rows) = (raster.width as usize, raster.height as usize);
    let mut heights = vec![0.0; columns * rows];
    for row in 0..rows {
        let image_row = (rows - 1 - row) as i64;
        for column in 0..columns {
            let [red, green, _, _] = raster.pixel(column as i64, image_row);
            let level = |value: f32, scale: f64| (f64::from(value) * scale).round();
            let palette_index = raster
                .palette_indices
                .as_ref()
                .and_then(|indices| indices.get(image_row as usize * columns + column));
            let value = if let Some(&index) = palette_index {
                f64::from(index) * 256.0
            } else if raster.grey || raster.high_dynamic_range {
                level(red, FULL_SCALE)
            } else if raster.sixteen_bit {
                // The grey level of the 16-bit channels, cut toward zero (measured).
                let [_, _, blue, _] = raster.pixel(column as i64, image_row);
                let grey = 0.297 * level(red, FULL_SCALE)
                    + 0.589 * level(green, FULL_SCALE)
                    + 0.114 * level(blue, FULL_SCALE);
                grey.floor()
            } else {
                level(red, 255.0) * 256.0 + level(green, 255.0)
            };
            heights[row * columns + column] = value.clamp(0.0, FULL_SCALE) / HEIGHT_DIVISOR;
        }
    }
    (columns, rows, heights)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::StoredEncoding;

    #[test]
    fn sixteen_bit_colour_pixels_give_their_grey_level_cut_toward_zero() {
        // Measured with a 16-bit RGB PNG: levels 17000, 15300, 4000 give height 14516.
        let level = |value: u16| f32::from(value) / 65535.0;
        let pixel = [level(17000), level(15300), level(4000), 1.0];
        let raster = Raster {
            width: 2,
            height: 2,
            pixels: vec![pixel; 4],
            grey: false,
            sixteen_bit: true,
            high_dynamic_range: false,
            alpha: false,
            palette_indices: None,
            encoding: StoredEncoding::Srgb,
        };
        let (_, _, heights) = image_heights(&raster);
        assert_eq!(heights[0] * HEIGHT_DIVISOR, 14516.0);
    }
}
