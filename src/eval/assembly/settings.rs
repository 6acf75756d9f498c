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
                    "charset" | "max_intersections" | "hf_gray_16" | "mm_per_unit"
                    | "subsurface" => {
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
                        let message = format!("`{name}` is not supported yet; it is ignored");
                        self.runtime.warn(block.head_span, message);
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
}
