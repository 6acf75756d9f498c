//! Triangle meshes as the scene holds them: shared vertex lists and faces indexing them.
//!
//! In: nothing (data definitions). Out: [`Mesh`] and the per-triangle view [`MeshTriangle`].
//! Holds: every index is in range of its list (the evaluator checks); the optional per-face
//! lists (`face_normals`, `face_uvs`, `face_textures`) are either empty or hold one entry per
//! face, so a mesh without normals, uv coordinates or textures costs nothing for them.

use crate::texture::Texture;
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// In `face_normals`, the index that marks a flat face (no normals to interpolate).
pub const FLAT_FACE: u32 = u32::MAX;

/// The uv coordinates POV-Ray gives the corners of a mesh triangle without `uv_vectors`
/// (measured: a uv-mapped pattern shows its value at the origin all over such a triangle).
pub const DEFAULT_TRIANGLE_UVS: [DVec2; 3] = [DVec2::ZERO; 3];

/// The triangles of a `mesh` or `mesh2`, or of a triangulated `bicubic_patch`.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    /// Corner positions.
    pub vertices: Vec<DVec3>,
    /// Normals that smooth faces interpolate.
    pub normals: Vec<DVec3>,
    /// uv coordinates of the corners (`uv_vectors`).
    pub uvs: Vec<DVec2>,
    /// Each face's three indices into `vertices`, in the order written.
    pub faces: Vec<[u32; 3]>,
    /// Empty, or for each face its indices into `normals` ([`FLAT_FACE`] for a flat face).
    pub face_normals: Vec<[u32; 3]>,
    /// Empty, or for each face its indices into `uvs`.
    pub face_uvs: Vec<[u32; 3]>,
    /// Empty, or for each face the texture slot of each corner: 0 is the texture of the mesh
    /// object itself, `k` is `textures[k - 1]`. A face whose corners name different slots
    /// blends the textures by the hit's barycentric weights.
    pub face_textures: Vec<[u32; 3]>,
    /// Textures given to single triangles or listed in a `texture_list`, in the mesh's space.
    pub textures: Vec<Arc<Texture>>,
    /// `inside_vector`: when given, the mesh is a solid (points are inside when a ray along
    /// this vector crosses the surface an odd number of times).
    pub inside_vector: Option<DVec3>,
    /// Set for a triangulated `bicubic_patch`: POV-Ray never tests its hits against its
    /// `clipped_by` objects; only their box bounds it (measured with `trace`).
    pub ignores_clipped_by: bool,
}

/// One triangle of a mesh, by value.
#[derive(Clone, Copy, Debug)]
pub struct MeshTriangle {
    /// The three corners.
    pub corners: [DVec3; 3],
    /// Normals at the corners for a smooth triangle; `None` for a flat one.
    pub normals: Option<[DVec3; 3]>,
}

impl Mesh {
    /// A mesh of separate triangles, without uv coordinates or textures.
    pub fn from_triangles(triangles: &[MeshTriangle]) -> Mesh {
        let mut mesh = Mesh::default();
        let smooth = triangles.iter().any(|t| t.normals.is_some());
        for triangle in triangles {
            let first = mesh.vertices.len() as u32;
            mesh.vertices.extend(triangle.corners);
            mesh.faces.push([first, first + 1, first + 2]);
            if smooth {
                mesh.face_normals.push(match triangle.normals {
                    Some(normals) => {
                        let first = mesh.normals.len() as u32;
                        mesh.normals.extend(normals);
                        [first, first + 1, first + 2]
                    }
                    None => [FLAT_FACE; 3],
                });
            }
        }
        mesh
    }

    /// Number of faces.
    pub fn len(&self) -> usize {
        self.faces.len()
    }

    /// True for a mesh without faces.
    pub fn is_empty(&self) -> bool {
        self.faces.is_empty()
    }

    /// The face at `index` (which must be below [`Mesh::len`]) as a triangle.
    pub fn triangle(&self, index: usize) -> MeshTriangle {
        let corners = self.faces[index].map(|at| self.vertices[at as usize]);
        let normals = self
            .face_normals
            .get(index)
            .filter(|indices| indices[0] != FLAT_FACE)
            .map(|indices| indices.map(|at| self.normals[at as usize]));
        MeshTriangle { corners, normals }
    }

    /// Every face as a triangle, in order.
    pub fn triangles(&self) -> impl Iterator<Item = MeshTriangle> + '_ {
        (0..self.len()).map(|index| self.triangle(index))
    }

    /// The uv coordinates of the corners of face `index`; [`DEFAULT_TRIANGLE_UVS`] when the
    /// mesh has none.
    pub fn corner_uvs(&self, index: usize) -> [DVec2; 3] {
        match self.face_uvs.get(index) {
            Some(indices) => indices.map(|at| self.uvs[at as usize]),
            None => DEFAULT_TRIANGLE_UVS,
        }
    }

    /// The texture slots of the corners of face `index` (all 0 when the mesh has none).
    pub fn corner_textures(&self, index: usize) -> [u32; 3] {
        self.face_textures.get(index).copied().unwrap_or([0; 3])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn separate_triangles_keep_their_normals() {
        let flat = MeshTriangle {
            corners: [DVec3::ZERO, DVec3::X, DVec3::Y],
            normals: None,
        };
        let smooth = MeshTriangle {
            corners: [DVec3::Z, DVec3::X, DVec3::Y],
            normals: Some([DVec3::Z; 3]),
        };
        let mesh = Mesh::from_triangles(&[flat, smooth]);
        assert_eq!(mesh.len(), 2);
        assert!(mesh.triangle(0).normals.is_none());
        assert_eq!(mesh.triangle(1).normals, Some([DVec3::Z; 3]));
        assert_eq!(mesh.triangle(1).corners[0], DVec3::Z);
        assert_eq!(mesh.corner_uvs(0), DEFAULT_TRIANGLE_UVS);
        assert_eq!(mesh.corner_textures(1), [0; 3]);
    }
}
