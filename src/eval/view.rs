//! Blocks that set up the view: camera, light sources, background and global settings;
//! and the dispatch of every block keyword to its evaluator.

use super::atmosphere::AtmosphericEffect;
use super::camera::FocalBlurItems;
use super::stream::Stream;
use super::texture_maps::APPEARANCE_BLOCKS;
use super::value::Value;
use super::{EvalResult, Evaluator};
use crate::diag::did_you_mean;
use crate::syntax::ast::{Block, BlockHead, Item};
use crate::{
    math::Transform,
    scene::{Camera, CylinderKind, Projection},
};
use glam::DVec3;
use std::rc::Rc;
use std::sync::Arc;

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
                            .error(block.head_span, "no branch of this `#if` chose a block")
                            .into())
                    }
                }
            }
        };
        self.enter_nesting(block.span)?;
        let result = self.eval_block_as(&head, block);
        self.nesting -= 1;
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
                super::texture_maps::AppearanceMap::Densities(self.eval_density_map(stream)?),
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
                .error(
                    block.head_span,
                    "`interior_texture` belongs in an object or a `material`",
                )
                .with_label("not a value of its own")
                .into()),
            _ if UNSUPPORTED_BLOCKS.contains(&head) => {
                // Leave the feature out of the picture but say so, so the rest still renders.
                self.warn(
                    block.head_span,
                    format!("`{head}` is not supported yet; it is left out"),
                );
                Ok(Value::Nothing)
            }
            _ => {
                let mut d = self
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

    /// Reads the next item as a value (skipping one leading comma).
    pub(crate) fn expect_value(
        &mut self,
        stream: &mut Stream,
        what: &str,
    ) -> EvalResult<(Value, crate::diag::Span)> {
        let mut item = self.next_item(stream)?;
        if let Some(Item::Comma(_)) = item {
            item = self.next_item(stream)?;
        }
        match item {
            Some(Item::Expr(expr)) => {
                // `"text" -1` is two values in POV-Ray: a sign after a non-number starts
                // the next value.
                let (value, rest) = self.eval_value_pair(&expr)?;
                if let Some(rest) = rest {
                    stream.push_back(Item::Expr(rest));
                }
                Ok((value, expr.span()))
            }
            Some(item @ Item::Block(_)) => {
                let span = item.span();
                Ok((self.item_value(&item)?, span))
            }
            Some(other) => Err(self
                .error(
                    other.span(),
                    format!("expected {what}, found {}", describe_item(&other)),
                )
                .with_label(format!("expected {what}"))
                .into()),
            None => Err(self
                .error(
                    self.stream_end_span(),
                    format!("expected {what}, found the end of the block"),
                )
                .into()),
        }
    }

    pub(crate) fn expect_float(&mut self, stream: &mut Stream, what: &str) -> EvalResult<f64> {
        let (value, span) = self.expect_value(stream, what)?;
        self.to_float(value, span)
    }

    pub(crate) fn expect_vector(&mut self, stream: &mut Stream, what: &str) -> EvalResult<DVec3> {
        let (value, span) = self.expect_value(stream, what)?;
        self.to_vector3(value, span)
    }

    /// Reads an optional float argument (e.g. `hollow` or `hollow off`).
    pub(crate) fn optional_bool(&mut self, stream: &mut Stream) -> EvalResult<bool> {
        match self.next_item(stream)? {
            Some(Item::Expr(expr)) => {
                let value = self.eval_expr(&expr)?;
                match value {
                    Value::Float(f) => Ok(f != 0.0),
                    other => {
                        stream.push_back(Item::Expr(expr));
                        let _ = other;
                        Ok(true)
                    }
                }
            }
            Some(other) => {
                stream.push_back(other);
                Ok(true)
            }
            None => Ok(true),
        }
    }

    pub(crate) fn stream_end_span(&self) -> crate::diag::Span {
        self.trace.last().map(|t| t.span).unwrap_or_default()
    }

    /// Errors if anything but commas is left in the block.
    pub(crate) fn expect_end(&mut self, stream: &mut Stream, block: &str) -> EvalResult<()> {
        while let Some(item) = self.next_item(stream)? {
            if !matches!(item, Item::Comma(_)) {
                return Err(self.unexpected_in(&item, block));
            }
        }
        Ok(())
    }

    /// "`x` is not allowed inside `block`" with a did-you-mean for misspelt keywords.
    pub(crate) fn unexpected_in(&self, item: &Item, block: &str) -> Box<crate::diag::Diagnostic> {
        let mut d = self
            .error(
                item.span(),
                format!("{} is not allowed inside `{block}`", describe_item(item)),
            )
            .with_label("unexpected here");
        if let Item::Expr(crate::syntax::ast::Expr::Ident(name, _)) = item {
            if self.lookup(*name).is_none() {
                d.message = format!("unknown keyword or identifier `{name}` inside `{block}`");
                if let Some(s) = did_you_mean(name, crate::syntax::keywords::ALL.iter().copied()) {
                    d = d.with_help(format!("did you mean `{s}`?"));
                }
            }
        }
        d.into()
    }

    fn eval_camera(&mut self, stream: &mut Stream) -> EvalResult<Camera> {
        let mut camera = Camera::default();
        let mut sky = DVec3::Y;
        let mut look_at: Option<DVec3> = None;
        let mut angle: Option<f64> = None;
        let mut image_plane_given = false;
        let mut transforms: Vec<Transform> = Vec::new();
        let mut vertical_angle: Option<f64> = None;
        let mut blur = FocalBlurItems::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => {
                    match &**word {
                        "perspective" => camera.projection = Projection::Perspective,
                        "orthographic" => camera.projection = Projection::Orthographic,
                        "location" => camera.location = self.expect_vector(stream, "a vector")?,
                        "direction" => camera.direction = self.expect_vector(stream, "a vector")?,
                        "right" => {
                            camera.right = self.expect_vector(stream, "a vector")?;
                            image_plane_given = true;
                        }
                        "up" => {
                            camera.up = self.expect_vector(stream, "a vector")?;
                            image_plane_given = true;
                        }
                        "sky" => sky = self.expect_vector(stream, "a vector")?,
                        "look_at" => look_at = Some(self.expect_vector(stream, "a vector")?),
                        "angle" => {
                            // `angle` may stand alone for orthographic cameras.
                            match self.peek_item(stream)? {
                                Some(Item::Expr(_)) => {
                                    angle = Some(self.expect_float(stream, "an angle")?);
                                    if camera.projection == Projection::Spherical {
                                        vertical_angle = self
                                            .optional_second_value(stream)?
                                            .map(|(value, _)| value);
                                    }
                                }
                                _ => angle = Some(f64::NAN),
                            }
                        }
                        "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                            transforms.push(self.transform_keyword(word, *span, stream)?)
                        }
                        "fisheye" => camera.projection = Projection::Fisheye,
                        "ultra_wide_angle" => camera.projection = Projection::UltraWideAngle,
                        "omnimax" => camera.projection = Projection::Omnimax,
                        "panoramic" => camera.projection = Projection::Panoramic,
                        "spherical" => camera.projection = Projection::Spherical,
                        "cylinder" => {
                            let (value, value_span) =
                                self.expect_value(stream, "the cylinder camera type")?;
                            let number = self.to_float(value, value_span)?;
                            let Some(kind) = CylinderKind::from_number(number) else {
                                return Err(self
                                    .error(
                                        value_span,
                                        format!("unknown cylinder camera type {number}"),
                                    )
                                    .with_label("expected 1, 2, 3 or 4")
                                    .into());
                            };
                            camera.projection = Projection::Cylinder(kind);
                        }
                        "focal_point" | "aperture" | "blur_samples" | "confidence" | "variance" => {
                            self.eval_focal_blur_item(word, stream, &mut blur)?
                        }
                        _ => return Err(self.unexpected_in(&item, "camera")),
                    }
                }
                Item::Block(block) if matches!(&block.head, BlockHead::Word(w) if &**w == "mesh_camera") =>
                {
                    camera.projection = Projection::Mesh;
                    camera.mesh = Some(Arc::new(self.eval_mesh_camera(block)?));
                }
                Item::Block(block) => match self.eval_block(block)? {
                    Value::Transform(t) => transforms.push(*t),
                    Value::Camera(c) => camera = Rc::unwrap_or_clone(c),
                    Value::Normal(normal) => camera.normal = Some(Rc::unwrap_or_clone(normal)),
                    Value::Nothing => {}
                    _ => return Err(self.unexpected_in(&item, "camera")),
                },
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Camera(c) => camera = Rc::unwrap_or_clone(c),
                    _ => return Err(self.unexpected_in(&item, "camera")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "camera")),
            }
        }
        if let Some(mesh) = &mut camera.mesh {
            // Only the z of `location` and `direction` mean something to a mesh camera.
            let mesh = Arc::make_mut(mesh);
            mesh.offset = camera.location.z;
            mesh.reversed = camera.direction.z < -1e-10;
        }
        if let Some(given) = angle.filter(|a| a.is_finite()) {
            camera.angle = given;
            camera.vertical_angle = vertical_angle.unwrap_or(given / 2.0);
        } else if camera.projection == Projection::Spherical {
            // Without `angle` the spherical camera sees everything.
            camera.angle = 360.0;
            camera.vertical_angle = 180.0;
        }
        if let Some(focal_blur) = blur.resolve() {
            camera.focal_blur = Some(focal_blur);
        }
        // Angle sets the direction's length so the horizontal field of view is `angle`.
        if let Some(angle) = angle.filter(|a| a.is_finite()) {
            if camera.projection == Projection::Perspective && angle > 0.0 && angle < 180.0 {
                let length = 0.5 * camera.right.length() / (angle.to_radians() / 2.0).tan();
                camera.direction = camera.direction.normalize_or(DVec3::Z) * length;
            }
        }
        if let Some(target) = look_at {
            let handedness = camera.up.cross(camera.direction).dot(camera.right);
            let direction_length = camera.direction.length();
            let right_length = camera.right.length();
            let up_length = camera.up.length();
            let direction = (target - camera.location).normalize_or(DVec3::Z);
            let mut right = sky.cross(direction).normalize_or(DVec3::X);
            let up = direction.cross(right).normalize_or(DVec3::Y);
            // POV-Ray keeps the right vector only for a strictly left-handed frame: when
            // `up` and `direction` are parallel (up z with the default direction), the
            // frame counts as right-handed and the image is mirrored (prism3a.pov).
            if handedness <= 0.0 {
                right = -right;
            }
            camera.direction = direction * direction_length;
            camera.right = right * right_length;
            camera.up = up * up_length;
        }
        if camera.projection == Projection::Orthographic {
            if let (Some(angle), Some(target)) = (angle, look_at) {
                // Same view as a perspective camera at the look_at distance.
                let angle = if angle.is_finite() {
                    angle
                } else {
                    2.0 * (0.5 * camera.right.length() / camera.direction.length())
                        .atan()
                        .to_degrees()
                };
                let distance = (target - camera.location).length();
                let width = 2.0 * distance * (angle.to_radians() / 2.0).tan();
                let aspect = camera.up.length() / camera.right.length();
                camera.right = camera.right.normalize_or(DVec3::X) * width;
                camera.up = camera.up.normalize_or(DVec3::Y) * width * aspect;
            } else if let (None, Some(target), false) = (angle, look_at, image_plane_given) {
                // Without `right`/`up`, POV-Ray scales the default plane by the look_at distance.
                let distance = (target - camera.location).length();
                camera.right *= distance;
                camera.up *= distance;
            }
        }
        for t in &transforms {
            camera.location = t.point_to_outer(camera.location);
            camera.direction = t.vector_to_outer(camera.direction);
            camera.right = t.vector_to_outer(camera.right);
            camera.up = t.vector_to_outer(camera.up);
            if let Some(focal_blur) = &mut camera.focal_blur {
                focal_blur.focal_point = t.point_to_outer(focal_blur.focal_point);
            }
        }
        Ok(camera)
    }

    fn eval_global_settings(&mut self, stream: &mut Stream) -> EvalResult<()> {
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "assumed_gamma" => {
                        self.settings.assumed_gamma = Some(self.expect_float(stream, "a float")?)
                    }
                    "max_trace_level" => {
                        let level = self.expect_float(stream, "a float")?;
                        self.settings.max_trace_level = level.clamp(1.0, 256.0) as u32;
                    }
                    "adc_bailout" => {
                        self.settings.adc_bailout = self.expect_float(stream, "a float")?
                    }
                    "ambient_light" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        self.settings.ambient_light = self.to_colour(value, span)?.rgb_vec();
                    }
                    "noise_generator" => {
                        let generator = self.expect_noise_generator(stream)?.unwrap_or_default();
                        self.settings.noise_generator = generator;
                        self.settings.scene_noise_generator.set(generator);
                    }
                    "number_of_waves" => self.number_of_waves(stream)?,
                    "irid_wavelength" => {
                        let (value, span) = self.expect_value(stream, "a colour")?;
                        self.settings.irid_wavelength = self.to_colour(value, span)?.rgb_vec();
                    }
                    "charset" | "max_intersections" | "hf_gray_16" | "mm_per_unit"
                    | "subsurface" => {
                        self.warn(
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
                        self.warn(block.head_span, message);
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

/// An atmospheric effect as a value.
fn atmospheric(effect: AtmosphericEffect) -> Value {
    Value::Atmospheric(Rc::new(effect))
}

/// A short description of an item for messages.
pub(crate) fn describe_item(item: &Item) -> String {
    match item {
        Item::Keyword(word, _) => format!("`{word}`"),
        Item::Block(block) => match &block.head {
            BlockHead::Word(w) => format!("`{w} {{ .. }}`"),
            BlockHead::Conditional(_) => "a block".to_string(),
        },
        Item::Expr(crate::syntax::ast::Expr::Ident(name, _)) => format!("`{name}`"),
        Item::Expr(_) => "a value".to_string(),
        Item::Comma(_) => "`,`".to_string(),
        Item::MapEntry(..) => "a map entry `[ .. ]`".to_string(),
        Item::Directive(_) => "a directive".to_string(),
    }
}
