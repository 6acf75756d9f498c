//! Objects: shapes, CSG, `object { Ident }`, and the modifiers and transformations that
//! apply to them.

use super::texture_maps::{change_top_layer, layered, top_layer, top_layer_finish};
use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::{MaterialValue, Value};
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Block, Expr, Item};
use crate::{
    math::Transform,
    scene::{CsgOperation, Interior, LightGroup, Object, Shape},
    texture::Texture,
};
use glam::{DAffine3, DMat3, DVec3};
use std::rc::Rc;
use std::sync::Arc;

impl Evaluator {
    /// Whether a block starts with the identifier of a declared object (not a light).
    pub(crate) fn starts_with_declared_object(&mut self, stream: &mut Stream) -> EvalResult<bool> {
        Ok(match self.peek_item(stream)? {
            Some(Item::Expr(Expr::Ident(name, _))) => {
                matches!(self.runtime.lookup(name), Some(Value::Object(_)))
            }
            _ => false,
        })
    }

    /// Evaluates the body of an object block (`head` is its keyword), counted against the
    /// `objects` limit.
    /// `None` when the object is a feature durer leaves out (already warned about).
    pub(crate) fn eval_object(
        &mut self,
        head: &str,
        block: &Block,
        stream: &mut Stream,
    ) -> EvalResult<Option<Object>> {
        self.runtime.count_objects(1, block.head_span)?;
        // POV-Ray lets every shape and CSG block start with a declared object (or light), as
        // `object { .. }` does, whatever its kind: `sphere { Box_Ident scale 2 }` is that box
        // (measured); only object modifiers may follow it. A mesh takes any value there.
        let starts_with_object = match self.peek_item(stream)? {
            Some(Item::Expr(_)) if matches!(head, "mesh" | "mesh2") => true,
            Some(Item::Expr(Expr::Ident(name, _))) if head != "light_group" => matches!(
                self.runtime.lookup(name),
                Some(Value::Object(_) | Value::Light(_))
            ),
            _ => false,
        };
        let mut object = match head {
            _ if head == "object" || starts_with_object => {
                let (value, span) = self.expect_value(stream, "an object")?;
                match value {
                    Value::Object(o) => {
                        // A copy costs as much as its tree: count every node, and refuse a
                        // tree deeper than blocks may nest (a loop of
                        // `#declare O = union { object { O } }` grows one level each time).
                        let (size, depth) = tree_measure(&o);
                        self.runtime.count_objects(size, span)?;
                        let limit = self.runtime.options().limits.nesting;
                        if depth > limit {
                            return Err(self
                                .runtime
                                .error(
                                    span,
                                    format!("this object nests more than {limit} levels deep"),
                                )
                                .with_label("too deep")
                                .with_help(crate::limits::Limits::raise_hint("nesting", limit))
                                .into());
                        }
                        Arc::unwrap_or_clone(o)
                    }
                    Value::Nothing => return Ok(None),
                    // `object { Light transforms }`: an empty union carrying the light, so
                    // it moves with the transformations and with any CSG around it.
                    Value::Light(light) => {
                        let mut carrier = Object::new(Shape::Csg {
                            operation: CsgOperation::Union,
                            children: Vec::new(),
                        });
                        carrier.lights = Some(Box::new(vec![Rc::unwrap_or_clone(light)]));
                        self.scene.objects_carry_lights = true;
                        carrier
                    }
                    other => {
                        return Err(self
                            .runtime
                            .error(
                                span,
                                format!("expected an object, found {}", other.type_name()),
                            )
                            .with_label(format!("`{head}` needs an object identifier"))
                            .into())
                    }
                }
            }
            "union" | "intersection" | "difference" | "merge" | "light_group" => {
                let operation = match head {
                    "union" | "light_group" => CsgOperation::Union,
                    "intersection" => CsgOperation::Intersection,
                    "difference" => CsgOperation::Difference,
                    _ => CsgOperation::Merge,
                };
                let mut object = Object::new(Shape::Csg {
                    operation,
                    children: Vec::new(),
                });
                // A light group is a union whose lights light only its objects.
                let group = (head == "light_group").then(|| {
                    self.scene.light_groups += 1;
                    LightGroup {
                        id: self.scene.light_groups,
                        global_lights: false,
                    }
                });
                object.light_group = group;
                let mut uv_mapping = false;
                while let Some(item) = self.next_item(stream)? {
                    let child = match &item {
                        Item::Keyword(word, _) if group.is_some() && &**word == "global_lights" => {
                            let global_lights = self.optional_bool(stream)?;
                            if let Some(group) = &mut object.light_group {
                                group.global_lights = global_lights;
                            }
                            None
                        }
                        Item::Block(b)
                            if matches!(&b.head, crate::syntax::ast::BlockHead::Word(w)
                                if matches!(&**w, "clipped_by" | "bounded_by" | "interior_texture" | "material" | "photons" | "finish")) =>
                        {
                            self.object_modifier(&mut object, item, stream, head, &mut uv_mapping)?;
                            None
                        }
                        Item::Block(b) => match self.eval_block(b)? {
                            Value::Object(o) => Some(o),
                            Value::Light(light) => {
                                // The light moves with the CSG and joins the scene where
                                // the CSG is placed; in a light group it lights only the
                                // group.
                                let mut light = Rc::unwrap_or_clone(light);
                                if let Some(group) = group {
                                    light.group = Some(group.id);
                                }
                                object
                                    .lights
                                    .get_or_insert_with(Default::default)
                                    .push(light);
                                self.scene.objects_carry_lights = true;
                                None
                            }
                            other => {
                                let other = uv_mapped_if(other, uv_mapping);
                                self.object_modifier_value(&mut object, other, item.span())?;
                                None
                            }
                        },
                        _ => {
                            self.object_modifier(&mut object, item, stream, head, &mut uv_mapping)?;
                            None
                        }
                    };
                    if let Some(child) = child {
                        if let Shape::Csg { children, .. } = &mut object.shape {
                            children.push(Arc::unwrap_or_clone(child));
                        }
                    }
                }
                return Ok(Some(object));
            }
            _ => Object::new(self.eval_shape(head, block, stream)?),
        };
        let mut uv_mapping = false;
        while let Some(item) = self.next_item(stream)? {
            self.object_modifier(&mut object, item, stream, head, &mut uv_mapping)?;
        }
        Ok(Some(object))
    }

