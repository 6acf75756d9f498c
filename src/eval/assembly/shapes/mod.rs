//! Bodies of the shapes beyond the basic ones: `smooth_triangle`, `polygon`, `mesh`, `mesh2`,
//! `poly`, `cubic` and `quartic`.
//!
//! In: the block's item stream, positioned after the keyword's brace. Out: the [`Shape`], with
//! the stream left at the object modifiers that follow the shape's own data.
//! Holds: bad counts and indices end in spanned diagnostics, never panics. Meshes are read in
//! `shapes/mesh.rs`.

mod bicubic_patch;
mod blob;
mod height_field;
mod isosurface;
mod julia;
mod mesh;
mod parametric;
mod prism;
mod sor;
mod sphere_sweep;
mod spindle;
mod text;

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{Poly, Polygon, Shape};
use crate::syntax::ast::{Block, BlockHead, Expr, Item};
use glam::DVec3;
use std::sync::Arc;

/// Most points a `polygon` or entries a `mesh2` list may declare (guards huge allocations).
const LIST_LIMIT: usize = 50_000_000;

/// Number of coefficients of a polynomial of total degree `order` in three variables.
pub(crate) fn poly_term_count(order: u32) -> usize {
    let n = order as usize;
    (n + 1) * (n + 2) * (n + 3) / 6
}

impl Evaluator {
    /// `smooth_triangle { c1, n1, c2, n2, c3, n3 }`.
    pub(crate) fn eval_smooth_triangle(&mut self, stream: &mut Stream) -> EvalResult<Shape> {
        let mut corners = [DVec3::ZERO; 3];
        let mut normals = [DVec3::ZERO; 3];
        for index in 0..3 {
            corners[index] = self.expect_vector(stream, "a corner")?;
            normals[index] = self.expect_vector(stream, "the corner's normal")?;
        }
        Ok(Shape::SmoothTriangle {
            corners: Box::new(corners),
            normals: Box::new(normals),
        })
    }

    /// `polygon { n, p1, .. pn }`: a sub-polygon closes when a point repeats its first point.
    pub(crate) fn eval_polygon(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let count = self.expect_count(stream, "the number of points", span)?;
        let mut outlines = Vec::new();
        let mut current: Vec<DVec3> = Vec::new();
        for _ in 0..count {
            let point = self.expect_vector(stream, "a point")?;
            if current.first() == Some(&point) {
                outlines.push(std::mem::take(&mut current));
            } else {
                current.push(point);
            }
        }
        if !current.is_empty() {
            if current.len() > 1 {
                self.runtime
                    .warn(span, "polygon outline not closed; closing it");
            }
            outlines.push(current);
        }
        outlines.retain(|outline| outline.len() >= 3);
        Ok(Shape::Polygon(Arc::new(Polygon { outlines })))
    }

