//! Shared mesh geometry: a mesh's triangles prepared once, with their own BVH, and placed in
//! the world any number of times through instances that hold only a transform and materials.
//!
//! In: a scene [`Mesh`] (shared by `Arc` between every `object { Ident }` copy). Out:
//! [`MeshGeometry`] (the vertices and each triangle's vertex indices in the mesh's local
//! space, plus a BVH over the triangles) and [`MeshInstance`] (geometry, world-to-local map,
//! one material per texture slot) answering nearest hits, normals and, for meshes with
//! textured triangles or uv coordinates, which material and uv a hit has.
//! Holds: a triangle costs 12 bytes plus its share of the BVH (normals, uv coordinates and
//! texture slots only for meshes that have them); ray parameters are the same in both
//! spaces (the map is affine and the direction is mapped without normalising), so limits pass
//! through unchanged; queries never allocate.

use super::flat::triangle_crossing;
use super::polygon::interpolated_normal;
use super::uv::{barycentric, corner_weighted};
use super::{HitDetails, Ray};
use crate::accel::{Aabb, Bvh};
use crate::{
    math::Transform,
    scene::{Mesh, DEFAULT_TRIANGLE_UVS, FLAT_FACE},
};
use glam::{DAffine3, DVec2, DVec3};
use std::sync::Arc;

/// Crossings closer than this to the start of an inside ray do not count.
const INSIDE_EPSILON: f64 = 1e-9;

/// A mesh's triangles in its local space, behind their own BVH.
#[derive(Debug)]
pub struct MeshGeometry {
    /// Corner positions shared by the triangles.
    vertices: Vec<DVec3>,
    /// Each triangle's indices into `vertices`, in BVH order.
    triangles: Vec<[u32; 3]>,
    bvh: Bvh,
    /// Unit normals the smooth triangles interpolate.
    normals: Vec<DVec3>,
    /// Empty, or for each triangle its indices into `normals` ([`FLAT_FACE`] when flat).
    smooth: Vec<[u32; 3]>,
    /// `inside_vector`, when the mesh is a solid.
    inside_vector: Option<DVec3>,
    /// Empty, or for each triangle the uv coordinates of its corners (`uv_vectors`).
    corner_uvs: Vec<[[f32; 2]; 3]>,
    /// Empty, or for each triangle the texture slots of its corners (0: the object's texture).
    corner_slots: Vec<[u32; 3]>,
}

impl MeshGeometry {
    /// Prepares the triangles of `mesh`; degenerate ones (corners in a line, not finite) are
    /// dropped.
    pub fn new(mesh: &Mesh) -> MeshGeometry {
        let vertices = mesh.vertices.clone();
        let mut kept = Vec::with_capacity(mesh.len());
        let mut bounds = Vec::with_capacity(mesh.len());
        for (face, indices) in mesh.faces.iter().enumerate() {
            let corners = indices.map(|index| vertices[index as usize]);
            let [a, b, c] = corners;
            let area = (b - a).cross(c - a).length_squared();
            if area > 0.0 && area.is_finite() && a.is_finite() {
                kept.push(face as u32);
                bounds.push(Aabb::from_points(corners).padded(1e-9, 1e-12));
            }
        }
        let (bvh, order) = Bvh::build(&bounds);
        drop(bounds);
        let faces: Vec<usize> = order.iter().map(|&at| kept[at as usize] as usize).collect();
        drop(kept);
        let triangles = faces.iter().map(|&face| mesh.faces[face]).collect();
        let smooth = if mesh.face_normals.is_empty() {
            Vec::new()
        } else {
            faces.iter().map(|&face| mesh.face_normals[face]).collect()
        };
        let normals = mesh
            .normals
            .iter()
            .map(|normal| normal.try_normalize().unwrap_or(DVec3::ZERO))
            .collect();
        let corner_uvs = if mesh.face_uvs.is_empty() {
            Vec::new()
        } else {
            faces
                .iter()
                .map(|&face| mesh.corner_uvs(face).map(|uv| [uv.x as f32, uv.y as f32]))
                .collect()
        };
        let corner_slots = if mesh.face_textures.is_empty() {
            Vec::new()
        } else {
            faces
                .iter()
                .map(|&face| mesh.corner_textures(face))
                .collect()
        };
        MeshGeometry {
            vertices,
            triangles,
            bvh,
            normals,
            smooth,
            inside_vector: mesh.inside_vector.and_then(DVec3::try_normalize),
            corner_uvs,
            corner_slots,
        }
    }

    /// Number of triangles kept.
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Local bounds of all triangles; `None` for an empty mesh.
    pub fn bounds(&self) -> Option<Aabb> {
        self.bvh.bounds()
    }