    /// Reads a shape's required parameters.
    fn eval_shape(&mut self, head: &str, block: &Block, stream: &mut Stream) -> EvalResult<Shape> {
        Ok(match head {
            "smooth_triangle" => self.eval_smooth_triangle(stream)?,
            "polygon" => self.eval_polygon(block.head_span, stream)?,
            "mesh" => self.eval_mesh(stream)?,
            "mesh2" => self.eval_mesh2(block.head_span, stream)?,
            "poly" | "cubic" | "quartic" => self.eval_poly(head, block.head_span, stream)?,
            "text" => self.eval_text(block.head_span, stream)?,
            "prism" => self.eval_prism(block.head_span, stream)?,
            "lathe" => self.eval_lathe(block.head_span, stream)?,
            "blob" => self.eval_blob(stream)?,
            "isosurface" => self.eval_isosurface(block.head_span, stream)?,
            "julia_fractal" => self.eval_julia_fractal(block.head_span, stream)?,
            "height_field" => self.eval_height_field(block.head_span, stream)?,
            "sphere_sweep" => self.eval_sphere_sweep(block.head_span, stream)?,
            "bicubic_patch" => self.eval_bicubic_patch(block.head_span, stream)?,
            "ovus" => self.eval_ovus(stream)?,
            "lemon" => self.eval_lemon(block.head_span, stream)?,
            "parametric" => self.eval_parametric(block.head_span, stream)?,
            "sor" => self.eval_sor(block.head_span, stream)?,
            "superellipsoid" => {
                let (value, span) = self.expect_value(stream, "<east-west, north-south>")?;
                let exponents = self.to_vector3(value, span)?;
                Shape::Superellipsoid {
                    east_west: exponents.x,
                    north_south: exponents.y,
                }
            }
            "sphere" => {
                let centre = self.expect_vector(stream, "the centre")?;
                let radius = self.expect_float(stream, "the radius")?;
                Shape::Sphere { centre, radius }
            }
            "box" => {
                let corner1 = self.expect_vector(stream, "a corner")?;
                let corner2 = self.expect_vector(stream, "the opposite corner")?;
                Shape::Box { corner1, corner2 }
            }
            "plane" => {
                let normal = self.expect_vector(stream, "the normal")?;
                let distance = self.expect_float(stream, "the distance")?;
                Shape::Plane { normal, distance }
            }
            "cylinder" => {
                let base = self.expect_vector(stream, "the base point")?;
                let cap = self.expect_vector(stream, "the cap point")?;
                let radius = self.expect_float(stream, "the radius")?;
                Shape::Cylinder {
                    base,
                    cap,
                    radius,
                    open: false,
                }
            }
            "cone" => {
                let base = self.expect_vector(stream, "the base point")?;
                let base_radius = self.expect_float(stream, "the base radius")?;
                let cap = self.expect_vector(stream, "the cap point")?;
                let cap_radius = self.expect_float(stream, "the cap radius")?;
                Shape::Cone {
                    base,
                    base_radius,
                    cap,
                    cap_radius,
                    open: false,
                }
            }
            "torus" => {
                let major = self.expect_float(stream, "the major radius")?;
                let minor = self.expect_float(stream, "the minor radius")?;
                Shape::Torus { major, minor }
            }
            "disc" => {
                let centre = self.expect_vector(stream, "the centre")?;
                let normal = self.expect_vector(stream, "the normal")?;
                let radius = self.expect_float(stream, "the radius")?;
                let mut hole_radius = 0.0;
                match self.next_item(stream)? {
                    Some(Item::Comma(_)) => {
                        hole_radius = self.expect_float(stream, "the hole radius")?
                    }
                    Some(other) => stream.push_back(other),
                    None => {}
                }
                Shape::Disc {
                    centre,
                    normal,
                    radius,
                    hole_radius,
                }
            }
            "quadric" => {
                let a = self.expect_vector(stream, "<A, B, C>")?;
                let b = self.expect_vector(stream, "<D, E, F>")?;
                let c = self.expect_vector(stream, "<G, H, I>")?;
                let j = self.expect_float(stream, "J")?;
                Shape::Quadric {
                    coefficients: Box::new([a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, j]),
                }
            }
            _ => {
                let a = self.expect_vector(stream, "the first corner")?;
                let b = self.expect_vector(stream, "the second corner")?;
                let c = self.expect_vector(stream, "the third corner")?;
                Shape::Triangle {
                    corners: Box::new([a, b, c]),
                }
            }
        })
    }

