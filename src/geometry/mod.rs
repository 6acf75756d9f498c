//! Render-time geometry: shapes prepared for ray intersection, CSG, and the World of objects.
//!
//! In: a [`Scene`](crate::scene::Scene)'s object tree. Out: a [`World`] answering "what does
//! this ray hit first" with a world-space [`SurfaceHit`] (distance, point, outward unit normal,
//! material index), plus the table of [`Material`]s the hits refer to.
//! Holds: the world is immutable after [`World::build`] and can be shared between threads;
//! normals are the surface's outward normals (flipped for inverted objects and subtracted
//! surfaces) and are never turned towards the ray; pattern transforms inside materials map
//! pattern space to world space.

mod blob;
mod build;
mod csg;
mod cuboid;
mod extrusion;
mod flat;
mod height_field;
mod instance;
mod isosurface;
mod julia;
mod julia_algebra;
mod lathe;
mod leaf;
mod parametric;
mod poly;
mod polygon;
mod quadric;
mod quadric_bounds;
mod roots;
mod round;
mod sor;
mod sphere_sweep;
mod spindle;
mod superellipsoid;
mod torus;
mod uv;
mod world;

#[cfg(test)]
mod test_support;
#[cfg(test)]
mod tests;

pub use roots::MAX_ROOTS as MAX_CROSSINGS;
pub use spindle::lemon_smallest_inner_radius;
pub use world::{ShadowQuery, World};

use crate::{scene::Interior, texture::Texture};
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// A ray: a start point and a (unit length) direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts.
    pub origin: DVec3,
    /// Which way it goes; unit length, so distances along it are world units.
    pub direction: DVec3,
}

impl Ray {
    /// A ray from `origin` along `direction` (the caller normalises `direction`).
    pub fn new(origin: DVec3, direction: DVec3) -> Ray {
        Ray { origin, direction }
    }

    /// The point at ray parameter `distance`.
    #[inline]
    pub fn at(&self, distance: f64) -> DVec3 {
        self.origin + self.direction * distance
    }
}

/// Where a ray meets a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit {
    /// Distance along the ray (world units, since the direction is unit length).
    pub distance: f64,
    /// The hit point in world space.
    pub point: DVec3,
    /// The surface's outward unit normal in world space: for an inverted object or a surface
    /// of a subtracted child it points out of the resulting solid. Not turned towards the ray.
    pub normal: DVec3,
    /// Index into [`World::materials`].
    pub material: u32,
    /// The surface's uv coordinates at the point, for materials that use `uv_mapping` (the
    /// world point's x and y on shapes without uv coordinates, as POV-Ray); `None` otherwise.
    pub uv: Option<DVec2>,
    /// Several textures blended at the point (a mesh triangle whose corners have different
    /// textures, a blob whose components have their own): each is shaded on its own and the
    /// results are summed by weight. `material` stays the object's identity for its interior.
    pub blend: Option<TextureBlend>,
}

/// The most textures a [`TextureBlend`] holds: a blob point where more component textures
/// meet keeps the heaviest ones.
pub const BLEND_SLOTS: usize = 6;

/// Textures blended at a hit point: materials and their weights (which sum to 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextureBlend {
    materials: [u32; BLEND_SLOTS],
    weights: [f64; BLEND_SLOTS],
    len: u8,
}

impl TextureBlend {
    /// The corner textures of a triangle at barycentric `weights`.
    pub fn corners(materials: [u32; 3], weights: [f64; 3]) -> TextureBlend {
        let mut blend = TextureBlend {
            materials: [0; BLEND_SLOTS],
            weights: [0.0; BLEND_SLOTS],
            len: 3,
        };
        blend.materials[..3].copy_from_slice(&materials);
        blend.weights[..3].copy_from_slice(&weights);
        blend
    }

