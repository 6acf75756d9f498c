//! `blob { threshold t sphere { .. } cylinder { .. } component s, r, c .. }`.
//!
//! In: the item stream after the brace. Out: [`Shape::Blob`] with each component's own
//! transformations applied to it. Holds: component textures are not supported yet (warned
//! about once, ignored); the stream is left at the blob's object modifiers.

use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{BlockHead, Item};
use crate::{
    math::Transform,
    scene::{Blob, BlobComponent, BlobKind, Shape},
};
use std::sync::Arc;

impl Evaluator {
    /// Reads the blob's threshold and components.
    pub(crate) fn eval_blob(&mut self, stream: &mut Stream) -> EvalResult<Shape> {
        let mut blob = Blob {
            threshold: 1.0,
            components: Vec::new(),
        };
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
                    let mut transform = Transform::IDENTITY;
                    while let Some(modifier) = self.next_item(&mut body)? {
                        match &modifier {
                            Item::Keyword(word, span)
                                if matches!(
                                    &**word,
                                    "translate" | "rotate" | "scale" | "matrix" | "transform"
                                ) =>
                            {
                                let t = self.transform_keyword(word, *span, &mut body)?;
                                transform = transform.then(&t);
                            }
                            Item::Comma(_) => {}
                            Item::Block(_) | Item::Expr(_) => {
                                match self.item_value(&modifier)? {
                                    crate::eval::language::value::Value::Transform(t) => {
                                        transform = transform.then(&t)
                                    }
                                    _ => self.runtime.warn(
                                        modifier.span(),
                                        "textures of single blob components are not supported yet; they are ignored",
                                    ),
                                }
                            }
                            _ => return Err(self.unexpected_in(&modifier, "blob component")),
                        }
                    }
                    blob.components.push(BlobComponent {
                        kind,
                        radius,
                        strength,
                        transform,
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
}
