//! Bodies of `mesh` and `mesh2`: triangles with their normals, uv coordinates and textures.
//!
//! In: the block's item stream, positioned after the keyword's brace. Out: a
//! [`Shape::Mesh`] holding an indexed [`Mesh`], with the stream left at the object modifiers
//! that follow. Holds: every index stored is in range (bad ones end in spanned diagnostics);
//! per-face lists the mesh does not use stay empty; a texture named by identifier in several
//! triangles is stored once.

use super::{block_word, LIST_LIMIT};
use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Block, Item};
use crate::{
    scene::{Mesh, Shape, DEFAULT_TRIANGLE_UVS, FLAT_FACE},
    texture::Texture,
};
use glam::{DVec2, DVec3};
use std::collections::HashMap;
use std::sync::Arc;

/// Bytes one `triangle` of a `mesh` holds: its three vertices and its vertex, normal, uv
/// and texture indices (counted against the `geometry-memory` limit).
const TRIANGLE_BYTES: u64 =
    (3 * std::mem::size_of::<DVec3>() + 4 * std::mem::size_of::<[u32; 3]>()) as u64;

/// One entry of `face_indices`: the corners' vertex indices and the optional texture indices
/// (one for the whole face, or one per corner).
struct FaceEntry {
    vertices: [f64; 3],
    textures: Option<[f64; 3]>,
    span: Span,
}

/// Textures collected while reading a `mesh`, each stored once.
#[derive(Default)]
struct TextureSlots {
    textures: Vec<Arc<Texture>>,
    slot_of: HashMap<usize, u32>,
}

impl TextureSlots {
    /// The slot of `texture` (1 for the first texture stored), storing it on first use.
    fn slot(&mut self, texture: Arc<Texture>) -> u32 {
        let key = Arc::as_ptr(&texture) as usize;
        if let Some(&slot) = self.slot_of.get(&key) {
            return slot;
        }
        self.textures.push(texture);
        let slot = self.textures.len() as u32;
        self.slot_of.insert(key, slot);
        slot
    }
}

impl Evaluator {
    /// `mesh { triangle { .. } smooth_triangle { .. } .. }`; modifiers follow.
    pub(crate) fn eval_mesh(&mut self, stream: &mut Stream) -> EvalResult<Shape> {
        let mut mesh = Mesh::default();
        let mut slots = TextureSlots::default();
        // Per-face data, filled in once the first face needs it.
        let mut any_smooth = false;
        let mut any_uv = false;
        let mut any_texture = false;
        while let Some(item) = self.next_item(stream)? {
            let Item::Block(block) = &item else {
                stream.push_back(item);
                break;
            };
            let head = block_word(block);
            if head != "triangle" && head != "smooth_triangle" {
                stream.push_back(item);
                break;
            }
            self.runtime.count_geometry(TRIANGLE_BYTES, block.span)?;
            let face = mesh.faces.len();
            let mut body = Stream::new(block.body.clone());
            let mut corners = [DVec3::ZERO; 3];
            let mut normals = [DVec3::ZERO; 3];
            for index in 0..3 {
                corners[index] = self.expect_vector(&mut body, "a corner")?;
                if head == "smooth_triangle" {
                    normals[index] = self.expect_vector(&mut body, "the corner's normal")?;
                }
            }
            let first = mesh.vertices.len() as u32;
            mesh.vertices.extend(corners);
            mesh.faces.push([first, first + 1, first + 2]);
            if head == "smooth_triangle" {
                if !any_smooth {
                    any_smooth = true;
                    mesh.face_normals = vec![[FLAT_FACE; 3]; face];
                }
                let first = mesh.normals.len() as u32;
                mesh.normals.extend(normals);
                mesh.face_normals.push([first, first + 1, first + 2]);
            } else if any_smooth {
                mesh.face_normals.push([FLAT_FACE; 3]);
            }
            let mut uvs = None;
            let mut textures = None;
            while let Some(rest) = self.next_item(&mut body)? {
                match &rest {
                    Item::Comma(_) => {}
                    Item::Keyword(word, _) if &**word == "uv_vectors" => {
                        let mut corner_uvs = [DVec2::ZERO; 3];
                        for uv in &mut corner_uvs {
                            *uv = self.expect_uv(&mut body)?;
                        }
                        uvs = Some(corner_uvs);
                    }
                    Item::Block(inner) if block_word(inner) == "texture" => {
                        let slot = slots.slot(self.mesh_texture(inner)?);
                        textures = Some([slot; 3]);
                    }
                    Item::Block(inner) if block_word(inner) == "texture_list" => {
                        let mut list = Stream::new(inner.body.clone());
                        let mut corner_slots = [0; 3];
                        for slot in &mut corner_slots {
                            *slot = slots.slot(self.expect_texture(&mut list, inner.span)?);
                        }
                        self.expect_end(&mut list, "texture_list")?;
                        textures = Some(corner_slots);
                    }
                    _ => return Err(self.unexpected_in(&rest, head)),
                }
            }
            if let Some(corner_uvs) = uvs {
                if !any_uv {
                    // Triangles without uv_vectors take POV-Ray's default corners, stored first.
                    any_uv = true;
                    mesh.uvs.extend(DEFAULT_TRIANGLE_UVS);
                    mesh.face_uvs = vec![[0, 1, 2]; face];
                }
                let first = mesh.uvs.len() as u32;
                mesh.uvs.extend(corner_uvs);
                mesh.face_uvs.push([first, first + 1, first + 2]);
            } else if any_uv {
                mesh.face_uvs.push([0, 1, 2]);
            }
            if let Some(corner_slots) = textures {
                if !any_texture {
                    any_texture = true;
                    mesh.face_textures = vec![[0; 3]; face];
                }
                mesh.face_textures.push(corner_slots);
            } else if any_texture {
                mesh.face_textures.push([0; 3]);
            }
        }
        mesh.textures = slots.textures;
        Ok(Shape::Mesh(Arc::new(mesh)))
    }

