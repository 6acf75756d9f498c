//! The `photons { .. }` blocks: in `global_settings`, in objects and in light sources.
//!
//! In: the block's items. Out: [`PhotonSettings`] in the global settings, [`ObjectPhotons`]
//! on an object, [`LightPhotons`] on a light. Holds: out-of-range values are reported with
//! their span; `save_file` and `load_file` are refused with a warning (photons are shot
//! afresh for every render); a `media` spacing factor must be positive.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{LightPhotons, ObjectPhotons, PhotonDensity, PhotonSettings};
use crate::syntax::ast::Item;

/// The most photons `count` may ask for.
const COUNT_LIMIT: f64 = 50_000_000.0;

/// The most photons one gather may use.
const GATHER_LIMIT: f64 = 1_000_000.0;

impl Evaluator {
    /// Reads the body of the global `photons { .. }` block into the photon settings.
    pub(crate) fn eval_global_photons(
        &mut self,
        stream: &mut Stream,
        head: Span,
    ) -> EvalResult<()> {
        let mut photons = PhotonSettings::default();
        let mut density_given = false;
        while let Some(item) = self.next_item(stream)? {
            let Item::Keyword(word, span) = &item else {
                if matches!(item, Item::Comma(_)) {
                    continue;
                }
                return Err(self.unexpected_in(&item, "photons"));
            };
            match &**word {
                "spacing" => {
                    let spacing = self.photon_positive(stream, "the photon spacing")?;
                    photons.density = PhotonDensity::Spacing(spacing);
                    density_given = true;
                }
                "count" => {
                    let count = self.photon_whole(stream, "the photon count", COUNT_LIMIT)?;
                    photons.density = PhotonDensity::Count(count);
                    density_given = true;
                }
                "gather" => {
                    photons.gather_min = self.photon_whole(stream, "a count", GATHER_LIMIT)?;
                    self.skip_comma(stream)?;
                    photons.gather_max = self.photon_whole(stream, "a count", GATHER_LIMIT)?;
                    photons.gather_max = photons.gather_max.max(photons.gather_min);
                }
                "media" => {
                    let steps = self.photon_whole_or_zero(stream, "a number of steps")?;
                    photons.media_steps = steps;
                    if let Some((factor, factor_span)) = self.optional_second_value(stream)? {
                        if !(factor > 0.0 && factor.is_finite()) {
                            return Err(self
                                .runtime
                                .error(
                                    factor_span,
                                    format!("media photon spacing factor {factor} is not positive"),
                                )
                                .with_label("expected a number above 0")
                                .into());
                        }
                        photons.media_factor = factor;
                    }
                }
                "jitter" => {
                    let (value, value_span) = self.expect_value(stream, "a float")?;
                    let jitter = self.to_float(value, value_span)?;
                    if !(0.0..=1.0).contains(&jitter) {
                        return Err(self
                            .runtime
                            .error(
                                value_span,
                                format!("photon jitter {jitter} is out of range"),
                            )
                            .with_label("expected a fraction from 0 to 1")
                            .into());
                    }
                    photons.jitter = jitter;
                }
                "max_trace_level" => {
                    let level = self.expect_float(stream, "a float")?;
                    photons.max_trace_level = Some(level.clamp(1.0, 256.0) as u32);
                }
                "adc_bailout" => {
                    photons.adc_bailout = Some(self.expect_float(stream, "a float")?.max(0.0))
                }
                "autostop" => {
                    // povray takes any value silently: 2 shoots as 1 does, -1 as 0 (measured
                    // by the photon counts it prints).
                    let fraction = self.expect_float(stream, "a fraction")?;
                    photons.autostop = if fraction.is_nan() {
                        0.0
                    } else {
                        fraction.clamp(0.0, 1.0)
                    };
                }
                "expand_thresholds" => {
                    photons.expand_increase = self.expect_float(stream, "a float")?.max(0.0);
                    self.skip_comma(stream)?;
                    photons.expand_min = self.photon_whole(stream, "a count", GATHER_LIMIT)?;
                }
                "radius" => self.photon_radius(stream, &mut photons)?,
                "save_file" | "load_file" => {
                    let _ = self.expect_value(stream, "a file name")?;
                    self.runtime.warn(
                        *span,
                        format!(
                            "photon map files are not supported; `{word}` is ignored and \
                             photons are shot for this render"
                        ),
                    );
                }
                _ => return Err(self.unexpected_in(&item, "photons")),
            }
        }
        if !density_given {
            return Err(self
                .runtime
                .error(
                    head,
                    "the global `photons` block needs `spacing` or `count`",
                )
                .with_label("no photon density given")
                .into());
        }
        self.scene.settings.photons = Some(photons);
        Ok(())
    }

