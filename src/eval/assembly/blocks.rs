//! The dispatch of every block keyword to its reader: `sphere { .. }`, `texture { .. }`,
//! `camera { .. }`... become values here.
//!
//! In: a block (keyword and body). Out: its [`Value`]. Holds: this is the one hook through
//! which the language runtime turns a block into a value ([`Evaluator::eval_block`]); an
//! unknown keyword gets a did-you-mean over every block keyword durer reads.

use super::texture_maps::APPEARANCE_BLOCKS;
use crate::diag::did_you_mean;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::AtmosphericEffect;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Block, BlockHead};
use std::rc::Rc;

/// Block keywords durer evaluates.
pub(crate) const BLOCK_KEYWORDS: &[&str] = &[
    "media",
    "density",
    "density_map",
    "background",
    "box",
    "camera",
    "color_map",
    "colour_map",
    "cone",
    "cylinder",
    "difference",
    "disc",
    "fog",
    "finish",
    "global_settings",
    "interior",
    "intersection",
    "light_group",
    "light_source",
    "material",
    "merge",
    "object",
    "pigment",
    "plane",
    "quadric",
    "rainbow",
    "sky_sphere",
    "sphere",
    "texture",
    "torus",
    "transform",
    "triangle",
    "union",
    "smooth_triangle",
    "polygon",
    "mesh",
    "mesh2",
    "poly",
    "cubic",
    "quartic",
    "text",
    "prism",
    "lathe",
    "blob",
    "superellipsoid",
    "sor",
    "isosurface",
    "julia_fractal",
    "height_field",
    "sphere_sweep",
    "bicubic_patch",
    "ovus",
    "lemon",
    "parametric",
];

/// Block keywords of POV-Ray that durer does not evaluate yet.
const UNSUPPORTED_BLOCKS: &[&str] = &[
    "bounded_by",
    "clipped_by",
    "photons",
    "radiosity",
    "looks_like",
    "projected_through",
    "warp",
    "material_map",
    "uv_vectors",
    "irid",
    "subsurface",
    "media_attenuation",
    "photons",
];

impl Evaluator {
    /// Evaluates a block to its value.
    pub(crate) fn eval_block(&mut self, block: &Block) -> EvalResult<Value> {
        let head: crate::syntax::symbol::Symbol = match &block.head {
            BlockHead::Word(word) => *word,
            BlockHead::Conditional(branches) => {
                let mut chosen = None;
                for (condition, word) in branches {
                    let holds = match condition {
                        Some(c) => self.eval_condition(c)?,
                        None => true,
                    };
                    if holds {
                        chosen = Some(*word);
                        break;
                    }
                }
                match chosen {
                    Some(word) => word,
                    None => {
                        return Err(self
                            .runtime
                            .error(block.head_span, "no branch of this `#if` chose a block")
                            .into())
                    }
                }
            }
        };
        self.runtime.enter_nesting(block.span)?;
        let result = self.eval_block_as(&head, block);
        self.runtime.leave_nesting();
        result
    }