    /// A blend of `entries` (material, weight ≥ 0) in the given order: entries of one
    /// material merge; beyond [`BLEND_SLOTS`] materials only the heaviest are kept (the
    /// first of equal ones); the weights are scaled to sum to 1. `None` when no weight is
    /// positive.
    pub fn weighted(entries: impl IntoIterator<Item = (u32, f64)>) -> Option<TextureBlend> {
        let mut merged: Vec<(u32, f64)> = Vec::new();
        for (material, weight) in entries {
            if !(weight > 0.0 && weight.is_finite()) {
                continue;
            }
            match merged.iter_mut().find(|(m, _)| *m == material) {
                Some(entry) => entry.1 += weight,
                None => merged.push((material, weight)),
            }
        }
        if merged.len() > BLEND_SLOTS {
            merged.sort_by(|a, b| b.1.total_cmp(&a.1));
            merged.truncate(BLEND_SLOTS);
        }
        let total: f64 = merged.iter().map(|(_, weight)| weight).sum();
        if !total.is_finite() || total <= 0.0 {
            return None;
        }
        let mut blend = TextureBlend {
            materials: [0; BLEND_SLOTS],
            weights: [0.0; BLEND_SLOTS],
            len: merged.len() as u8,
        };
        for (slot, (material, weight)) in merged.into_iter().enumerate() {
            blend.materials[slot] = material;
            blend.weights[slot] = weight / total;
        }
        Some(blend)
    }

    /// The materials and their weights.
    pub fn iter(&self) -> impl Iterator<Item = (u32, f64)> + '_ {
        let len = self.len as usize;
        self.materials[..len]
            .iter()
            .copied()
            .zip(self.weights[..len].iter().copied())
    }

    /// The first material of the blend.
    pub fn first(&self) -> u32 {
        self.materials[0]
    }
}

/// What a hit adds to its distance and point: the normal and the surface's appearance there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitDetails {
    /// The unit outward world normal.
    pub normal: DVec3,
    /// The material at the point (the first corner's when a triangle's corners differ).
    pub material: u32,
    /// The uv coordinates (`None` when no material uses them).
    pub uv: Option<DVec2>,
    /// The textures blended at the point, when there are several.
    pub blend: Option<TextureBlend>,
}

impl HitDetails {
    /// A hit with one material and no uv coordinates.
    pub fn plain(normal: DVec3, material: u32) -> HitDetails {
        HitDetails {
            normal,
            material,
            uv: None,
            blend: None,
        }
    }

    /// A hit on a triangle whose corners have `materials`, at barycentric `weights`.
    pub fn blended(
        normal: DVec3,
        materials: [u32; 3],
        weights: [f64; 3],
        uv: Option<DVec2>,
    ) -> HitDetails {
        let differ = materials[0] != materials[1] || materials[0] != materials[2];
        HitDetails {
            normal,
            material: materials[0],
            uv,
            blend: differ.then(|| TextureBlend::corners(materials, weights)),
        }
    }
}

/// The appearance and interior shared by the leaves that inherit them from one object.
#[derive(Clone, Debug)]
pub struct Material {
    /// The texture, with every pattern transform mapping pattern space to world space.
    pub texture: Arc<Texture>,
    /// The texture of the inside faces (`interior_texture`), world space like `texture`;
    /// `None` when they show `texture`.
    pub interior_texture: Option<Arc<Texture>>,
    /// What is inside the object (shared by every material with the same interior).
    pub interior: Arc<Interior>,
    /// The object casts no shadow.
    pub no_shadow: bool,
    /// `no_image`: camera rays pass through.
    pub no_image: bool,
    /// `no_reflection`: reflected rays pass through.
    pub no_reflection: bool,
    /// `no_radiosity`: radiosity's gathering rays pass through.
    pub no_radiosity: bool,
    /// `double_illuminate`: lit from both sides.
    pub double_illuminate: bool,
    /// `hollow`: atmospheric media and fog fill the object's inside.
    pub hollow: bool,
    /// The texture evaluates a pigment at uv coordinates (`uv_mapping`), so hits need them.
    pub uses_uv: bool,
    /// The `light_group` the material's object sits in (its lights and `global_lights`).
    pub light_group: Option<crate::scene::LightGroup>,
    /// The object's `photons` block (inherited from its CSG parents).
    pub photons: crate::scene::ObjectPhotons,
}

impl Material {
    /// The texture seen by a ray going along `direction` that hits a surface with outward
    /// `normal`: the `interior_texture` when the ray leaves the object (or meets the back of
    /// a patch), else `texture`.
    pub fn texture_facing(&self, direction: DVec3, normal: DVec3) -> &Arc<Texture> {
        match &self.interior_texture {
            Some(inside) if direction.dot(normal) > 0.0 => inside,
            _ => &self.texture,
        }
    }
}