    /// The corners of triangle `index`.
    #[inline]
    fn corners(&self, index: usize) -> [DVec3; 3] {
        self.triangles[index].map(|at| self.vertices[at as usize])
    }

    /// Where the local line crosses triangle `index`, if it does.
    #[inline]
    fn crossing(&self, index: usize, origin: DVec3, direction: DVec3) -> Option<f64> {
        let [a, b, c] = self.corners(index);
        triangle_crossing(a, b - a, c - a, origin, direction)
    }

    /// True when triangle `index` interpolates corner normals.
    fn is_smooth(&self, index: usize) -> bool {
        self.smooth
            .get(index)
            .is_some_and(|indices| indices[0] != FLAT_FACE)
    }

    /// The local normal (any length) of triangle `index` with `corners` at the point with
    /// barycentric `weights`: interpolated for a smooth triangle (a zero corner normal stands
    /// for the flat one).
    fn normal(&self, index: usize, corners: [DVec3; 3], weights: [f64; 3]) -> DVec3 {
        let [a, b, c] = corners;
        // POV-Ray's orientation, as for a plain triangle.
        let flat = (c - a).cross(b - a);
        match self.smooth.get(index) {
            Some(indices) if indices[0] != FLAT_FACE => {
                let unit_flat = flat.normalize_or_zero();
                let normals = indices.map(|at| {
                    let normal = self.normals[at as usize];
                    if normal == DVec3::ZERO {
                        unit_flat
                    } else {
                        normal
                    }
                });
                interpolated_normal(normals, weights, flat)
            }
            _ => flat,
        }
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

    /// The unit outward world normal, material, uv coordinates and corner blend at the
    /// world `point` on triangle `triangle` (as [`MeshInstance::nearest`] returned it): the
    /// point is mapped and the barycentric weights computed once, and only when needed.
    pub fn hit_details(&self, triangle: u32, point: DVec3) -> HitDetails {
        let geometry = &*self.geometry;
        let index = triangle as usize;
        if index >= geometry.len() {
            return HitDetails::plain(DVec3::Z, self.materials[0]);
        }
        let corners = geometry.corners(index);
        let needs_weights =
            self.needs_uv || !geometry.corner_slots.is_empty() || geometry.is_smooth(index);
        let weights = if needs_weights {
            barycentric(corners, self.local_from_world.transform_point3(point))
        } else {
            [1.0, 0.0, 0.0]
        };
        let local_normal = geometry.normal(index, corners, weights);
        let normal = (self.local_from_world.matrix3.transpose() * local_normal)
            .try_normalize()
            .unwrap_or(DVec3::Z);
        let uv = self.needs_uv.then(|| {
            let corner_uvs = geometry
                .corner_uvs
                .get(index)
                .map_or(DEFAULT_TRIANGLE_UVS, |uvs| {
                    uvs.map(|[u, v]| DVec2::new(f64::from(u), f64::from(v)))
                });
            corner_weighted(corner_uvs, weights)
        });
        let slots = geometry.corner_slots.get(index).copied().unwrap_or([0; 3]);
        let materials = slots.map(|slot| {
            self.materials
                .get(slot as usize)
                .copied()
                .unwrap_or(self.materials[0])
        });
        HitDetails::blended(normal, materials, weights, uv)
    }

    /// True when the world `point` is inside the mesh: a mesh with an `inside_vector` is
    /// inside where a ray from the point along that vector crosses its triangles an odd
    /// number of times; other meshes have no inside.
    pub fn inside(&self, point: DVec3) -> bool {
        let Some(direction) = self.geometry.inside_vector else {
            return false;
        };
        let origin = self.local_from_world.transform_point3(point);
        let geometry = &*self.geometry;
        let mut odd = false;
        geometry
            .bvh
            .for_each_on_ray(origin, direction.recip(), 0.0, f64::INFINITY, |at| {
                if let Some(distance) = geometry.crossing(at, origin, direction) {
                    if distance > INSIDE_EPSILON {
                        odd = !odd;
                    }
                }
            });
        odd
    }

    /// The nearest triangle hit strictly between the limits: distance and triangle index.
    #[inline]
    pub fn nearest(&self, ray: &Ray, min_distance: f64, max_distance: f64) -> Option<(f64, u32)> {
        let origin = self.local_from_world.transform_point3(ray.origin);
        let direction = self.local_from_world.transform_vector3(ray.direction);
        let inverse_direction = DVec3::ONE / direction;
        let geometry = &*self.geometry;
        geometry.bvh.nearest_hit(
            origin,
            inverse_direction,
            min_distance,
            max_distance,
            |at, limit| {
                let distance = geometry.crossing(at, origin, direction)?;
                (distance > min_distance && distance < limit).then_some((distance, at as u32))
            },
        )
    }
}
