//! Camera items beyond the basic vectors: focal blur, the spherical camera's second
//! angle and `mesh_camera`.
//!
//! In: camera block items. Out: a resolved [`FocalBlur`], a [`MeshCamera`] with its faces
//! in world space (read from the meshes, which stay untouched). Holds: POV-Ray's defaults
//! (focal point at the origin, confidence 0.9, variance 1/128, minimum samples 4 below 7
//! samples, else 7); bad values are reported with their span.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{Camera, CylinderKind, Projection};
use crate::syntax::ast::{Block, BlockHead, Item};
use crate::{
    math::Transform,
    scene::{CameraFace, FocalBlur, Mesh, MeshCamera, MeshDistribution, Shape, UvFace, UvFaces},
};
use glam::DVec3;
use std::rc::Rc;
use std::sync::Arc;

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
                        .runtime
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
                .runtime
                .error(span, format!("{count} is not a number of samples"))
                .with_label("expected a whole number of at least 1")
                .into())
        }
    }
}

/// The largest `rays_per_pixel` of a mesh camera.
const MAX_MESH_RAYS: f64 = 1024.0;

impl Evaluator {
    /// `mesh_camera { rays_per_pixel distribution [max_distance] mesh { .. } .. [smooth] }`;
    /// the camera's `location` and `direction` fill in `offset` and `reversed` afterwards.
    pub(crate) fn eval_mesh_camera(&mut self, block: &Block) -> EvalResult<MeshCamera> {
        let mut stream = Stream::new(block.body.clone());
        let (value, rays_span) = self.expect_value(&mut stream, "the number of rays per pixel")?;
        let rays = self.to_float(value, rays_span)?;
        if !(1.0..=MAX_MESH_RAYS).contains(&rays) {
            return Err(self
                .runtime
                .error(rays_span, format!("{rays} rays per pixel"))
                .with_label(format!("expected 1 to {MAX_MESH_RAYS}"))
                .into());
        }
        self.skip_comma(&mut stream)?;
        let (value, type_span) = self.expect_value(&mut stream, "the distribution type")?;
        let distribution = match self.to_float(value, type_span)? {
            0.0 => MeshDistribution::PerMesh,
            1.0 => MeshDistribution::Summed,
            2.0 => MeshDistribution::SideBySide,
            3.0 => MeshDistribution::UvMapped,
            other => {
                return Err(self
                    .runtime
                    .error(
                        type_span,
                        format!("unknown mesh camera distribution {other}"),
                    )
                    .with_label("expected 0, 1, 2 or 3")
                    .into())
            }
        };
        let single_ray = matches!(
            distribution,
            MeshDistribution::SideBySide | MeshDistribution::UvMapped
        );
        if single_ray && rays != 1.0 {
            return Err(self
                .runtime
                .error(rays_span, format!("{rays} rays per pixel"))
                .with_label("distributions 2 and 3 shoot exactly 1 ray per pixel")
                .into());
        }
        let mut camera = MeshCamera {
            rays_per_pixel: rays as u32,
            distribution,
            max_distance: 0.0,
            meshes: Vec::new(),
            uv_faces: UvFaces::default(),
            smooth: false,
            offset: 0.0,
            reversed: false,
        };
        if let Some((distance, _)) = self.optional_second_value(&mut stream)? {
            camera.max_distance = distance.max(0.0);
        }
        let mut uv_faces = Vec::new();
        let mut mesh_count = 0;
        while let Some(item) = self.next_item(&mut stream)? {
            match &item {
                Item::Comma(_) => {}
                Item::Block(mesh) if matches!(&mesh.head, BlockHead::Word(w) if &**w == "mesh") => {
                    let (mesh, transform) = self.camera_mesh(mesh)?;
                    mesh_count += 1;
                    if distribution == MeshDistribution::UvMapped {
                        uv_faces.extend(uv_camera_faces(&mesh, &transform));
                    } else {
                        camera.meshes.push(camera_faces(&mesh, &transform));
                    }
                }
                Item::Keyword(word, span) if &**word == "smooth" => {
                    if distribution != MeshDistribution::UvMapped {
                        return Err(self
                            .runtime
                            .error(*span, "`smooth` needs mesh camera distribution 3")
                            .with_label("only uv-mapped mesh cameras interpolate normals")
                            .into());
                    }
                    camera.smooth = true;
                }
                _ => return Err(self.unexpected_in(&item, "mesh_camera")),
            }
        }
        if mesh_count == 0 {
            return Err(self
                .runtime
                .error(block.span, "a mesh camera needs at least one `mesh { .. }`")
                .with_label("no mesh in this mesh_camera")
                .into());
        }
        camera.uv_faces = UvFaces::new(uv_faces);
        if distribution == MeshDistribution::PerMesh && camera.meshes.len() < rays as usize {
            return Err(self
                .runtime
                .error(
                    rays_span,
                    format!(
                        "distribution 0 needs a mesh for each of the {rays} rays per pixel, \
                         found {} meshes",
                        camera.meshes.len()
                    ),
                )
                .into());
        }
        Ok(camera)
    }

