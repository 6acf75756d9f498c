//! The `radiosity { .. }` block of `global_settings`.
//!
//! In: the block's items. Out: [`RadiositySettings`] stored in the global settings.
//! Also an object's `radiosity { importance }` block (checked, no effect).
//! Holds: out-of-range values are reported with their span (POV-Ray's limits: `count` at
//! least 1, `recursion_limit` 1..=20, `nearest_count` 1..=20, reuse radii ordered).

use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::RadiositySettings;
use crate::syntax::ast::Item;

/// Settings POV-Ray accepts in a radiosity block that durer reads and ignores.
const IGNORED: &[&str] = &["subsurface"];

impl Evaluator {
    /// Reads the body of `radiosity { .. }` into the radiosity settings.
    pub(crate) fn eval_radiosity(&mut self, stream: &mut Stream) -> EvalResult<()> {
        let mut radiosity = RadiositySettings::default();
        let mut pool_given = false;
        while let Some(item) = self.next_item(stream)? {
            let Item::Keyword(word, span) = &item else {
                if matches!(item, Item::Comma(_)) {
                    continue;
                }
                return Err(self.unexpected_in(&item, "radiosity"));
            };
            match &**word {
                "count" => {
                    radiosity.count = self.positive_count(stream, "the ray count", 1600 * 16)?;
                    if let Some(Item::Comma(_)) = self.peek_item(stream)? {
                        self.skip_comma(stream)?;
                        radiosity.direction_pool =
                            self.positive_count(stream, "the direction pool size", 1600 * 16)?;
                        pool_given = true;
                    }
                }
                "nearest_count" => {
                    radiosity.nearest_count = self.positive_count(stream, "a count", 20)?;
                    if let Some(Item::Comma(_)) = self.peek_item(stream)? {
                        // The adaptive pretrace target: accepted, the pretrace is not adaptive.
                        self.skip_comma(stream)?;
                        let _ = self.expect_float(stream, "a count")?;
                    }
                }
                "recursion_limit" => {
                    radiosity.recursion_limit = self.positive_count(stream, "a depth", 20)?
                }
                "error_bound" => radiosity.error_bound = self.positive(stream)?,
                "brightness" => radiosity.brightness = self.expect_float(stream, "a float")?,
                "gray_threshold" => {
                    radiosity.gray_threshold = self.expect_float(stream, "a float")?.clamp(0.0, 1.0)
                }
                "low_error_factor" => radiosity.low_error_factor = self.positive(stream)?,
                "minimum_reuse" => radiosity.minimum_reuse = self.positive(stream)?,
                "maximum_reuse" => radiosity.maximum_reuse = self.positive(stream)?,
                "pretrace_start" => radiosity.pretrace_start = self.block_fraction(stream)?,
                "pretrace_end" => radiosity.pretrace_end = self.block_fraction(stream)?,
                "adc_bailout" => radiosity.adc_bailout = self.expect_float(stream, "a float")?,
                "max_sample" => radiosity.max_sample = self.expect_float(stream, "a float")?,
                "always_sample" => radiosity.always_sample = self.optional_bool(stream)?,
                // povray reuses a saved sample cache to skip its pretrace; durer neither
                // reads nor writes the file and computes the samples afresh.
                "save_file" | "load_file" => {
                    let _ = self.expect_value(stream, "a file name")?;
                    self.runtime.warn(
                        *span,
                        format!(
                            "radiosity sample files are not read or written; `{word}` is \
                             ignored and the samples are computed for this render"
                        ),
                    );
                }
                "normal" => radiosity.use_normal = self.optional_bool(stream)?,
                "media" => radiosity.use_media = self.optional_bool(stream)?,
                other if IGNORED.contains(&other) => {
                    self.runtime.warn(
                        *span,
                        format!("radiosity `{other}` is not supported; ignored"),
                    );
                    let _ = self.optional_bool(stream)?;
                }
                _ => return Err(self.unexpected_in(&item, "radiosity")),
            }
        }
        if !pool_given {
            radiosity.direction_pool = radiosity.count;
        }
        radiosity.direction_pool = radiosity.direction_pool.max(radiosity.count);
        if radiosity.minimum_reuse >= radiosity.maximum_reuse {
            // POV-Ray refuses this; durer keeps rendering with the reuse radii swapped.
            std::mem::swap(&mut radiosity.minimum_reuse, &mut radiosity.maximum_reuse);
        }
        if radiosity.pretrace_end > radiosity.pretrace_start {
            radiosity.pretrace_end = radiosity.pretrace_start;
        }
        self.scene.settings.radiosity = Some(radiosity);
        Ok(())
    }

    /// Reads an object's `radiosity { importance F }` block. The importance (a fraction of
    /// `count` for samples gathered on the object) is checked and has no effect: every
    /// sample gathers `count` rays.
    pub(crate) fn eval_object_radiosity(&mut self, stream: &mut Stream) -> EvalResult<()> {
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) if &**word == "importance" => {
                    let (value, span) = self.expect_value(stream, "the importance")?;
                    let importance = self.to_float(value, span)?;
                    if !(importance > 0.0 && importance <= 1.0) {
                        return Err(self
                            .runtime
                            .error(
                                span,
                                format!("radiosity importance {importance} is out of range"),
                            )
                            .with_label("expected a fraction above 0 and at most 1")
                            .into());
                    }
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "radiosity")),
            }
        }
        Ok(())
    }

    /// A whole number from 1 to `limit`.
    fn positive_count(&mut self, stream: &mut Stream, what: &str, limit: u32) -> EvalResult<u32> {
        let (value, span) = self.expect_value(stream, what)?;
        let number = self.to_float(value, span)?;
        if !(number >= 1.0 && number <= f64::from(limit)) {
            return Err(self
                .runtime
                .error(span, format!("radiosity value {number} is out of range"))
                .with_label(format!("expected a whole number from 1 to {limit}"))
                .into());
        }
        Ok(number as u32)
    }

    /// A float greater than zero.
    fn positive(&mut self, stream: &mut Stream) -> EvalResult<f64> {
        let (value, span) = self.expect_value(stream, "a positive float")?;
        let number = self.to_float(value, span)?;
        if !(number > 0.0 && number.is_finite()) {
            return Err(self
                .runtime
                .error(span, format!("radiosity value {number} must be positive"))
                .with_label("expected a float greater than 0")
                .into());
        }
        Ok(number)
    }

    /// A pretrace block size: a fraction of the image from 0 (exclusive) to 1.
    fn block_fraction(&mut self, stream: &mut Stream) -> EvalResult<f64> {
        let (value, span) = self.expect_value(stream, "a fraction")?;
        let number = self.to_float(value, span)?;
        if !(number > 0.0 && number <= 1.0) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("pretrace block size {number} is out of range"),
                )
                .with_label("expected a fraction of the image, above 0 and at most 1")
                .into());
        }
        Ok(number)
    }
}