    /// `mesh2 { vertex_vectors { .. } normal_vectors { .. } uv_vectors { .. }
    /// texture_list { .. } face_indices { .. } normal_indices { .. } uv_indices { .. } }`.
    pub(crate) fn eval_mesh2(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let mut mesh = Mesh::default();
        let mut faces: Vec<FaceEntry> = Vec::new();
        let mut normal_faces: Vec<([f64; 3], Span)> = Vec::new();
        let mut uv_faces: Vec<([f64; 3], Span)> = Vec::new();
        while let Some(item) = self.next_item(stream)? {
            let Item::Block(block) = &item else {
                stream.push_back(item);
                break;
            };
            let head = block_word(block);
            let mut body = Stream::new(block.body.clone());
            match head {
                "vertex_vectors" => mesh.vertices = self.vector_list(&mut body, block.span)?,
                "normal_vectors" => mesh.normals = self.vector_list(&mut body, block.span)?,
                "uv_vectors" => mesh.uvs = self.uv_list(&mut body, block.span)?,
                "texture_list" => mesh.textures = self.texture_list(&mut body, block.span)?,
                "face_indices" => faces = self.face_list(&mut body, block.span)?,
                "normal_indices" => normal_faces = self.index_list(&mut body, block.span)?,
                "uv_indices" => uv_faces = self.index_list(&mut body, block.span)?,
                _ => {
                    stream.push_back(item);
                    break;
                }
            }
        }
        mesh.faces.reserve_exact(faces.len());
        for face in &faces {
            let vertices =
                checked_indices(face.vertices, mesh.vertices.len()).ok_or_else(|| {
                    self.runtime
                        .error(face.span, "face index out of range")
                        .with_label(format!("there are {} vertices", mesh.vertices.len()))
                })?;
            mesh.faces.push(vertices);
        }
        if !mesh.normals.is_empty() {
            mesh.face_normals = self.corner_indices(
                &faces,
                &normal_faces,
                mesh.normals.len(),
                ("normal_indices", "normal", span),
            )?;
        }
        if !mesh.uvs.is_empty() {
            if uv_faces.is_empty() && mesh.uvs.len() != mesh.vertices.len() && !faces.is_empty() {
                return Err(self
                    .runtime
                    .error(span, "missing `uv_indices` in mesh2")
                    .with_label(format!(
                        "{} uv vectors for {} vertices: the face indices cannot pick them",
                        mesh.uvs.len(),
                        mesh.vertices.len()
                    ))
                    .into());
            }
            mesh.face_uvs = self.corner_indices(
                &faces,
                &uv_faces,
                mesh.uvs.len(),
                ("uv_indices", "uv", span),
            )?;
        }
        if faces.iter().any(|face| face.textures.is_some()) {
            let count = mesh.textures.len();
            let mut face_textures = Vec::with_capacity(faces.len());
            for face in &faces {
                let slots = match face.textures {
                    None => [0; 3],
                    Some(indices) => checked_indices(indices, count)
                        .ok_or_else(|| {
                            self.runtime
                                .error(face.span, "texture index out of range")
                                .with_label(format!("the texture_list has {count} textures"))
                        })?
                        .map(|index| index + 1),
                };
                face_textures.push(slots);
            }
            mesh.face_textures = face_textures;
        }
        Ok(Shape::Mesh(Arc::new(mesh)))
    }

