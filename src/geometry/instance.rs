//! Shared mesh geometry: a mesh's triangles prepared once, with their own BVH, and placed in
//! the world any number of times through instances that hold only a transform and a material.
//!
//! In: a scene [`Mesh`] (shared by `Arc` between every `object { Ident }` copy). Out:
//! [`MeshGeometry`] (triangle leaves in the mesh's local space plus a BVH over them) and
//! [`MeshInstance`] (geometry, world-to-local map, material) answering nearest hits.
//! Holds: ray parameters are the same in both spaces (the map is affine and the direction is
//! mapped without normalising), so limits pass through unchanged; queries never allocate.

use super::leaf::{Leaf, LocalShape};
use super::roots::Roots;
use super::Ray;
use crate::accel::{Aabb, Bvh};
use crate::scene::{Mesh, Transform};
use glam::{DAffine3, DVec3};
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
}

impl MeshGeometry {
    /// Prepares the triangles of `mesh` (degenerate ones are dropped).
    pub fn new(mesh: &Mesh) -> MeshGeometry {
        let mut leaves = Vec::new();
        let mut bounds = Vec::new();
        for triangle in &mesh.triangles {
            let local = LocalShape::from_mesh_triangle(triangle);
            let (leaf, leaf_bounds) = Leaf::from_local(local, &Transform::IDENTITY, 0, false);
            if let (false, Some(surface)) = (leaf.is_empty(), leaf_bounds.surface) {
                leaves.push(Some(leaf));
                bounds.push(surface.padded(1e-9, 1e-12));
            }
        }
        let (bvh, order) = Bvh::build(&bounds);
        let leaves = order
            .iter()
            .filter_map(|&index| leaves[index as usize].take())
            .collect();
        MeshGeometry {
            leaves,
            bvh,
            inside_vector: mesh.inside_vector.and_then(DVec3::try_normalize),
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
    material: u32,
}

impl MeshInstance {
    /// Places `geometry` through `world_from_local`; `None` when the map cannot be inverted
    /// or the mesh is empty. Returns the instance and its world bounds.
    pub fn new(
        geometry: Arc<MeshGeometry>,
        world_from_local: &Transform,
        material: u32,
    ) -> Option<(MeshInstance, Aabb)> {
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
                material,
            },
            bounds,
        ))
    }

    /// The instance's material index.
    pub fn material(&self) -> u32 {
        self.material
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
