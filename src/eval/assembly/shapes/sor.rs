//! `sor { n, <radius, height>.. [open] [sturm] }`: the surface of revolution's points.
//!
//! In: the item stream after the brace. Out: [`Shape::Sor`]. Holds: POV-Ray's checks, each a
//! spanned error (measured: POV-Ray stops with "Incorrect point in surface of revolution"):
//! at least four points, no negative radius (the first and last points included), and
//! heights that strictly increase from the second point to the last but one, and no point at
//! the height of the point two places on (within 1e-10, measured: a first point level with
//! the third or a last point level with the last but two is refused; the first and last
//! points only set slopes, so otherwise their heights may lie anywhere). The stream is left
//! at the object modifiers (`open` and `sturm` among them).

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::Shape;
use std::sync::Arc;

/// Fewest points a sor takes: a segment and the two points that set its end slopes.
const FEWEST_POINTS: f64 = 4.0;
/// Most points a sor may declare (guards huge allocations).
const MOST_POINTS: f64 = 1e7;
/// Least height difference between a point and the point two places on (measured in
/// POV-Ray: 1e-10 passes, 1e-11 is refused); a slope is the ratio over that difference.
const LEAST_SLOPE_SPAN: f64 = 1e-10;

impl Evaluator {
    /// Reads a sor's point count and points and checks them as POV-Ray does.
    pub(crate) fn eval_sor(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let count = self.expect_float(stream, "the number of points")?;
        if !(FEWEST_POINTS..=MOST_POINTS).contains(&count) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("a sor needs 4 to 10000000 points, found {count}"),
                )
                .with_label("the first and last points only set the end slopes")
                .into());
        }
        let count = count as usize;
        let mut points = Vec::with_capacity(count.min(1 << 20));
        let mut spans = Vec::with_capacity(count.min(1 << 20));
        let mut previous_height = f64::NEG_INFINITY;
        for index in 0..count {
            let (value, point_span) = self.expect_value(stream, "a point <radius, height>")?;
            let point = self.to_vector3(value, point_span)?.truncate();
            if !point.is_finite() {
                return Err(self
                    .runtime
                    .error(
                        point_span,
                        format!("a sor's point must be finite, found {point}"),
                    )
                    .into());
            }
            if point.x < 0.0 {
                return Err(self
                    .runtime
                    .error(
                        point_span,
                        format!("a sor's radius must not be negative, found {}", point.x),
                    )
                    .with_label("the first number of a point is its radius")
                    .into());
            }
            let inner = index > 0 && index + 1 < count;
            if inner {
                if point.y <= previous_height {
                    return Err(self
                        .runtime
                        .error(
                            point_span,
                            format!(
                                "a sor's heights must increase: {} follows {previous_height}",
                                point.y
                            ),
                        )
                        .with_label(
                            "from the second point to the last but one, each point must be \
                             higher than the one before",
                        )
                        .into());
                }
                previous_height = point.y;
            }
            points.push(point);
            spans.push(point_span);
        }
        for (first, window) in points.windows(3).enumerate() {
            if (window[2].y - window[0].y).abs() < LEAST_SLOPE_SPAN {
                // Blame the slope-setting end point when it is involved.
                let blamed = if first == 0 { 0 } else { first + 2 };
                return Err(self
                    .runtime
                    .error(
                        spans[blamed],
                        format!(
                            "a sor's point may not lie at the height of the point two places \
                             from it ({})",
                            window[0].y
                        ),
                    )
                    .with_label("the slope here would divide by a zero height difference")
                    .into());
            }
        }
        Ok(Shape::Sor {
            points: Arc::new(points),
            open: false,
        })
    }
}
