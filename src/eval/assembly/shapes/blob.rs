//! `blob { threshold t sphere { .. } cylinder { .. } component s, r, c .. }`.
//!
//! In: the item stream after the brace. Out: [`Shape::Blob`] with each component's own
//! transformations applied to it, and its own texture (if it has one) in the blob's space.
//! Holds: the stream is left at the blob's object modifiers.

use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{BlockHead, Item};
use crate::{
    math::{Colour, Transform},
    scene::{Blob, BlobComponent, BlobKind, Object, Shape},
    texture::{finish::Finish, Pigment, Texture},
};
use std::sync::Arc;

impl Evaluator {
    /// Reads the blob's threshold and components.
    pub(crate) fn eval_blob(&mut self, stream: &mut Stream) -> EvalResult<Shape> {
        let mut blob = Blob {
            threshold: 1.0,
            components: Vec::new(),
        };
        let mut shared = SharedTextures::default();
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, _) if &**word == "threshold" => {
                    blob.threshold = self.expect_float(stream, "the threshold")?;
                }
                Item::Keyword(word, _) if &**word == "component" => {
                    let strength = self.expect_float(stream, "the strength")?;
                    let radius = self.expect_float(stream, "the radius")?;
                    let centre = self.expect_vector(stream, "the centre")?;
                    blob.components.push(BlobComponent {
                        kind: BlobKind::Sphere { centre },
                        radius,
                        strength,
                        transform: Transform::IDENTITY,
                        texture: None,
                    });
                }
                Item::Comma(_) => {}
                Item::Block(block) if matches!(&block.head, BlockHead::Word(w) if &**w == "sphere" || &**w == "cylinder") =>
                {
                    let is_sphere = matches!(&block.head, BlockHead::Word(w) if &**w == "sphere");
                    let mut body = Stream::new(block.body.clone());
                    let kind = if is_sphere {
                        BlobKind::Sphere {
                            centre: self.expect_vector(&mut body, "the centre")?,
                        }
                    } else {
                        let end1 = self.expect_vector(&mut body, "the first end")?;
                        let end2 = self.expect_vector(&mut body, "the second end")?;
                        BlobKind::Cylinder { end1, end2 }
                    };
                    let radius = self.expect_float(&mut body, "the radius")?;
                    self.skip_comma(&mut body)?;
                    if let Some(next) = self.next_item(&mut body)? {
                        match next {
                            Item::Keyword(word, _) if &*word == "strength" => {}
                            other => body.push_back(other),
                        }
                    }
                    let strength = self.expect_float(&mut body, "the strength")?;
                    let (transform, texture) = self.blob_component_modifiers(&mut body)?;
                    let texture = texture.map(|texture| shared.share(texture));
                    blob.components.push(BlobComponent {
                        kind,
                        radius,
                        strength,
                        transform,
                        texture,
                    });
                }
                _ => {
                    stream.push_back(item);
                    break;
                }
            }
        }
        Ok(Shape::Blob(Arc::new(blob)))
    }

    /// The modifiers of a `sphere { .. }` or `cylinder { .. }` component after its strength:
    /// transformations and its own `texture`, `pigment`, `normal` or `finish`,
    /// read as for an object (a texture given after a transformation is not moved by it; a
    /// second texture is layered on the first; a lone `pigment` starts from the default
    /// texture, not the blob's). Returns the component's transform and its texture in the
    /// blob's space.
    fn blob_component_modifiers(
        &mut self,
        body: &mut Stream,
    ) -> EvalResult<(Transform, Option<Texture>)> {
        // The component read as a stand-in object: its placement and texture.
        let mut part = Object::new(Shape::Sphere {
            centre: glam::DVec3::ZERO,
            radius: 1.0,
        });
        let mut uv_mapping = false;
        while let Some(modifier) = self.next_item(body)? {
            match &modifier {
                Item::Comma(_) => {}
                // Transformations and a finish apply as they do to an object.
                _ if is_transform_or_finish(&modifier) => {
                    self.object_modifier(
                        &mut part,
                        modifier,
                        body,
                        "blob component",
                        &mut uv_mapping,
                    )?;
                }
                Item::Block(_) | Item::Expr(_) => {
                    let value = self.item_value(&modifier)?;
                    match value {
                        Value::Texture(_)
                        | Value::Pigment(_)
                        | Value::Normal(_)
                        | Value::Finish(_)
                        | Value::Transform(_) => {
                            self.object_modifier_value(&mut part, value, modifier.span())?
                        }
                        _ => return Err(self.unexpected_in(&modifier, "blob component")),
                    }
                }
                _ => return Err(self.unexpected_in(&modifier, "blob component")),
            }
        }
        let transform = *part.transform();
        let texture = part.texture.map(|local| {
            let mut texture = Arc::unwrap_or_clone(local);
            texture.transform(&transform);
            texture
        });
        Ok((transform, texture))
    }
}

/// The component textures of one blob, so that components showing the same plain texture
/// (one colour, one finish: transformations cannot change it) share one: their colours then
/// blend once, not once per component.
#[derive(Default)]
struct SharedTextures {
    plain: Vec<(Colour, *const Finish, Arc<Texture>)>,
}

impl SharedTextures {
    /// `texture`, or an equal plain texture met before.
    fn share(&mut self, texture: Texture) -> Arc<Texture> {
        let Pigment::Solid(colour) = texture.pigment else {
            return Arc::new(texture);
        };
        if texture.depends_on_position() {
            return Arc::new(texture);
        }
        let finish = Arc::as_ptr(&texture.finish);
        if let Some((_, _, found)) = self
            .plain
            .iter()
            .find(|(c, f, _)| *c == colour && *f == finish)
        {
            return Arc::clone(found);
        }
        let texture = Arc::new(texture);
        self.plain.push((colour, finish, Arc::clone(&texture)));
        texture
    }
}

/// Whether a blob component's item is a transformation keyword or a `finish` block.
fn is_transform_or_finish(item: &Item) -> bool {
    match item {
        Item::Keyword(word, _) => matches!(
            &**word,
            "translate" | "rotate" | "scale" | "matrix" | "transform"
        ),
        Item::Block(block) => matches!(&block.head, BlockHead::Word(w) if &**w == "finish"),
        _ => false,
    }
}