    /// The mesh of one camera `mesh { MESH_IDENTIFIER transformations }` (or an inline
    /// mesh) and the transformation to world space.
    fn camera_mesh(&mut self, block: &Block) -> EvalResult<(Arc<Mesh>, Transform)> {
        let object = match self.eval_block(block)? {
            Value::Object(object) => object,
            other => {
                return Err(self
                    .runtime
                    .error(
                        block.span,
                        format!("expected a mesh, found {}", other.type_name()),
                    )
                    .into())
            }
        };
        let Shape::Mesh(mesh) = &object.shape else {
            return Err(self
                .runtime
                .error(block.span, "a mesh camera needs `mesh` or `mesh2` objects")
                .with_label("this is not a mesh")
                .into());
        };
        Ok((mesh.clone(), *object.transform()))
    }
}

/// The faces of `mesh` for distributions 0-2: centroids and face normals in world space.
fn camera_faces(mesh: &Mesh, transform: &Transform) -> Vec<CameraFace> {
    mesh.triangles()
        .map(|triangle| {
            let [a, b, c] = triangle
                .corners
                .map(|corner| transform.point_to_outer(corner));
            CameraFace {
                centre: (a + b + c) / 3.0,
                normal: (c - a).cross(b - a).normalize_or_zero(),
            }
        })
        .collect()
}

/// The faces of `mesh` for distribution 3: corners, normals and uv coordinates, in world
/// space. POV-Ray normalises a smooth triangle's corner normals before interpolating them,
/// and a flat face its face normal at every corner.
fn uv_camera_faces<'a>(
    mesh: &'a Mesh,
    transform: &'a Transform,
) -> impl Iterator<Item = UvFace> + 'a {
    let to_world = |normal: DVec3| transform.normal_to_outer(normal).normalize_or_zero();
    (0..mesh.len()).map(move |index| {
        let triangle = mesh.triangle(index);
        let [a, b, c] = triangle
            .corners
            .map(|corner| transform.point_to_outer(corner));
        let normal = (c - a).cross(b - a).normalize_or_zero();
        UvFace {
            corners: [a, b, c],
            corner_normals: triangle.normals.map_or([normal; 3], |n| n.map(to_world)),
            normal,
            uvs: mesh.corner_uvs(index),
        }
    })
}

impl Evaluator {
    /// POV-Ray refuses a negative viewing angle, and one of 180 degrees or more for the two
    /// cameras that look through a plane.
    fn check_viewing_angle(
        &self,
        angle: f64,
        projection: Projection,
        span: Span,
    ) -> EvalResult<()> {
        let planar = matches!(
            projection,
            Projection::Perspective | Projection::Orthographic
        );
        let problem = if angle < 0.0 {
            "a viewing angle cannot be negative"
        } else if planar && angle >= 180.0 {
            "this camera's viewing angle must be smaller than 180 degrees"
        } else {
            return Ok(());
        };
        Err(self
            .runtime
            .error(span, problem)
            .with_label(format!("angle {angle}"))
            .into())
    }

    pub(crate) fn eval_camera(&mut self, stream: &mut Stream) -> EvalResult<Camera> {
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
                                Some(Item::Expr(expr)) => {
                                    let angle_span = expr.span();
                                    let given = self.expect_float(stream, "an angle")?;
                                    self.check_viewing_angle(given, camera.projection, angle_span)?;
                                    angle = Some(given);
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
                                    .runtime
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
                // Same view as a perspective camera at the look_at distance; `angle 0` (or
                // no value) takes the perspective angle of `right` and `direction`, as povray.
                let angle = if angle.is_finite() && angle > 0.0 && angle < 180.0 {
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
}
