//! Shape-level uv maths: the sphere's, box's and torus's uv coordinates as `uv_mapping` reads
//! them, the barycentric weights of points on triangles and the blend of corner uvs, and
//! whether a texture needs uv coordinates at all.
//!
//! In: a local point on a shape's surface (with the part tag the intersection gave, or the
//! shape's own numbers), a triangle's corners, a texture. Out: the point's `<u, v>` in
//! POV-Ray 3.7's parametrisation (measured by rendering uv-mapped gradients with `povray`),
//! barycentric weights, or a yes/no. Which shape uses which parametrisation is decided per
//! leaf in [`leaf`](super::leaf); lathe, sor, ovus and parametric surfaces compute theirs in
//! their own files (with [`sphere_uv`] for the angle around their axis).
//! Holds: pure functions, no allocation; nothing here knows the leaf types.

use crate::accel::Aabb;
use crate::texture::{
    BlendMap, CompoundTexture, Normal, NormalSource, Pigment, PigmentMap, Texture,
};
use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

/// Barycentric weights of `point` (on or near the triangle's plane) for the corners `a`, `b`,
/// `c`; they sum to 1. A degenerate triangle gives all weight to `a`.
pub fn barycentric(corners: [DVec3; 3], point: DVec3) -> [f64; 3] {
    let [a, b, c] = corners;
    let (edge_one, edge_two, offset) = (b - a, c - a, point - a);
    let (d00, d01, d11) = (
        edge_one.dot(edge_one),
        edge_one.dot(edge_two),
        edge_two.dot(edge_two),
    );
    let (d20, d21) = (offset.dot(edge_one), offset.dot(edge_two));
    let denominator = d00 * d11 - d01 * d01;
    if denominator == 0.0 || !denominator.is_finite() {
        return [1.0, 0.0, 0.0];
    }
    let second = (d11 * d20 - d01 * d21) / denominator;
    let third = (d00 * d21 - d01 * d20) / denominator;
    [1.0 - second - third, second, third]
}

/// The uv point blended from the corners' uv coordinates by barycentric `weights`.
pub fn corner_weighted(corner_uvs: [DVec2; 3], weights: [f64; 3]) -> DVec2 {
    corner_uvs[0] * weights[0] + corner_uvs[1] * weights[1] + corner_uvs[2] * weights[2]
}

/// A sphere's uv at `offset` from its centre: u the longitude from the +x axis turning
/// towards +z (0 to 1), v the latitude from the south pole (0) to the north pole (1).
pub fn sphere_uv(offset: DVec3) -> DVec2 {
    let length = offset.length();
    if length == 0.0 || !length.is_finite() {
        return DVec2::ZERO;
    }
    let u = turns(offset.z.atan2(offset.x));
    let v = 1.0 - (offset.y / length).clamp(-1.0, 1.0).acos() / PI;
    DVec2::new(u, v)
}

/// True when `texture` or a texture it is made of has a uv-mapped pigment (possibly nested
/// in pigment maps) or normal, so its hits need uv coordinates.
pub fn texture_uses_uv(texture: &Texture) -> bool {
    if pigment_uses_uv(&texture.pigment) || texture.normal.as_deref().is_some_and(normal_uses_uv) {
        return true;
    }
    let Some(compound) = &texture.compound else {
        return false;
    };
    match &**compound {
        CompoundTexture::Layered(layers) => layers.iter().any(texture_uses_uv),
        CompoundTexture::Pattern { map, .. } => match map {
            BlendMap::Entries(entries) => entries.iter().any(|(_, t)| texture_uses_uv(t)),
            BlendMap::Blocks(blocks) => blocks.iter().any(texture_uses_uv),
        },
        CompoundTexture::Average(entries) => entries.iter().any(|(_, t)| texture_uses_uv(t)),
        CompoundTexture::MaterialMap { textures, .. } => textures.iter().any(texture_uses_uv),
    }
}

/// True when `normal` is uv-mapped or holds a uv-mapped normal.
fn normal_uses_uv(normal: &Normal) -> bool {
    normal.uv_mapped
        || match &normal.source {
            NormalSource::Pattern { .. } | NormalSource::BumpMap(_) => false,
            NormalSource::Map { map, .. } => match map {
                BlendMap::Entries(entries) => entries.iter().any(|(_, n)| normal_uses_uv(n)),
                BlendMap::Blocks(blocks) => blocks.iter().any(normal_uses_uv),
            },
            NormalSource::Average(entries) => entries.iter().any(|(_, n)| normal_uses_uv(n)),
        }
}

