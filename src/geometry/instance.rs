//! Shared mesh geometry: a mesh's triangles prepared once, with their own BVH, and placed in
//! the world any number of times through instances that hold only a transform and a material.
//!
//! In: a scene [`Mesh`] (shared by `Arc` between every `object { Ident }` copy). Out:
//! [`MeshGeometry`] (triangle leaves in the mesh's local space plus a BVH over them) and
//! [`MeshInstance`] (geometry, world-to-local map, one material per texture slot) answering
//! nearest hits and, for meshes with textured triangles or uv coordinates, which material
//! and uv a hit has.
//! Holds: ray parameters are the same in both spaces (the map is affine and the direction is
//! mapped without normalising), so limits pass through unchanged; queries never allocate.

use super::leaf::{Leaf, LocalShape};
use super::roots::Roots;
use super::uv::{barycentric, corner_weighted};
use super::{CornerBlend, Ray};
use crate::accel::{Aabb, Bvh};
use crate::scene::{Mesh, Transform, DEFAULT_TRIANGLE_UVS};
use glam::{DAffine3, DVec2, DVec3};
use std::sync::Arc;

/// Crossings closer than this to the start of an inside ray do not count.
const INSIDE_EPSILON: f64 = 1e-9;

/// A mesh's triangles in its local space, behind their own BVH.
#[derive(Debug)]
pub struct MeshGeometry {
    leaves: Vec<Leaf>,
    bvh: Bvh,
    /// `inside_vector`, when the mesh is a solid.
    inside_vector: Option<DVec3>,
    /// Empty, or for each leaf the uv coordinates of its corners (`uv_vectors`).
    corner_uvs: Vec<[[f32; 2]; 3]>,
    /// Empty, or for each leaf the texture slots of its corners (0 is the object's texture).
    corner_slots: Vec<[u32; 3]>,
}

/// What a hit on a mesh adds to the bare hit: uv coordinates and blended corner textures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshSurface {
    /// The uv coordinates at the point (`None` when no material uses them).
    pub uv: Option<DVec2>,
    /// The material at the point (the first corner's when the corners differ).
    pub material: u32,
    /// The corners' materials and weights, when they differ.
    pub corner_blend: Option<CornerBlend>,
}

impl MeshGeometry {
    /// Prepares the triangles of `mesh` (degenerate ones are dropped).
    pub fn new(mesh: &Mesh) -> MeshGeometry {
        let mut leaves = Vec::with_capacity(mesh.len());
        let mut faces = Vec::with_capacity(mesh.len());
        let mut bounds = Vec::with_capacity(mesh.len());
        for (face, triangle) in mesh.triangles().enumerate() {
            let local = LocalShape::from_mesh_triangle(&triangle);
            let (leaf, leaf_bounds) = Leaf::from_local(local, &Transform::IDENTITY, 0, false);
            if let (false, Some(surface)) = (leaf.is_empty(), leaf_bounds.surface) {
                leaves.push(Some(leaf));
                faces.push(face);
                bounds.push(surface.padded(1e-9, 1e-12));
            }
        }
        let (bvh, order) = Bvh::build(&bounds);
        drop(bounds);
        let ordered_faces = || order.iter().map(|&index| faces[index as usize]);
        let corner_uvs = if mesh.face_uvs.is_empty() {
            Vec::new()
        } else {
            ordered_faces()
                .map(|face| mesh.corner_uvs(face).map(|uv| [uv.x as f32, uv.y as f32]))
                .collect()
        };
        let corner_slots = if mesh.face_textures.is_empty() {
            Vec::new()
        } else {
            ordered_faces()
                .map(|face| mesh.corner_textures(face))
                .collect()
        };
        let leaves = order
            .iter()
            .filter_map(|&index| leaves[index as usize].take())
            .collect();
        MeshGeometry {
            leaves,
            bvh,
            inside_vector: mesh.inside_vector.and_then(DVec3::try_normalize),
            corner_uvs,
            corner_slots,
        }
    }

    /// Number of triangles kept.
    pub fn len(&self) -> usize {
        self.leaves.len()
    }

    /// Local bounds of all triangles; `None` for an empty mesh.
    pub fn bounds(&self) -> Option<Aabb> {
        self.bvh.bounds()
    }
}

/// One placement of a shared mesh.
#[derive(Clone, Debug)]
pub struct MeshInstance {
    geometry: Arc<MeshGeometry>,
    local_from_world: DAffine3,
    /// The material of each texture slot: first the object's own, then those of the mesh's
    /// triangle textures.
    materials: Box<[u32]>,
    /// Hits need uv coordinates (a material uses `uv_mapping`).
    needs_uv: bool,
}