    /// Applies one modifier item to an object. `uv_mapping` is set by the object's own
    /// `uv_mapping` item, which maps every texture, pigment and normal given after it by uv.
    pub(crate) fn object_modifier(
        &mut self,
        object: &mut Object,
        item: Item,
        stream: &mut Stream,
        head: &str,
        uv_mapping: &mut bool,
    ) -> EvalResult<()> {
        match &item {
            Item::Keyword(word, span) => match &**word {
                // As povray: every texture, pigment and normal of the object is uv-mapped;
                // one given before is refused.
                "uv_mapping" => {
                    if object.texture.is_some() || object.interior_texture.is_some() {
                        return Err(self
                            .runtime
                            .error(*span, "`uv_mapping` must come before the object's texture")
                            .with_label("the object has a texture already")
                            .with_help("write it before `texture`, `pigment` and `normal`")
                            .into());
                    }
                    *uv_mapping = true;
                }
                "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                    let t = self.transform_keyword(word, *span, stream)?;
                    apply_transform(object, &t);
                }
                "inverse" => object.inverse = !object.inverse,
                "no_shadow" => object.no_shadow = true,
                "hollow" => object.hollow = Some(self.optional_bool(stream)?),
                "open" => match &mut object.shape {
                    Shape::Cylinder { open, .. } | Shape::Cone { open, .. } => *open = true,
                    Shape::Prism(prism) => Arc::make_mut(prism).open = true,
                    Shape::Sor { open, .. } => *open = true,
                    Shape::Lemon(lemon) => Arc::make_mut(lemon).open = true,
                    _ => return Err(self.unexpected_in(&item, head)),
                },
                "sturm" => {
                    let sturm = self.optional_bool(stream)?;
                    if let Shape::Poly(poly) = &mut object.shape {
                        Arc::make_mut(poly).sturm = sturm;
                    }
                }
                "threshold" => {
                    let threshold = self.expect_float(stream, "the threshold")?;
                    match &mut object.shape {
                        Shape::Blob(blob) => Arc::make_mut(blob).threshold = threshold,
                        _ => return Err(self.unexpected_in(&item, head)),
                    }
                }
                "inside_vector" => {
                    let vector = self.expect_vector(stream, "the inside vector")?;
                    match &mut object.shape {
                        Shape::Mesh(mesh) => Arc::make_mut(mesh).inside_vector = Some(vector),
                        _ => return Err(self.unexpected_in(&item, head)),
                    }
                }
                "hierarchy" => {
                    let _ = self.optional_bool(stream)?;
                }
                "no_image" => object.no_image = self.optional_bool(stream)?,
                "no_reflection" => object.no_reflection = self.optional_bool(stream)?,
                "double_illuminate" => object.double_illuminate = self.optional_bool(stream)?,
                "no_radiosity" => object.no_radiosity = self.optional_bool(stream)?,
                "cutaway_textures" => match &mut object.shape {
                    Shape::Csg {
                        operation:
                            operation @ (crate::scene::CsgOperation::Difference
                            | crate::scene::CsgOperation::Intersection),
                        children,
                    } => cutaway_textures(*operation, children),
                    // As POV-Ray: "cutaway_textures can only be used with intersection and
                    // difference".
                    _ => {
                        return Err(self
                            .runtime
                            .error(
                                *span,
                                "`cutaway_textures` can only be used with intersection and \
                                 difference",
                            )
                            .with_label(format!("inside `{head}`"))
                            .into())
                    }
                },
                _ => return Err(self.unexpected_in(&item, head)),
            },
            Item::Block(block) => {
                if let crate::syntax::ast::BlockHead::Word(w) = &block.head {
                    if &**w == "material" {
                        let mut body = Stream::new(block.body.clone());
                        let material = self.eval_material(&mut body)?;
                        if let Some(texture) = material.texture {
                            self.attach_texture(object, texture);
                        }
                        if let Some(texture) = material.interior_texture {
                            self.attach_interior_texture(object, texture);
                        }
                        if let Some(interior) = material.interior {
                            attach_interior(object, interior);
                        }
                        return Ok(());
                    }
                    if &**w == "interior_texture" {
                        let mut body = Stream::new(block.body.clone());
                        let texture = self.eval_texture(&mut body)?;
                        self.attach_interior_texture(object, texture);
                        return Ok(());
                    }
                    if &**w == "radiosity" {
                        let mut body = Stream::new(block.body.clone());
                        return self.eval_object_radiosity(&mut body);
                    }
                    if &**w == "photons" {
                        let mut body = Stream::new(block.body.clone());
                        return self.eval_object_photons(&mut body, &mut object.photons);
                    }
                    if &**w == "clipped_by" || &**w == "bounded_by" {
                        return self.eval_clip_or_bound(object, w, block);
                    }
                    // `object { O pigment { scale 2 } }`: a pigment given to an object that
                    // has a texture modifies that texture's (its top layer's), as povray
                    // renders it (measured: the pattern keeps its map and transformations, and
                    // a new pattern keeps the old one's transformations, as in `texture { T
                    // pigment { .. } }`), evaluated where the object stands.
                    if &**w == "pigment" && object.texture.is_some() && !*uv_mapping {
                        let mut texture = self.object_texture(object);
                        let mut base = top_layer(&texture).pigment.clone();
                        base.transform(object.transform());
                        let mut body = Stream::new(block.body.clone());
                        let mut pigment = self.eval_pigment_from(&mut body, base)?;
                        pigment.transform(&object.transform().inverse());
                        change_top_layer(&mut texture, |top| top.pigment = pigment);
                        object.texture = Some(Arc::new(texture));
                        return Ok(());
                    }
                    if &**w == "finish" {
                        let mut texture = self.object_texture(object);
                        let base = top_layer_finish(&texture).clone();
                        let mut body = Stream::new(block.body.clone());
                        let finish = self.eval_finish(&mut body, Some(base))?;
                        let finish = Arc::new(finish);
                        change_top_layer(&mut texture, |top| top.finish = finish.clone());
                        object.texture = Some(Arc::new(texture));
                        return Ok(());
                    }
                }
                let value = uv_mapped_if(self.eval_block(block)?, *uv_mapping);
                self.object_modifier_value(object, value, block.span)?;
            }
            Item::Comma(_) => {}
            Item::Expr(expr) => {
                let value = self.eval_expr(expr)?;
                if matches!(
                    value,
                    Value::Vector(_) | Value::String(_) | Value::Colour(_)
                ) {
                    return Err(self.unexpected_in(&item, head));
                }
                let value = uv_mapped_if(value, *uv_mapping);
                self.object_modifier_value(object, value, expr.span())?;
            }
            _ => return Err(self.unexpected_in(&item, head)),
        }
        Ok(())
    }

    /// Applies an evaluated modifier (texture, pigment, transform...) to an object.
    pub(crate) fn object_modifier_value(
        &mut self,
        object: &mut Object,
        value: Value,
        span: Span,
    ) -> EvalResult<()> {
        match value {
            Value::Texture(texture) => self.attach_texture(object, (*texture).clone()),
            Value::Normal(normal) => {
                let mut texture = self.object_texture(object);
                let mut normal = Rc::unwrap_or_clone(normal);
                normal.transform(&object.transform().inverse());
                change_top_layer(&mut texture, |top| top.normal = Some(Box::new(normal)));
                object.texture = Some(Arc::new(texture));
            }
            Value::Pigment(pigment) => {
                let mut texture = self.object_texture(object);
                let mut pigment = Rc::unwrap_or_clone(pigment);
                pigment.transform(&object.transform().inverse());
                change_top_layer(&mut texture, |top| top.pigment = pigment);
                object.texture = Some(Arc::new(texture));
            }
            Value::Finish(finish) => {
                let mut texture = self.object_texture(object);
                let finish = Arc::new(Rc::unwrap_or_clone(finish));
                change_top_layer(&mut texture, |top| top.finish = finish.clone());
                object.texture = Some(Arc::new(texture));
            }
            Value::Interior(interior) => attach_interior(object, Rc::unwrap_or_clone(interior)),
            Value::Transform(t) => apply_transform(object, &t),
            Value::Nothing => {} // a left-out block such as `media { .. }`
            other => {
                return Err(self
                    .runtime
                    .error(
                        span,
                        format!("{} cannot modify an object", other.type_name()),
                    )
                    .with_label("not an object modifier")
                    .into())
            }
        }
        Ok(())
    }

    /// `clipped_by { objects | bounded_by }` or `bounded_by { objects | clipped_by }`; the
    /// objects are stored in the object's local space, so later transformations move them.
    fn eval_clip_or_bound(
        &mut self,
        object: &mut Object,
        word: &str,
        block: &Block,
    ) -> EvalResult<()> {
        let mut body = Stream::new(block.body.clone());
        let mut found = Vec::new();
        while let Some(item) = self.next_item(&mut body)? {
            match &item {
                Item::Keyword(other, _) if &**other == "bounded_by" && word == "clipped_by" => {
                    found.extend(object.bounded_by.iter().cloned());
                }
                Item::Keyword(other, _) if &**other == "clipped_by" && word == "bounded_by" => {
                    found.extend(object.clipped_by.iter().cloned());
                }
                Item::Comma(_) => {}
                Item::Block(_) | Item::Expr(_) => match self.item_value(&item)? {
                    Value::Object(child) => {
                        let mut child = Arc::unwrap_or_clone(child);
                        apply_transform(&mut child, &object.transform().inverse());
                        found.push(child);
                    }
                    Value::Nothing => {}
                    _ => return Err(self.unexpected_in(&item, word)),
                },
                _ => return Err(self.unexpected_in(&item, word)),
            }
        }
        if word == "clipped_by" {
            object.clipped_by.extend(found);
        } else {
            object.bounded_by.extend(found);
        }
        Ok(())
    }

    /// The object's texture (already in its local space) or a fresh default one, placed
    /// where the object stands now: transformations written before the `pigment`, `normal`
    /// or `finish` that asks for it do not move its patterns, later ones do (measured with
    /// a `#default` gradient).
    fn object_texture(&self, object: &Object) -> Texture {
        match &object.texture {
            Some(t) => (**t).clone(),
            None => {
                let mut texture = self.scene.default_texture.clone();
                if *object.transform() != Transform::IDENTITY && texture.depends_on_position() {
                    texture.transform(&object.transform().inverse());
                }
                texture
            }
        }
    }

    /// Attaches a texture given in the object's outer space, re-expressing its patterns in
    /// the object's local space so later transformations carry it along; layered on top of
    /// a texture the object already has.
    fn attach_texture(&mut self, object: &mut Object, mut texture: Texture) {
        texture.transform(&object.transform().inverse());
        // POV-Ray lays a texture given to an object that has one on top of it.
        let texture = match object.texture.take() {
            Some(below) => layered(vec![Texture::clone(&below), texture]),
            None => texture,
        };
        object.texture = Some(Arc::new(texture));
    }

    /// Attaches an `interior_texture` given in the object's outer space like
    /// [`Self::attach_texture`]: a second one is laid on top of the first (measured).
    fn attach_interior_texture(&mut self, object: &mut Object, mut texture: Texture) {
        texture.transform(&object.transform().inverse());
        let texture = match object.interior_texture.take() {
            Some(below) => layered(vec![Texture::clone(&below), texture]),
            None => texture,
        };
        object.interior_texture = Some(Arc::new(texture));
    }

    /// Reads the operand of `translate`, `rotate`, `scale`, `matrix` or `transform`.
    pub(crate) fn transform_keyword(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Transform> {
        Ok(match word {
            "translate" => Transform::translation(self.expect_vector(stream, "a vector")?),
            "rotate" => Transform::rotation_degrees(self.expect_vector(stream, "a vector")?),
            "scale" => {
                let mut factors = self.expect_vector(stream, "a vector")?;
                // POV-Ray turns zero scale factors into 1 with a warning.
                for c in [&mut factors.x, &mut factors.y, &mut factors.z] {
                    if *c == 0.0 {
                        *c = 1.0;
                        self.runtime.warn(span, "scale factor of zero changed to 1");
                    }
                }
                Transform::scaling(factors).unwrap_or(Transform::IDENTITY)
            }
            "matrix" => return self.eval_matrix(span, stream),
            _ => {
                let (value, vspan) = self.expect_value(stream, "a transform")?;
                match value {
                    Value::Transform(t) => *t,
                    other => {
                        return Err(self
                            .runtime
                            .error(
                                vspan,
                                format!("expected a transform, found {}", other.type_name()),
                            )
                            .into())
                    }
                }
            }
        })
    }

    /// `matrix <m00, m01, m02, m10, .., m32>`: twelve numbers, rows applied to row vectors.
    fn eval_matrix(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Transform> {
        let item = self.next_item(stream)?;
        let Some(Item::Expr(crate::syntax::ast::Expr::Vector(elements, vspan))) = item else {
            return Err(self
                .runtime
                .error(span, "expected `matrix < 12 numbers >`")
                .into());
        };
        if elements.len() != 12 {
            return Err(self
                .runtime
                .error(
                    vspan,
                    format!("a matrix has 12 numbers, found {}", elements.len()),
                )
                .into());
        }
        let mut values = [0.0; 12];
        for (v, e) in values.iter_mut().zip(elements.iter()) {
            *v = self.eval_float(e)?;
        }
        matrix_transform(&values).ok_or_else(|| {
            self.runtime
                .error(vspan, "this matrix is singular")
                .with_label("cannot be inverted")
                .into()
        })
    }

    /// `transform { .. }` block: a sequence of transformations (and `inverse`).
    pub(crate) fn eval_transform_block(&mut self, stream: &mut Stream) -> EvalResult<Transform> {
        let mut result = Transform::IDENTITY;
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, span) => match &**word {
                    "translate" | "rotate" | "scale" | "matrix" | "transform" => {
                        let t = self.transform_keyword(word, *span, stream)?;
                        result = result.then(&t);
                    }
                    "inverse" => result = result.inverse(),
                    _ => return Err(self.unexpected_in(&item, "transform")),
                },
                Item::Expr(expr) => match self.eval_expr(expr)? {
                    Value::Transform(t) => result = result.then(&t),
                    _ => return Err(self.unexpected_in(&item, "transform")),
                },
                Item::Block(block) => match self.eval_block(block)? {
                    Value::Transform(t) => result = result.then(&t),
                    _ => return Err(self.unexpected_in(&item, "transform")),
                },
                Item::Comma(_) => {}
                _ => return Err(self.unexpected_in(&item, "transform")),
            }
        }
        Ok(result)
    }

    /// `material { texture { .. } interior_texture { .. } interior { .. } }`.
    pub(crate) fn eval_material(&mut self, stream: &mut Stream) -> EvalResult<MaterialValue> {
        let mut material = MaterialValue {
            texture: None,
            interior_texture: None,
            interior: None,
        };
        while let Some(item) = self.next_item(stream)? {
            let value = match &item {
                Item::Block(b)
                    if matches!(&b.head, crate::syntax::ast::BlockHead::Word(w)
                        if &**w == "interior_texture") =>
                {
                    let mut body = Stream::new(b.body.clone());
                    material.interior_texture = Some(self.eval_texture(&mut body)?);
                    continue;
                }
                // A transformation moves what the material holds so far (measured: a
                // `translate` after `texture { }` moves its pattern, one before it does not).
                Item::Keyword(word, span)
                    if matches!(
                        &**word,
                        "translate" | "rotate" | "scale" | "matrix" | "transform"
                    ) =>
                {
                    let t = self.transform_keyword(word, *span, stream)?;
                    material.transform(&t);
                    continue;
                }
                Item::Block(b) => self.eval_block(b)?,
                Item::Expr(e) => self.eval_expr(e)?,
                Item::Comma(_) => continue,
                _ => return Err(self.unexpected_in(&item, "material")),
            };
            match value {
                Value::Transform(t) => material.transform(&t),
                Value::Texture(t) => material.texture = Some((*t).clone()),
                Value::Interior(i) => material.interior = Some(Rc::unwrap_or_clone(i)),
                Value::Material(declared) => {
                    let declared = Rc::unwrap_or_clone(declared);
                    if declared.texture.is_some() {
                        material.texture = declared.texture;
                    }
                    if declared.interior_texture.is_some() {
                        material.interior_texture = declared.interior_texture;
                    }
                    if declared.interior.is_some() {
                        material.interior = declared.interior;
                    }
                }
                _ => return Err(self.unexpected_in(&item, "material")),
            }
        }
        Ok(material)
    }
}