    /// The indices into a mesh2's normals or uv coordinates for every face: from their own
    /// `*_indices` list, or else the face's vertex indices. `names` is (list name, what the
    /// indices pick, the mesh's span).
    fn corner_indices(
        &mut self,
        faces: &[FaceEntry],
        own: &[([f64; 3], Span)],
        count: usize,
        names: (&str, &str, Span),
    ) -> EvalResult<Vec<[u32; 3]>> {
        let (list, what, span) = names;
        let mut indices = Vec::with_capacity(faces.len());
        for (position, face) in faces.iter().enumerate() {
            let (wanted, at) = match own.get(position) {
                Some(&(wanted, at)) => (wanted, at),
                None if own.is_empty() => (face.vertices, face.span),
                None => {
                    return Err(self
                        .runtime
                        .error(span, format!("fewer {list} than face_indices"))
                        .into())
                }
            };
            let checked = checked_indices(wanted, count).ok_or_else(|| {
                self.runtime
                    .error(at, format!("{what} index out of range"))
                    .with_label(format!("there are {count} {what}s"))
            })?;
            indices.push(checked);
        }
        Ok(indices)
    }

    /// A texture given to a mesh triangle: `texture { Ident }` keeps the identifier's texture
    /// (so triangles naming the same one share it), anything else is evaluated afresh.
    fn mesh_texture(&mut self, block: &Block) -> EvalResult<Arc<Texture>> {
        let items: Vec<&Item> = block
            .body
            .iter()
            .filter(|item| !matches!(item, Item::Comma(_)))
            .collect();
        if let [item @ Item::Expr(_)] = items.as_slice() {
            if let Value::Texture(texture) = self.item_value(item)? {
                return Ok(texture);
            }
        }
        let mut body = Stream::new(block.body.clone());
        Ok(Arc::new(self.eval_texture(&mut body)?))
    }

    /// One texture of a `texture_list`: a `texture { .. }` block or a texture identifier.
    fn expect_texture(&mut self, stream: &mut Stream, span: Span) -> EvalResult<Arc<Texture>> {
        loop {
            let Some(item) = self.next_item(stream)? else {
                return Err(self
                    .runtime
                    .error(span, "expected a texture in the texture_list")
                    .into());
            };
            match &item {
                Item::Comma(_) => continue,
                Item::Block(block) if block_word(block) == "texture" => {
                    return self.mesh_texture(block)
                }
                _ => {}
            }
            let item_span = item.span();
            return match self.item_value(&item)? {
                Value::Texture(texture) => Ok(texture),
                other => Err(self
                    .runtime
                    .error(
                        item_span,
                        format!("expected a texture, found {}", other.type_name()),
                    )
                    .into()),
            };
        }
    }