impl MeshInstance {
    /// Places `geometry` through `world_from_local` with one material per texture slot
    /// (`materials[0]` is the object's); `None` when the map cannot be inverted, the mesh is
    /// empty or no material is given. Returns the instance and its world bounds.
    pub fn new(
        geometry: Arc<MeshGeometry>,
        world_from_local: &Transform,
        materials: Box<[u32]>,
        needs_uv: bool,
    ) -> Option<(MeshInstance, Aabb)> {
        if materials.is_empty() {
            return None;
        }
        let forward = world_from_local.outer_from_inner;
        let backward = world_from_local.inner_from_outer;
        let determinant = forward.matrix3.determinant();
        if !(forward.is_finite() && backward.is_finite() && determinant != 0.0) {
            return None;
        }
        let bounds = geometry.bounds()?.transformed(&forward);
        Some((
            MeshInstance {
                geometry,
                local_from_world: backward,
                materials,
                needs_uv,
            },
            bounds,
        ))
    }

    /// The material of the mesh object itself (every slot shares its object flags).
    pub fn material(&self) -> u32 {
        self.materials[0]
    }

    /// The material, uv coordinates and corner blend at the world `point` on `leaf` (one of
    /// this mesh's leaves, as [`MeshInstance::nearest`] returned it).
    pub fn surface(&self, leaf: &Leaf, point: DVec3) -> MeshSurface {
        let geometry = &*self.geometry;
        let plain = MeshSurface {
            uv: None,
            material: self.materials[0],
            corner_blend: None,
        };
        let has_slots = !geometry.corner_slots.is_empty();
        if !(has_slots || self.needs_uv) {
            return plain;
        }
        let Some(corners) = leaf.triangle_corners() else {
            return plain;
        };
        // The leaf's position in the geometry's own list (the caller got it from there).
        let index = (leaf as *const Leaf as usize).wrapping_sub(geometry.leaves.as_ptr() as usize)
            / std::mem::size_of::<Leaf>();
        let weights = barycentric(corners, self.local_from_world.transform_point3(point));
        let uv = if !self.needs_uv {
            None
        } else if let Some(uvs) = geometry.corner_uvs.get(index) {
            let corner_uvs = uvs.map(|[u, v]| DVec2::new(f64::from(u), f64::from(v)));
            Some(corner_weighted(corner_uvs, weights))
        } else {
            Some(corner_weighted(DEFAULT_TRIANGLE_UVS, weights))
        };
        let slots = geometry.corner_slots.get(index).copied().unwrap_or([0; 3]);
        let slot_material = |slot: u32| -> u32 {
            self.materials
                .get(slot as usize)
                .copied()
                .unwrap_or(self.materials[0])
        };
        let materials = slots.map(slot_material);
        let corner_blend = (materials[0] != materials[1] || materials[0] != materials[2])
            .then_some(CornerBlend { materials, weights });
        MeshSurface {
            uv,
            material: materials[0],
            corner_blend,
        }
    }

    /// True when the world `point` is inside the mesh: a mesh with an `inside_vector` is
    /// inside where a ray from the point along that vector crosses its triangles an odd
    /// number of times; other meshes have no inside.
    pub fn inside(&self, point: DVec3) -> bool {
        let Some(direction) = self.geometry.inside_vector else {
            return false;
        };
        let ray = Ray {
            origin: self.local_from_world.transform_point3(point),
            direction,
        };
        let mut odd = false;
        let leaves = &self.geometry.leaves;
        self.geometry.bvh.for_each_on_ray(
            ray.origin,
            direction.recip(),
            0.0,
            f64::INFINITY,
            |at| {
                let mut roots = Roots::new();
                leaves[at].intersect(&ray, &mut roots);
                for (distance, _) in roots.iter() {
                    if distance > INSIDE_EPSILON {
                        odd = !odd;
                    }
                }
            },
        );
        odd
    }

    /// The nearest triangle hit strictly between the limits: distance, leaf and part.
    #[inline]
    pub fn nearest(
        &self,
        ray: &Ray,
        min_distance: f64,
        max_distance: f64,
    ) -> Option<(f64, &Leaf, u8)> {
        let local = Ray {
            origin: self.local_from_world.transform_point3(ray.origin),
            direction: self.local_from_world.transform_vector3(ray.direction),
        };
        let inverse_direction = DVec3::ONE / local.direction;
        let leaves = &self.geometry.leaves;
        let (distance, (index, part)) = self.geometry.bvh.nearest_hit(
            local.origin,
            inverse_direction,
            min_distance,
            max_distance,
            |at, limit| {
                let (distance, part) = leaves[at].nearest(&local, min_distance, limit)?;
                Some((distance, (at, part)))
            },
        )?;
        Some((distance, &leaves[index], part))
    }

    /// The unit outward world normal at the world `point` on `leaf` (one of this mesh's).
    pub fn normal(&self, leaf: &Leaf, point: DVec3, part: u8) -> DVec3 {
        let local = self.local_from_world.transform_point3(point);
        let normal = self.local_from_world.matrix3.transpose() * leaf.normal(local, part);
        normal.try_normalize().unwrap_or(DVec3::Z)
    }
}
