//! `text { ttf "font.ttf" "string" thickness, offset }`: TrueType glyphs laid out as
//! extruded outlines.
//!
//! In: the font file (found like an include file), the string, the thickness and the offset
//! added after each character. Out: one [`Extrusion`] per visible glyph, in text space (one em
//! is one unit; the first glyph's left edge is at the origin, baseline on y = 0, extruded from z = 0 to
//! the thickness). Holds: fonts are read once per file per thread; a font that cannot be read
//! or parsed is a diagnostic, never a panic.

use crate::scene::Extrusion;
use glam::DVec2;
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

thread_local! {
    /// Font files already read, by path.
    static FONT_FILES: RefCell<HashMap<PathBuf, Rc<Vec<u8>>>> = RefCell::new(HashMap::new());
}

/// The bytes of a font file, read on first use.
pub(crate) fn font_bytes(
    path: &Path,
    read: impl FnOnce(&Path) -> std::io::Result<Vec<u8>>,
) -> std::io::Result<Rc<Vec<u8>>> {
    if let Some(bytes) = FONT_FILES.with(|files| files.borrow().get(path).cloned()) {
        return Ok(bytes);
    }
    let bytes = Rc::new(read(path)?);
    FONT_FILES.with(|files| {
        files
            .borrow_mut()
            .insert(path.to_path_buf(), Rc::clone(&bytes))
    });
    Ok(bytes)
}

/// Collects a glyph outline as quadratic segments, scaled and moved into text space.
struct SegmentCollector {
    scale: f64,
    origin: DVec2,
    start: DVec2,
    current: DVec2,
    segments: Vec<[DVec2; 4]>,
}

impl SegmentCollector {
    fn point(&self, x: f32, y: f32) -> DVec2 {
        self.origin + DVec2::new(f64::from(x), f64::from(y)) * self.scale
    }

    fn line(&mut self, to: DVec2) {
        if to != self.current {
            self.segments.push(line_segment(self.current, to));
        }
        self.current = to;
    }

    fn quadratic(&mut self, control: DVec2, to: DVec2) {
        let from = self.current;
        self.segments.push([
            from,
            from + (control - from) * (2.0 / 3.0),
            to + (control - to) * (2.0 / 3.0),
            to,
        ]);
        self.current = to;
    }
}

impl ttf_parser::OutlineBuilder for SegmentCollector {
    fn move_to(&mut self, x: f32, y: f32) {
        self.start = self.point(x, y);
        self.current = self.start;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let to = self.point(x, y);
        self.line(to);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let control = self.point(x1, y1);
        let to = self.point(x, y);
        self.quadratic(control, to);
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (c1, c2, to) = (self.point(x1, y1), self.point(x2, y2), self.point(x, y));
        self.segments.push([self.current, c1, c2, to]);
        self.current = to;
    }

    fn close(&mut self) {
        let start = self.start;
        self.line(start);
    }
}

/// Lays out `text` in the font `data`; `None` when the font cannot be parsed.
pub(crate) fn layout_text(
    data: &[u8],
    text: &str,
    thickness: f64,
    offset: DVec2,
) -> Option<Vec<Extrusion>> {
    let face = ttf_parser::Face::parse(data, 0).ok()?;
    let units = f64::from(face.units_per_em());
    if units <= 0.0 {
        return None;
    }
    let scale = 1.0 / units;
    let mut position = DVec2::ZERO;
    let mut glyphs = Vec::new();
    let mut previous: Option<ttf_parser::GlyphId> = None;
    for character in text.chars() {
        let glyph = face
            .glyph_index(character)
            .unwrap_or(ttf_parser::GlyphId(0));
        match previous {
            Some(left) => position.x += kerning(&face, left, glyph) * scale,
            // POV-Ray starts the text at the first glyph's left edge, not at its origin.
            None => {
                let left_edge = face
                    .glyph_bounding_box(glyph)
                    .map_or(0.0, |b| f64::from(b.x_min));
                position.x -= left_edge * scale;
            }
        }
        previous = Some(glyph);
        let mut collector = SegmentCollector {
            scale,
            origin: position,
            start: position,
            current: position,
            segments: Vec::new(),
        };
        if face.outline_glyph(glyph, &mut collector).is_some() && !collector.segments.is_empty() {
            glyphs.push(Extrusion {
                segments: collector.segments,
                depth: (0.0, thickness),
                open: false,
                conic: false,
            });
        }
        let advance = face.glyph_hor_advance(glyph).map_or(0.0, f64::from);
        position += DVec2::new(advance * scale, 0.0) + offset;
    }
    Some(glyphs)
}

/// The horizontal kerning between two glyphs in font units, from the `kern` table's format-0
/// subtables (0 without one).
///
/// The pairs are searched one by one rather than by binary search: some fonts shipped with
/// POV-Ray (cyrvetic.ttf) have unsorted pairs, and POV-Ray still finds them.
fn kerning(face: &ttf_parser::Face, left: ttf_parser::GlyphId, right: ttf_parser::GlyphId) -> f64 {
    let Some(table) = face.raw_face().table(ttf_parser::Tag::from_bytes(b"kern")) else {
        return 0.0;
    };
    let read = |at: usize| -> Option<u16> {
        Some(u16::from_be_bytes([*table.get(at)?, *table.get(at + 1)?]))
    };
    let wanted = (u32::from(left.0) << 16) | u32::from(right.0);
    let mut total = 0.0;
    let subtable_count = read(2).unwrap_or(0);
    let mut start = 4;
    for _ in 0..subtable_count {
        let (Some(length), Some(coverage), Some(pairs)) =
            (read(start + 2), read(start + 4), read(start + 6))
        else {
            break;
        };
        let horizontal = coverage & 1 != 0;
        let format = coverage >> 8;
        // Skip minimum-value and cross-stream subtables.
        if horizontal && format == 0 && coverage & 0b110 == 0 {
            for pair in 0..usize::from(pairs) {
                let at = start + 14 + 6 * pair;
                let (Some(l), Some(r), Some(value)) = (read(at), read(at + 2), read(at + 4)) else {
                    break;
                };
                if (u32::from(l) << 16) | u32::from(r) == wanted {
                    total += f64::from(value as i16);
                    break;
                }
            }
        }
        if length < 6 {
            break;
        }
        start += usize::from(length);
    }
    total
}

/// A straight segment as a cubic Bézier.
pub(crate) fn line_segment(from: DVec2, to: DVec2) -> [DVec2; 4] {
    [
        from,
        from + (to - from) / 3.0,
        from + (to - from) * (2.0 / 3.0),
        to,
    ]
}