    /// `poly { order, <coefficients> }`, `cubic { <20> }` or `quartic { <35> }`.
    pub(crate) fn eval_poly(
        &mut self,
        head: &str,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Shape> {
        let order = match head {
            "cubic" => 3,
            "quartic" => 4,
            _ => {
                let order = self.expect_float(stream, "the order")?;
                if !(2.0..=7.0).contains(&order) || order.fract() != 0.0 {
                    return Err(self
                        .runtime
                        .error(span, format!("poly order must be 2 to 7, found {order}"))
                        .into());
                }
                self.skip_comma(stream)?;
                order as u32
            }
        };
        let wanted = poly_term_count(order);
        let item = self.next_item(stream)?;
        let Some(Item::Expr(Expr::Vector(elements, vspan))) = item else {
            return Err(self
                .runtime
                .error(span, format!("expected `< {wanted} coefficients >`"))
                .into());
        };
        if elements.len() != wanted {
            return Err(self
                .runtime
                .error(
                    vspan,
                    format!(
                        "a polynomial of order {order} has {wanted} coefficients, found {}",
                        elements.len()
                    ),
                )
                .into());
        }
        let coefficients = elements
            .iter()
            .map(|e| self.eval_float(e))
            .collect::<EvalResult<Vec<f64>>>()?;
        Ok(Shape::Poly(Arc::new(Poly {
            order,
            coefficients,
            sturm: false,
        })))
    }

    /// `text { ttf "font.ttf" "string" thickness, offset }`, or `internal N` for one of
    /// POV-Ray's four built-in fonts, read from the font files of the same names that
    /// POV-Ray installs beside its include files.
    pub(crate) fn eval_text(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let mut internal = false;
        let (font, font_span) = match self.next_item(stream)? {
            Some(Item::Keyword(word, _)) if &*word == "ttf" => {
                self.expect_string(stream, "the font file name")?
            }
            Some(Item::Keyword(word, _) | Item::Expr(Expr::Ident(word, _)))
                if &*word == "internal" =>
            {
                let (value, number_span) = self.expect_value(stream, "a font number")?;
                let number = self.to_float(value, number_span)?;
                internal = true;
                (internal_font(number).to_string(), number_span)
            }
            Some(other) => {
                return Err(self
                    .runtime
                    .error(other.span(), "expected `ttf` and a font file name")
                    .with_label("durer reads TrueType fonts only")
                    .with_help("or `internal 0` to `internal 3` for POV-Ray's built-in fonts")
                    .into())
            }
            None => {
                return Err(self
                    .runtime
                    .error(span, "expected `ttf` and a font file name")
                    .into())
            }
        };
        let (string, _) = self.expect_string(stream, "the text")?;
        let thickness = self.expect_float(stream, "the thickness")?;
        let offset = self.expect_vector(stream, "the offset")?;
        // POV-Ray also tries the name with `.ttf` added.
        // A failure reports the name as written, not the one with `.ttf` added.
        let found = self.runtime.find_include(&font).or_else(|first| {
            self.runtime
                .find_include(&format!("{font}.ttf"))
                .map_err(|_| first)
        });
        let path = match found {
            Ok(path) => path,
            Err(missing) => {
                if let Some(refusal) = &missing.refused {
                    return Err(self.runtime.refused(font_span, refusal).into());
                }
                let mut error = self
                    .runtime
                    .error(font_span, format!("font file `{font}` not found"))
                    .with_label("looked next to the scene and on the include path");
                if internal {
                    error = error.with_help(format!(
                        "this built-in font is POV-Ray's `{font}`, installed with its include \
                         files: add their folder with -L"
                    ));
                }
                return Err(error.into());
            }
        };
        let bytes =
            text::font_bytes(&path, |p| self.runtime.read_file_bytes(p)).map_err(|error| {
                self.runtime.error(
                    font_span,
                    format!("cannot read `{}`: {error}", path.display()),
                )
            })?;
        let glyphs =
            text::layout_text(&bytes, &string, thickness, offset.truncate()).ok_or_else(|| {
                self.runtime.error(
                    font_span,
                    format!("`{}` is not a TrueType font", path.display()),
                )
            })?;
        Ok(Shape::Text(Arc::new(glyphs)))
    }

    /// Reads a string value.
    fn expect_string(&mut self, stream: &mut Stream, what: &str) -> EvalResult<(String, Span)> {
        let (value, span) = self.expect_value(stream, what)?;
        match value {
            Value::String(s) => Ok((s.to_string(), span)),
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected {what}, found {}", other.type_name()),
                )
                .into()),
        }
    }

    /// A non-negative whole number such as a list length.
    fn expect_count(&mut self, stream: &mut Stream, what: &str, span: Span) -> EvalResult<usize> {
        let count = self.expect_float(stream, what)?;
        if !(0.0..=LIST_LIMIT as f64).contains(&count) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("{what} must be 0 to {LIST_LIMIT}, found {count}"),
                )
                .into());
        }
        Ok(count as usize)
    }

    /// `n, v1, .. vn` of `vertex_vectors` or `normal_vectors`.
    fn vector_list(&mut self, stream: &mut Stream, span: Span) -> EvalResult<Vec<DVec3>> {
        let count = self.expect_count(stream, "the number of vectors", span)?;
        let mut list = Vec::with_capacity(count.min(1 << 20));
        for _ in 0..count {
            self.runtime
                .count_geometry(std::mem::size_of::<DVec3>() as u64, span)?;
            list.push(self.expect_vector(stream, "a vector")?);
        }
        self.expect_end(stream, "vector list")?;
        Ok(list)
    }

    /// `n, <a, b, c> ..` of `normal_indices` or `uv_indices` (stray floats are skipped).
    fn index_list(&mut self, stream: &mut Stream, span: Span) -> EvalResult<Vec<([f64; 3], Span)>> {
        let count = self.expect_count(stream, "the number of faces", span)?;
        let mut list = Vec::with_capacity(count.min(1 << 20));
        while let Some(item) = self.next_item(stream)? {
            if matches!(item, Item::Comma(_)) {
                continue;
            }
            let item_span = item.span();
            let value = self.item_value(&item)?;
            match value {
                Value::Vector(v) => {
                    let c = v.to_dvec3();
                    self.runtime.count_geometry(
                        std::mem::size_of::<([f64; 3], Span)>() as u64,
                        item_span,
                    )?;
                    list.push(([c.x, c.y, c.z], item_span));
                }
                Value::Float(_) => {}
                other => {
                    return Err(self
                        .runtime
                        .error(
                            item_span,
                            format!("expected an index vector, found {}", other.type_name()),
                        )
                        .into())
                }
            }
        }
        self.with_declared_count(list, count, span)
    }

    /// `list` when it holds the `count` entries its block declared, else an error at `span`.
    pub(crate) fn with_declared_count<T>(
        &self,
        list: Vec<T>,
        count: usize,
        span: Span,
    ) -> EvalResult<Vec<T>> {
        if list.len() != count {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("{count} entries declared, {} given", list.len()),
                )
                .into());
        }
        Ok(list)
    }
}

/// The keyword of a block ("" for a conditional head).
fn block_word(block: &Block) -> &str {
    match &block.head {
        BlockHead::Word(word) => word,
        BlockHead::Conditional(_) => "",
    }
}

/// The font file standing for POV-Ray's built-in font `internal N`: its manual's list, and
/// font 0 for a number out of range.
fn internal_font(number: f64) -> &'static str {
    const FONTS: [&str; 4] = ["povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"];
    let index = if (0.0..4.0).contains(&number) {
        number as usize
    } else {
        0
    };
    FONTS[index]
}