/// Gives `object` the interior `interior`, whose media densities are written in the
/// object's outer space: they are re-expressed in its local space, so transformations
/// written before the interior do not move them and later ones do (measured: POV-Ray
/// leaves a density in place when `translate` comes before `interior`).
fn attach_interior(object: &mut Object, mut interior: Interior) {
    let local_from_outer = object.transform().inverse();
    for media in &mut interior.media {
        media.transform(&local_from_outer);
    }
    object.interior = Some(Box::new(interior));
}

/// Applies a transformation to an object (its textures ride along in local space).
/// `cutaway_textures` in a difference or intersection: the surfaces an untextured child
/// cuts show the texture of the child they lie inside (evaluated there) instead of the
/// default texture. Of a difference that is the first child (the cut surfaces of the
/// others lie inside it); of an intersection the first textured child (POV-Ray averages
/// the textures of all the textured children a point lies in; with one textured child,
/// the common case, that is the same). Measured: an untextured box cut out of a red sphere
/// shows black without it and the sphere's red with it; a textured cutter keeps its own.
fn cutaway_textures(operation: crate::scene::CsgOperation, children: &mut [Object]) {
    use crate::scene::CsgOperation;
    let donor = match operation {
        CsgOperation::Difference => children.first().filter(|c| c.texture.is_some()),
        CsgOperation::Intersection => children.iter().find(|c| c.texture.is_some()),
        _ => None,
    };
    let Some(donor) = donor else {
        return;
    };
    let (Some(texture), donor_placement) = (donor.texture.clone(), *donor.transform()) else {
        return;
    };
    for child in children.iter_mut() {
        if child.texture.is_some() {
            continue;
        }
        // The donor's texture is in the donor's local space; the child's in its own.
        let mut moved = Texture::clone(&texture);
        moved.transform(&donor_placement.then(&child.transform().inverse()));
        child.texture = Some(Arc::new(moved));
    }
}

