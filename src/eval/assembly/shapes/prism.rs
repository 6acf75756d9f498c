//! `prism { [spline] [sweep] height1, height2, n, points.. [open] }` (outlines in the XZ
//! plane swept along Y) and `lathe { [spline] n, points.. }` (a curve turned around Y).
//!
//! In: the item stream after the brace. Out: [`Shape::Prism`] or [`Shape::Lathe`] with every spline turned into
//! cubic Bézier segments. Holds: sub-prisms close where their start point repeats (a linear
//! spline's last one closes itself).

use super::text::line_segment;
use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{Extrusion, OutlineSpline, Shape, SplineOutline};
use crate::syntax::ast::Item;
use glam::DVec2;
use std::sync::Arc;

/// How the points of a prism are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Spline {
    Linear,
    Quadratic,
    Cubic,
    Bezier,
}

/// A polynomial segment `a t³ + b t² + c t + d`, t in [0, 1], as a cubic Bézier.
fn power_to_bezier(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> [DVec2; 4] {
    [d, d + c / 3.0, d + (2.0 * c + b) / 3.0, a + b + c + d]
}

/// Bézier segments of the sub-prisms of `points` for `spline`; `None` when the points do
/// not make whole segments.
fn prism_segments(spline: Spline, points: &[DVec2]) -> Option<Vec<[DVec2; 4]>> {
    let mut segments = Vec::new();
    match spline {
        Spline::Linear => {
            let mut start = 0;
            while start < points.len() {
                let first = points[start];
                let mut end = start + 1;
                while end < points.len() && points[end] != first {
                    end += 1;
                }
                let outline = &points[start..end.min(points.len())];
                for (index, &from) in outline.iter().enumerate() {
                    let to = outline[(index + 1) % outline.len()];
                    if to != from {
                        segments.push(line_segment(from, to));
                    }
                }
                start = end + 1;
            }
        }
        Spline::Quadratic | Spline::Cubic => {
            // control, start, .., start [, end control]
            let extra = usize::from(spline == Spline::Cubic);
            let mut start = 0;
            while start + 2 < points.len() {
                let first = points[start + 1];
                let mut end = start + 2;
                while end < points.len() && points[end] != first {
                    end += 1;
                }
                if end >= points.len() || end + extra >= points.len() {
                    return None;
                }
                for i in start + 1..end {
                    let (before, from, to) = (points[i - 1], points[i], points[i + 1]);
                    segments.push(if spline == Spline::Quadratic {
                        quadratic_segment(before, from, to)
                    } else {
                        cubic_segment(before, from, to, points[i + 2])
                    });
                }
                start = end + 1 + extra;
            }
        }
        Spline::Bezier => {
            if !points.len().is_multiple_of(4) {
                return None;
            }
            for chunk in points.chunks_exact(4) {
                segments.push([chunk[0], chunk[1], chunk[2], chunk[3]]);
            }
        }
    }
    Some(segments)
}

/// Bézier segments of a lathe's open curve for `spline`; `None` when the points do not make
/// a whole segment.
fn lathe_segments(spline: Spline, points: &[DVec2]) -> Option<Vec<[DVec2; 4]>> {
    let mut segments = Vec::new();
    match spline {
        Spline::Linear => {
            for pair in points.windows(2) {
                segments.push(line_segment(pair[0], pair[1]));
            }
        }
        Spline::Quadratic => {
            for window in points.windows(3) {
                let (before, from, to) = (window[0], window[1], window[2]);
                segments.push(quadratic_segment(before, from, to));
            }
        }
        Spline::Cubic => {
            for window in points.windows(4) {
                segments.push(cubic_segment(window[0], window[1], window[2], window[3]));
            }
        }
        Spline::Bezier => {
            if !points.len().is_multiple_of(4) {
                return None;
            }
            for chunk in points.chunks_exact(4) {
                segments.push([chunk[0], chunk[1], chunk[2], chunk[3]]);
            }
        }
    }
    (!segments.is_empty()).then_some(segments)
}

/// The parabola through `before`, `from` and `to` at t = -1, 0, 1, between `from` and `to`.
fn quadratic_segment(before: DVec2, from: DVec2, to: DVec2) -> [DVec2; 4] {
    power_to_bezier(
        DVec2::ZERO,
        0.5 * (to - 2.0 * from + before),
        0.5 * (to - before),
        from,
    )
}

/// The Catmull-Rom segment from `from` to `to`.
fn cubic_segment(before: DVec2, from: DVec2, to: DVec2, after: DVec2) -> [DVec2; 4] {
    power_to_bezier(
        0.5 * (-before + 3.0 * from - 3.0 * to + after),
        0.5 * (2.0 * before - 5.0 * from + 4.0 * to - after),
        0.5 * (to - before),
        from,
    )
}

impl Evaluator {
    /// `lathe { [spline] n, points.. }`.
    pub(crate) fn eval_lathe(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let (spline, _) = self.spline_keywords(stream)?;
        let count = self.expect_float(stream, "the number of points")?;
        if !(0.0..=1e7).contains(&count) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("a lathe needs 0 to 10000000 points, found {count}"),
                )
                .into());
        }
        let mut points = Vec::with_capacity((count as usize).min(1 << 20));
        for _ in 0..count as usize {
            points.push(self.expect_vector(stream, "a point")?.truncate());
        }
        let Some(segments) = lathe_segments(spline, &points) else {
            return Err(self
                .runtime
                .error(span, "too few points for the lathe's spline")
                .with_label("check the spline type and the number of points")
                .into());
        };
        let spline = match spline {
            Spline::Linear => OutlineSpline::Linear,
            Spline::Quadratic => OutlineSpline::Quadratic,
            Spline::Cubic => OutlineSpline::Cubic,
            Spline::Bezier => OutlineSpline::Bezier,
        };
        Ok(Shape::Lathe {
            segments: Arc::new(segments),
            source: Some(Arc::new(SplineOutline { spline, points })),
        })
    }

    /// Reads spline and sweep keywords; returns the spline and whether the sweep is conic.
    fn spline_keywords(&mut self, stream: &mut Stream) -> EvalResult<(Spline, bool)> {
        let mut spline = Spline::Linear;
        let mut conic = false;
        loop {
            match self.next_item(stream)? {
                Some(Item::Keyword(word, word_span)) => match &*word {
                    "linear_spline" => spline = Spline::Linear,
                    "quadratic_spline" => spline = Spline::Quadratic,
                    "cubic_spline" => spline = Spline::Cubic,
                    "bezier_spline" => spline = Spline::Bezier,
                    "linear_sweep" => conic = false,
                    "conic_sweep" => conic = true,
                    _ => {
                        stream.push_back(Item::Keyword(word, word_span));
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
        Ok((spline, conic))
    }

    /// Reads a prism's spline and sweep keywords, heights and points.
    pub(crate) fn eval_prism(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let (spline, conic) = self.spline_keywords(stream)?;
        let first_height = self.expect_float(stream, "the first height")?;
        let second_height = self.expect_float(stream, "the second height")?;
        let count = self.expect_float(stream, "the number of points")?;
        if !(0.0..=1e7).contains(&count) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("a prism needs 0 to 10000000 points, found {count}"),
                )
                .into());
        }
        let mut points = Vec::with_capacity((count as usize).min(1 << 20));
        for _ in 0..count as usize {
            points.push(self.expect_vector(stream, "a point")?.truncate());
        }
        let Some(segments) = prism_segments(spline, &points) else {
            return Err(self
                .runtime
                .error(span, "the prism's points do not close its sub-prisms")
                .with_label("check the spline type and the number of points")
                .into());
        };
        Ok(Shape::Prism(Arc::new(Extrusion {
            segments,
            depth: (first_height, second_height),
            open: false,
            conic,
        })))
    }
}