    /// `radius [GATHER] [, MULTIPLIER [, MEDIA [, MEDIA_MULTIPLIER]]]`: every value may be
    /// left out, the commas keep the places.
    fn photon_radius(
        &mut self,
        stream: &mut Stream,
        photons: &mut PhotonSettings,
    ) -> EvalResult<()> {
        let mut slot = 0;
        let mut after_value = false;
        while slot < 4 {
            match self.next_item(stream)? {
                Some(Item::Comma(_)) => {
                    slot += 1;
                    after_value = false;
                }
                Some(Item::Expr(expr)) if !after_value => {
                    let value = self.eval_expr(&expr)?;
                    let Value::Float(number) = value else {
                        stream.push_back(Item::Expr(expr));
                        break;
                    };
                    if !(number >= 0.0 && number.is_finite()) {
                        return Err(self
                            .runtime
                            .error(
                                expr.span(),
                                format!("photon radius value {number} is negative"),
                            )
                            .with_label("expected 0 or more")
                            .into());
                    }
                    match slot {
                        0 => photons.radius = number,
                        1 if number > 0.0 => photons.radius_multiplier = number,
                        2 => photons.media_radius = number,
                        3 if number > 0.0 => photons.media_radius_multiplier = number,
                        _ => {}
                    }
                    after_value = true;
                }
                Some(other) => {
                    stream.push_back(other);
                    break;
                }
                None => break,
            }
        }
        Ok(())
    }

    /// Reads the body of an object's `photons { .. }` block into `photons`.
    pub(crate) fn eval_object_photons(
        &mut self,
        stream: &mut Stream,
        photons: &mut ObjectPhotons,
    ) -> EvalResult<()> {
        while let Some(item) = self.next_item(stream)? {
            let Item::Keyword(word, span) = &item else {
                if matches!(item, Item::Comma(_)) {
                    continue;
                }
                return Err(self.unexpected_in(&item, "photons"));
            };
            match &**word {
                "target" => {
                    let multiplier = match self.optional_second_value(stream)? {
                        Some((value, span)) if !(value > 0.0 && value.is_finite()) => {
                            return Err(self
                                .runtime
                                .error(
                                    span,
                                    format!("photon spacing multiplier {value} must be positive"),
                                )
                                .with_label("expected a float greater than 0")
                                .into())
                        }
                        Some((value, _)) => value,
                        None => 1.0,
                    };
                    photons.set_target(Some(multiplier));
                }
                "refraction" => {
                    let on = self.optional_bool(stream)?;
                    photons.set_refraction(on);
                }
                "reflection" => {
                    let on = self.optional_bool(stream)?;
                    photons.set_reflection(on);
                }
                "collect" => {
                    let on = self.optional_bool(stream)?;
                    photons.set_collect(on);
                }
                "pass_through" => {
                    let on = self.optional_bool(stream)?;
                    photons.set_pass_through(on);
                }
                // Unions are always split into their parts.
                "split_union" => {
                    if !self.optional_bool(stream)? {
                        self.runtime.warn(
                            *span,
                            "`split_union off` is not supported yet; unions are split into \
                             their parts",
                        );
                    }
                }
                _ => return Err(self.unexpected_in(&item, "photons")),
            }
        }
        Ok(())
    }

    /// Reads the body of a light's `photons { .. }` block into `photons`.
    pub(crate) fn eval_light_photons(
        &mut self,
        stream: &mut Stream,
        photons: &mut LightPhotons,
    ) -> EvalResult<()> {
        while let Some(item) = self.next_item(stream)? {
            let Item::Keyword(word, span) = &item else {
                if matches!(item, Item::Comma(_)) {
                    continue;
                }
                return Err(self.unexpected_in(&item, "photons"));
            };
            match &**word {
                "refraction" => {
                    photons.refraction = self.optional_bool(stream)?;
                    photons.refraction_given = true;
                }
                "reflection" => {
                    photons.reflection = self.optional_bool(stream)?;
                    photons.reflection_given = true;
                }
                "area_light" => {
                    if self.optional_bool(stream)? {
                        self.runtime.warn(
                            *span,
                            "area light photons are not supported yet; photons leave from \
                             the light's centre",
                        );
                    }
                }
                _ => return Err(self.unexpected_in(&item, "photons")),
            }
        }
        Ok(())
    }

    /// A float greater than zero.
    fn photon_positive(&mut self, stream: &mut Stream, what: &str) -> EvalResult<f64> {
        let (value, span) = self.expect_value(stream, what)?;
        let number = self.to_float(value, span)?;
        if !(number > 0.0 && number.is_finite()) {
            return Err(self
                .runtime
                .error(span, format!("{what} {number} must be positive"))
                .with_label("expected a float greater than 0")
                .into());
        }
        Ok(number)
    }

    /// A whole number from 1 to `limit`.
    fn photon_whole(&mut self, stream: &mut Stream, what: &str, limit: f64) -> EvalResult<u32> {
        let (value, span) = self.expect_value(stream, what)?;
        let number = self.to_float(value, span)?;
        if !(1.0..=limit).contains(&number) {
            return Err(self
                .runtime
                .error(span, format!("photon value {number} is out of range"))
                .with_label(format!("expected {what} from 1 to {limit}"))
                .into());
        }
        Ok(number as u32)
    }

    /// A whole number from 0 up.
    fn photon_whole_or_zero(&mut self, stream: &mut Stream, what: &str) -> EvalResult<u32> {
        let (value, span) = self.expect_value(stream, what)?;
        let number = self.to_float(value, span)?;
        if !(0.0..=COUNT_LIMIT).contains(&number) {
            return Err(self
                .runtime
                .error(span, format!("photon value {number} is out of range"))
                .with_label(format!("expected {what} from 0 to {COUNT_LIMIT}"))
                .into());
        }
        Ok(number as u32)
    }
}
