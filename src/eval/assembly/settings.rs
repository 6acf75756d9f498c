//! `global_settings { }`: gamma, trace depth and bailout, ambient light, noise generator,
//! irid wavelengths, number of waves, radiosity and photons.
//!
//! In: the block's items. Out: the evaluator's [`crate::scene::GlobalSettings`] updated in
//! place (the last setting wins, wherever it stands).

use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{BlockHead, Item};

impl Evaluator {
    pub(crate) fn eval_global_settings(&mut self, stream: &mut Stream) -> EvalResult<()> {
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "assumed_gamma" => {
                        self.scene.settings.assumed_gamma =
                            Some(self.expect_float(stream, "a float")?)
                    }
                    "max_trace_level" => {
                        let level = self.expect_float(stream, "a float")?;
                        self.scene.settings.max_trace_level = level.clamp(1.0, 256.0) as u32;
                    }
                    "adc_bailout" => {
                        self.scene.settings.adc_bailout = self.expect_float(stream, "a float")?
                    }
                    "ambient_light" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        self.scene.settings.ambient_light = self.to_colour(value, span)?.rgb_vec();
                    }
                    "noise_generator" => {
                        let generator = self.expect_noise_generator(stream)?.unwrap_or_default();
                        self.scene.settings.noise_generator = generator;
                        self.scene.settings.scene_noise_generator.set(generator);
                    }
                    "number_of_waves" => self.number_of_waves(stream)?,
                    "irid_wavelength" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        self.scene.settings.irid_wavelength =
                            self.to_colour(value, span)?.rgb_vec();
                    }
                    "mm_per_unit" => {
                        self.scene.settings.mm_per_unit = self.expect_float(stream, "a float")?
                    }
                    "charset" | "max_intersections" | "hf_gray_16" | "subsurface" => {
                        self.runtime.warn(
                            *span,
                            format!("global setting `{word}` is not supported yet; it is ignored"),
                        );
                        let _ = self.next_item(stream)?;
                    }
                    _ => return Err(self.unexpected_in(&item, "global_settings")),
                },
                Item::Block(block) => {
                    let name = match &block.head {
                        BlockHead::Word(w) => w.to_string(),
                        _ => String::new(),
                    };
                    if name == "radiosity" {
                        let mut body = Stream::new(block.body.clone());
                        self.eval_radiosity(&mut body)?;
                    } else if name == "photons" {
                        let mut body = Stream::new(block.body.clone());
                        self.eval_global_photons(&mut body, block.head_span)?;
                    } else if name == "subsurface" {
                        let mut body = Stream::new(block.body.clone());
                        self.eval_global_subsurface(&mut body)?;
                    } else {
                        return Err(self.unexpected_in(&item, "global_settings"));
                    }
                }
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "global_settings")),
            }
        }
        Ok(())
    }

    /// `subsurface { samples D, S radiosity B }`: both sample counts are required (POV-Ray
    /// rejects `samples D` alone); counts are clamped to 1..=100000 (0 turns a part off).
    fn eval_global_subsurface(&mut self, stream: &mut Stream) -> EvalResult<()> {
        let mut subsurface = self.scene.settings.subsurface.unwrap_or_default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) => match &**word {
                    "samples" => {
                        subsurface.diffuse_samples =
                            sample_count(self.expect_float(stream, "a count")?);
                        self.skip_comma(stream)?;
                        subsurface.single_samples =
                            sample_count(self.expect_float(stream, "a count")?);
                    }
                    "radiosity" => subsurface.radiosity = self.optional_bool(stream)?,
                    _ => return Err(self.unexpected_in(&item, "subsurface")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "subsurface")),
            }
        }
        self.scene.settings.subsurface = Some(subsurface);
        Ok(())
    }
}

/// A sample count as the renderer uses it: non-finite or negative values give none.
fn sample_count(value: f64) -> u32 {
    if value.is_finite() {
        value.clamp(0.0, 100_000.0) as u32
    } else {
        0
    }
}