    /// `n, texture { .. } ..` of a mesh2's `texture_list`.
    fn texture_list(&mut self, stream: &mut Stream, span: Span) -> EvalResult<Vec<Arc<Texture>>> {
        let count = self.expect_count(stream, "the number of textures", span)?;
        let mut textures = Vec::with_capacity(count.min(1 << 16));
        for _ in 0..count {
            textures.push(self.expect_texture(stream, span)?);
        }
        self.expect_end(stream, "texture_list")?;
        Ok(textures)
    }

    /// A uv vector `<u, v>` (a float stands for `<f, f>`).
    fn expect_uv(&mut self, stream: &mut Stream) -> EvalResult<DVec2> {
        let (value, span) = self.expect_value(stream, "a uv vector")?;
        match value {
            Value::Float(f) => Ok(DVec2::splat(f)),
            Value::Vector(v) => {
                let v = v.to_dvec3();
                Ok(DVec2::new(v.x, v.y))
            }
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected a uv vector, found {}", other.type_name()),
                )
                .into()),
        }
    }

    /// `n, <u, v> ..` of a mesh2's `uv_vectors`.
    fn uv_list(&mut self, stream: &mut Stream, span: Span) -> EvalResult<Vec<DVec2>> {
        let count = self.expect_count(stream, "the number of uv vectors", span)?;
        let mut list = Vec::with_capacity(count.min(1 << 20));
        for _ in 0..count {
            self.runtime
                .count_geometry(std::mem::size_of::<DVec2>() as u64, span)?;
            list.push(self.expect_uv(stream)?);
        }
        self.expect_end(stream, "uv_vectors")?;
        Ok(list)
    }

    /// `n, <a, b, c> [, i [, j, k]] ..` of `face_indices`: each face with its optional
    /// texture indices (one for the face, or one per corner).
    fn face_list(&mut self, stream: &mut Stream, span: Span) -> EvalResult<Vec<FaceEntry>> {
        let count = self.expect_count(stream, "the number of faces", span)?;
        let mut list: Vec<FaceEntry> = Vec::with_capacity(count.min(1 << 20));
        // Texture indices read after the current face.
        let mut pending: Vec<f64> = Vec::new();
        let finish_face = |this: &mut Self,
                           list: &mut Vec<FaceEntry>,
                           pending: &mut Vec<f64>|
         -> EvalResult<()> {
            let Some(face) = list.last_mut() else {
                return Ok(());
            };
            face.textures = match pending.as_slice() {
                [] => None,
                [one] => Some([*one; 3]),
                [a, b, c] => Some([*a, *b, *c]),
                _ => {
                    return Err(this
                        .runtime
                        .error(
                            face.span,
                            format!(
                                "a face takes 1 or 3 texture indices, found {}",
                                pending.len()
                            ),
                        )
                        .into())
                }
            };
            pending.clear();
            Ok(())
        };
        while let Some(item) = self.next_item(stream)? {
            if matches!(item, Item::Comma(_)) {
                continue;
            }
            let item_span = item.span();
            match self.item_value(&item)? {
                Value::Vector(v) => {
                    finish_face(self, &mut list, &mut pending)?;
                    self.runtime
                        .count_geometry(std::mem::size_of::<FaceEntry>() as u64, item_span)?;
                    let c = v.to_dvec3();
                    list.push(FaceEntry {
                        vertices: [c.x, c.y, c.z],
                        textures: None,
                        span: item_span,
                    });
                }
                Value::Float(index) if !list.is_empty() => pending.push(index),
                other => {
                    return Err(self
                        .runtime
                        .error(
                            item_span,
                            format!("expected an index vector, found {}", other.type_name()),
                        )
                        .into())
                }
            }
        }
        finish_face(self, &mut list, &mut pending)?;
        self.with_declared_count(list, count, span)
    }
}

/// `indices` as list positions when all are whole numbers below `count`.
fn checked_indices(indices: [f64; 3], count: usize) -> Option<[u32; 3]> {
    let check = |index: f64| -> Option<u32> {
        (index >= 0.0 && index.fract() == 0.0 && index < count as f64 && index < LIST_LIMIT as f64)
            .then_some(index as u32)
    };
    match indices.map(check) {
        [Some(a), Some(b), Some(c)] => Some([a, b, c]),
        _ => None,
    }
}