pub(crate) fn apply_transform(object: &mut Object, t: &Transform) {
    object.transform_by(t);
}

/// A POV-Ray `matrix < .. 12 values .. >` as a transform.
pub(crate) fn matrix_transform(values: &[f64; 12]) -> Option<Transform> {
    let v = values;
    let m = DMat3::from_cols(
        DVec3::new(v[0], v[1], v[2]),
        DVec3::new(v[3], v[4], v[5]),
        DVec3::new(v[6], v[7], v[8]),
    );
    Transform::from_affine(DAffine3::from_mat3_translation(
        m,
        DVec3::new(v[9], v[10], v[11]),
    ))
}

/// After an object's own `uv_mapping`, a texture, pigment or normal given to the object is
/// evaluated at the surface's uv coordinates, as if it said `uv_mapping` itself.
fn uv_mapped_if(value: Value, uv_mapping: bool) -> Value {
    if !uv_mapping {
        return value;
    }
    match value {
        Value::Texture(texture) => {
            let mut texture = Arc::unwrap_or_clone(texture);
            super::appearance::map_texture_by_uv(&mut texture);
            Value::Texture(Arc::new(texture))
        }
        Value::Pigment(pigment) if pigment.uv_mapped().is_none() => Value::Pigment(Rc::new(
            crate::texture::Pigment::UvMapped(Box::new(Rc::unwrap_or_clone(pigment))),
        )),
        Value::Normal(normal) => {
            let mut normal = Rc::unwrap_or_clone(normal);
            normal.uv_mapped = true;
            Value::Normal(Rc::new(normal))
        }
        other => other,
    }
}

/// The number of nodes of an object tree (children, `clipped_by` and `bounded_by`
/// included) and its depth, walked without recursion.
fn tree_measure(object: &Object) -> (u64, u64) {
    let mut size = 0u64;
    let mut deepest = 0u64;
    let mut pending = vec![(object, 1u64)];
    while let Some((node, depth)) = pending.pop() {
        size += 1;
        deepest = deepest.max(depth);
        if let Shape::Csg { children, .. } = &node.shape {
            pending.extend(children.iter().map(|c| (c, depth + 1)));
        }
        pending.extend(node.clipped_by.iter().map(|c| (c, depth + 1)));
        pending.extend(node.bounded_by.iter().map(|c| (c, depth + 1)));
    }
    (size, deepest)
}