/// True when `pigment` is uv-mapped or holds a uv-mapped pigment.
fn pigment_uses_uv(pigment: &Pigment) -> bool {
    match pigment {
        Pigment::UvMapped(_) => true,
        Pigment::Solid(_) | Pigment::Image { .. } => false,
        Pigment::Average { entries, .. } => entries.iter().any(|(_, p)| pigment_uses_uv(p)),
        Pigment::Pattern { map, .. } => match map {
            PigmentMap::Colours(_) => false,
            PigmentMap::Blocks(blocks) => blocks.iter().any(pigment_uses_uv),
            PigmentMap::Pigments(entries) => entries.iter().any(|(_, p)| pigment_uses_uv(p)),
        },
    }
}

/// A box's uv: the faces unfolded into a cross over the unit square, each face a quarter
/// wide and a third high (measured): the four sides -x, +z, +x, -z run along u at v from
/// 1/3 to 2/3; the bottom (-y) and top (+y) sit above and below the +z face.
pub fn box_uv(bounds: Aabb, point: DVec3, part: u8) -> DVec2 {
    let size = bounds.max - bounds.min;
    let unit = |axis: usize| -> f64 {
        if size[axis] > 0.0 {
            ((point[axis] - bounds.min[axis]) / size[axis]).clamp(0.0, 1.0)
        } else {
            0.0
        }
    };
    let (x, y, z) = (unit(0), unit(1), unit(2));
    let (column, row, across, up) = match part {
        0 => (0.0, 1.0, z, y),
        1 => (2.0, 1.0, 1.0 - z, y),
        2 => (1.0, 0.0, x, z),
        3 => (1.0, 2.0, x, 1.0 - z),
        4 => (3.0, 1.0, 1.0 - x, y),
        _ => (1.0, 1.0, x, y),
    };
    DVec2::new((column + across) / 4.0, (row + up) / 3.0)
}

/// A torus's uv: u the angle around the Y axis from the -x axis turning towards +z, v the
/// angle around the tube from its inner rim over the top (both 0 to 1; measured).
pub fn torus_uv(major: f64, point: DVec3) -> DVec2 {
    let u = turns(point.z.atan2(-point.x));
    let from_tube_centre = DVec2::new(point.x, point.z).length() - major;
    let v = point.y.atan2(from_tube_centre) / TAU + 0.5;
    DVec2::new(u, v)
}

/// An angle in radians as a fraction of a turn in [0, 1).
fn turns(angle: f64) -> f64 {
    let fraction = angle / TAU;
    if fraction < 0.0 {
        fraction + 1.0
    } else {
        fraction
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn barycentric_weights_reproduce_the_point() {
        let corners = [
            DVec3::ZERO,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 3.0, 0.0),
        ];
        let point = DVec3::new(0.5, 0.75, 0.0);
        let weights = barycentric(corners, point);
        let back = corners[0] * weights[0] + corners[1] * weights[1] + corners[2] * weights[2];
        assert!((back - point).length() < 1e-12);
        assert!((weights.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert_eq!(barycentric([DVec3::ZERO; 3], point), [1.0, 0.0, 0.0]);
    }

    #[test]
    fn sphere_uv_follows_pov_ray() {
        // Measured: the point towards -z has u = 0.75; the equator has v = 0.5.
        let uv = sphere_uv(-DVec3::Z);
        assert!((uv - DVec2::new(0.75, 0.5)).length() < 1e-12);
        assert!((sphere_uv(DVec3::Y).y - 1.0).abs() < 1e-12);
        assert!(sphere_uv(-DVec3::Y * 2.0).y.abs() < 1e-12);
        assert_eq!(sphere_uv(DVec3::ZERO), DVec2::ZERO);
    }

    #[test]
    fn box_and_torus_uv_follow_pov_ray() {
        // Measured on box { -1, 1 }: the -z face at x = -0.78, y = 0.78 has u = 0.973,
        // v = 0.631; the top face at x = 0.78, z = -0.78 has u = 0.471, v = 0.965.
        let bounds = Aabb::from_corners(-DVec3::ONE, DVec3::ONE);
        let front = box_uv(bounds, DVec3::new(-0.78, 0.78, -1.0), 4);
        assert!((front - DVec2::new(0.9725, 0.63)).abs().max_element() < 2e-3);
        let top = box_uv(bounds, DVec3::new(0.78, 1.0, -0.78), 3);
        assert!((top - DVec2::new(0.4725, 0.963)).abs().max_element() < 3e-3);
        // Measured on torus { 1, 0.5 }: +z has u = 0.25, the top of the tube v = 0.75.
        let uv = torus_uv(1.0, DVec3::new(0.0, 0.5, 1.0));
        assert!((uv - DVec2::new(0.25, 0.75)).abs().max_element() < 1e-12);
    }
}
