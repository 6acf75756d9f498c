//! Camera items beyond the basic vectors: focal blur and the spherical camera's second
//! angle.
//!
//! In: camera block items. Out: a resolved [`FocalBlur`]. Holds: POV-Ray's defaults
//! (focal point at the origin, confidence 0.9, variance 1/128, minimum samples 4 below 7
//! samples, else 7); bad values are reported with their span.

use super::stream::Stream;
use super::value::Value;
use super::{EvalResult, Evaluator};
use crate::diag::Span;
use crate::scene::FocalBlur;
use crate::syntax::ast::Item;
use glam::DVec3;

/// POV-Ray's default `variance` of focal blur sampling.
const DEFAULT_VARIANCE: f64 = 1.0 / 128.0;

/// Focal-blur items as written in one camera block.
#[derive(Clone, Debug, Default)]
pub(crate) struct FocalBlurItems {
    aperture: Option<f64>,
    focal_point: Option<DVec3>,
    samples: Option<(Option<u32>, u32)>,
    confidence: Option<f64>,
    variance: Option<f64>,
}

impl FocalBlurItems {
    /// The focal blur these items ask for: `None` unless both a positive `aperture` and
    /// `blur_samples` were given.
    pub(crate) fn resolve(&self) -> Option<FocalBlur> {
        let aperture = self.aperture.filter(|a| *a > 0.0)?;
        let (min_samples, max_samples) = self.samples?;
        let max_samples = max_samples.max(1);
        let default_min = if max_samples < 7 { 4 } else { 7 };
        let variance = match self.variance {
            // POV-Ray warns about 1 and uses the default.
            Some(v) if v != 1.0 => v,
            _ => DEFAULT_VARIANCE,
        };
        Some(FocalBlur {
            aperture,
            focal_point: self.focal_point.unwrap_or(DVec3::ZERO),
            min_samples: min_samples.unwrap_or(default_min).min(max_samples),
            max_samples,
            confidence: self.confidence.unwrap_or(0.9),
            variance,
        })
    }
}

impl Evaluator {
    /// Reads the operand of a focal-blur keyword (`aperture`, `blur_samples`,
    /// `focal_point`, `confidence` or `variance`).
    pub(crate) fn eval_focal_blur_item(
        &mut self,
        word: &str,
        stream: &mut Stream,
        items: &mut FocalBlurItems,
    ) -> EvalResult<()> {
        match word {
            "aperture" => items.aperture = Some(self.expect_float(stream, "an aperture")?),
            "focal_point" => items.focal_point = Some(self.expect_vector(stream, "a point")?),
            "confidence" => {
                let (value, span) = self.expect_value(stream, "a probability")?;
                let confidence = self.to_float(value, span)?;
                if !(0.0..1.0).contains(&confidence) {
                    return Err(self
                        .error(
                            span,
                            format!("confidence {confidence} is not a probability"),
                        )
                        .with_label("expected a value from 0 up to (not including) 1")
                        .into());
                }
                items.confidence = Some(confidence);
            }
            "variance" => items.variance = Some(self.expect_float(stream, "a float")?),
            _ => {
                let first = self.sample_count(stream)?;
                items.samples = Some(match self.optional_second_value(stream)? {
                    Some((second, span)) => (Some(first), self.count_from(second, span)?),
                    None => (None, first),
                });
            }
        }
        Ok(())
    }

    /// A second number after a first one (`blur_samples 4, 16`, `angle 360, 180`), with or
    /// without the comma; `None` when the next item is not a number.
    pub(crate) fn optional_second_value(
        &mut self,
        stream: &mut Stream,
    ) -> EvalResult<Option<(f64, Span)>> {
        let mut item = self.next_item(stream)?;
        if let Some(Item::Comma(_)) = item {
            item = self.next_item(stream)?;
        }
        if let Some(Item::Expr(expr)) = &item {
            if let Value::Float(value) = self.eval_expr(expr)? {
                return Ok(Some((value, expr.span())));
            }
        }
        // A lone comma before something else means nothing, so it need not be kept.
        if let Some(item) = item {
            stream.push_back(item);
        }
        Ok(None)
    }

    /// A sample count: a positive whole number.
    fn sample_count(&mut self, stream: &mut Stream) -> EvalResult<u32> {
        let (value, span) = self.expect_value(stream, "a number of samples")?;
        let count = self.to_float(value, span)?;
        self.count_from(count, span)
    }

    /// `count` (written at `span`) as a sample count: a whole number of at least 1.
    fn count_from(&self, count: f64, span: Span) -> EvalResult<u32> {
        if (1.0..=f64::from(u32::MAX)).contains(&count) {
            Ok(count as u32)
        } else {
            Err(self
                .error(span, format!("{count} is not a number of samples"))
                .with_label("expected a whole number of at least 1")
                .into())
        }
    }
}