    fn eval_block_as(&mut self, head: &str, block: &Block) -> EvalResult<Value> {
        let mut stream = Stream::new(block.body.clone());
        let stream = &mut stream;
        match head {
            "sphere" | "box" | "plane" | "cylinder" | "cone" | "torus" | "disc" | "quadric"
            | "triangle" | "smooth_triangle" | "polygon" | "mesh" | "mesh2" | "poly" | "cubic"
            | "quartic" | "text" | "prism" | "lathe" | "blob" | "superellipsoid" | "sor"
            | "isosurface" | "height_field" | "sphere_sweep" | "bicubic_patch" | "ovus"
            | "lemon" | "parametric" | "object" | "julia_fractal" | "union" | "intersection"
            | "difference" | "merge" | "light_group" => {
                Ok(match self.eval_object(head, block, stream)? {
                    Some(object) => Value::Object(std::sync::Arc::new(object)),
                    None => Value::Nothing,
                })
            }
            "camera" => Ok(Value::Camera(Rc::new(self.eval_camera(stream)?))),
            "spline" => self.eval_spline(block.span, stream),
            // `light_source { Union_Ident .. }` is that object, as povray renders it.
            "light_source" if self.starts_with_declared_object(stream)? => {
                Ok(match self.eval_object("object", block, stream)? {
                    Some(object) => Value::Object(std::sync::Arc::new(object)),
                    None => Value::Nothing,
                })
            }
            "light_source" => Ok(Value::Light(Rc::new(self.eval_light(stream)?))),
            "fog" => Ok(atmospheric(AtmosphericEffect::Fog(self.eval_fog(stream)?))),
            "sky_sphere" => Ok(atmospheric(AtmosphericEffect::SkySphere(
                self.eval_sky_sphere(stream)?,
            ))),
            "rainbow" => Ok(atmospheric(AtmosphericEffect::Rainbow(
                self.eval_rainbow(stream)?,
            ))),
            "background" => {
                let (value, span) = self.expect_value(stream, "a colour")?;
                let colour = self.to_colour(value, span)?;
                self.expect_end(stream, "background")?;
                Ok(Value::Colour(colour))
            }
            "default" => {
                // POV-Ray 1.0 syntax for `#default`.
                self.run_default(block.body.clone())?;
                Ok(Value::Nothing)
            }
            "global_settings" => {
                self.eval_global_settings(stream)?;
                Ok(Value::Nothing)
            }
            "texture" => Ok(Value::Texture(std::sync::Arc::new(
                self.eval_texture(stream)?,
            ))),
            "pigment" => Ok(Value::Pigment(Rc::new(self.eval_pigment(stream)?))),
            "finish" => Ok(Value::Finish(Rc::new(self.eval_finish(stream, None)?))),
            "interior" => Ok(Value::Interior(Rc::new(self.eval_interior(stream)?))),
            "media" => Ok(Value::Media(Rc::new(self.eval_media(stream)?))),
            "density" => Ok(Value::Density(Rc::new(self.eval_density(stream)?))),
            "density_map" => Ok(Value::Map(Rc::new(
                crate::eval::language::value::AppearanceMap::Densities(
                    self.eval_density_map(stream)?,
                ),
            ))),
            "color_map" | "colour_map" => {
                Ok(Value::ColourMap(Rc::new(self.eval_colour_map(stream)?)))
            }
            "transform" => Ok(Value::Transform(Rc::new(
                self.eval_transform_block(stream)?,
            ))),
            "material" => Ok(Value::Material(Rc::new(self.eval_material(stream)?))),
            _ if APPEARANCE_BLOCKS.contains(&head) => {
                self.eval_appearance_block(head, block, stream)
            }
            "interior_texture" => Err(self
                .runtime
                .error(
                    block.head_span,
                    "`interior_texture` belongs in an object or a `material`",
                )
                .with_label("not a value of its own")
                .into()),
            _ if UNSUPPORTED_BLOCKS.contains(&head) => {
                // Leave the feature out of the picture but say so, so the rest still renders.
                self.runtime.warn(
                    block.head_span,
                    format!("`{head}` is not supported yet; it is left out"),
                );
                Ok(Value::Nothing)
            }
            _ => {
                let mut d = self
                    .runtime
                    .error(block.head_span, format!("unknown block keyword `{head}`"))
                    .with_label("not a POV-Ray block");
                let candidates = BLOCK_KEYWORDS
                    .iter()
                    .chain(UNSUPPORTED_BLOCKS)
                    .chain(APPEARANCE_BLOCKS)
                    .copied();
                if let Some(s) = did_you_mean(head, candidates) {
                    d = d.with_help(format!("did you mean `{s}`?"));
                }
                Err(d.into())
            }
        }
    }
}

/// An atmospheric effect as a value.
fn atmospheric(effect: AtmosphericEffect) -> Value {
    Value::Atmospheric(Rc::new(effect))
}
