//! Normal perturbation: the shading normal tilted by a `normal { }` block.
//!
//! In: a [`Normal`] whose transforms map world space to pattern space, a world point (with
//! the surface's uv coordinates, if any) and the unit surface normal already turned towards
//! the viewer. Out: the unit perturbed normal.
//! Holds: no allocation, no panic; a non-finite result falls back to the unperturbed normal.
//!
//! Rules measured against POV-Ray 3.7 renders of `normal { gradient .. }` on a plane (16-bit
//! output, `File_Gamma=1`):
//! - a pattern without a dedicated perturbation is used as a height field: its slope G is
//!   estimated in pattern space from four samples at the corners of a regular tetrahedron
//!   `accuracy` (default 0.02) from the point; the result does not depend on `accuracy`
//!   for a linear pattern, so the samples are divided by it. The normal becomes
//!   `normalize(N − (2/15) · bump_size · s · Mᵀ G)` where Mᵀ G is the slope in world space
//!   (M maps world to pattern space) — for `gradient x 1` on a plane `y` the tilt is
//!   `atan(2/15)`. `bump_size` written after the pattern, or the default 0.5.
//! - bump scaling: s = |Fᵀ N| with F the pattern-to-world map, so scaling a pattern
//!   uniformly keeps the bumps' steepness (`scale 2`: same picture; `scale <1,2,1>` on a
//!   plane `y`: twice as steep; `scale <2,1,1>`: half). `no_bump_scale` makes s = 1.
//! - the warps and turbulence move only the point itself; the pattern is then sampled
//!   around the moved point, unwarped (measured: `gradient x turbulence 1` tilts the
//!   normal alike everywhere, with bumps only along the wrap).
//! - the four samples lie at `point + accuracy · corner` (in pattern space) for the corners
//!   of a regular tetrahedron with corners on +Y and towards +X: where bumps appear along a
//!   pattern's discontinuity (the wrap of `gradient x`, checker edges) then matches POV-Ray
//!   to a pixel. Block patterns (`checker`) are heights 0 on the first block, 1 on the
//!   second (their value).
//! - a reflected ray that a perturbed normal would send into the surface is mirrored once
//!   more about the surface plane, or about the unperturbed normal when the ray met the
//!   perturbed normal from behind (see `render::trace`).
//! - the tilt is applied to the normal facing the viewer (the same picture from above and
//!   below a plane lit from the viewer's side).
//! - `normal_map`, block normals and `average`: the weighted sum of the entries' perturbed
//!   normals, normalised.
//! - `uv_mapping`: the pattern (and the normals it is made of) is sampled around the hit's
//!   `<u, v, 0>` instead of the point (the point on shapes without uv coordinates), and the
//!   slope found in that space is added to the world normal as it stands, bump scaling as
//!   above (measured: `uv_mapping gradient x 1` tilts a box face or a sphere towards world
//!   -x exactly like `gradient x 1`, however the object is turned).

use super::image_map::bump_map_tilt;
use super::pigment::{blend_position, block_index};
use crate::texture::pattern::SurfaceContext;
use crate::texture::{BlendMap, Normal, NormalSource, SlopeEntry};
use glam::{DVec2, DVec3};

/// Factor between the pattern's slope and the tilt of the normal (measured).
const TILT_PER_SLOPE: f64 = 2.0 / 15.0;

/// How far nested normals are followed.
const MAX_NORMAL_NESTING: u32 = 64;

/// Corners of a regular tetrahedron of unit circumradius, one on +Y and one on +X: the
/// sample directions of the numeric slope (this orientation reproduces where POV-Ray's bumps
/// appear along a pattern's discontinuities).
const TETRAHEDRON: [DVec3; 4] = [
    DVec3::new(0.942809041582063, -1.0 / 3.0, 0.0),
    DVec3::new(-0.471404520791032, -1.0 / 3.0, 0.816496580927726),
    DVec3::new(-0.471404520791032, -1.0 / 3.0, -0.816496580927726),
    DVec3::new(0.0, 1.0, 0.0),
];

/// The unit normal at `world_point` (with surface coordinates `uv`, if the surface has
/// them) after `normal` tilts the facing unit normal `facing`.
pub fn perturbed_normal(
    normal: &Normal,
    world_point: DVec3,
    uv: Option<DVec2>,
    facing: DVec3,
) -> DVec3 {
    let surface = SurfaceContext {
        point: world_point,
        normal: facing,
        ray_direction: DVec3::ZERO,
        uv,
    };
    perturbed_normal_at(normal, world_point, uv, &surface)
}

/// [`perturbed_normal`] knowing the ray too: `surface.normal` is the facing unit normal,
/// and the surface-dependent patterns (`slope`, `aoi`) see it and the ray direction.
pub fn perturbed_normal_at(
    normal: &Normal,
    world_point: DVec3,
    uv: Option<DVec2>,
    surface: &SurfaceContext,
) -> DVec3 {
    let tilted = tilt(normal, world_point, uv, surface, 0);
    match tilted.try_normalize() {
        Some(unit) => unit,
        None => surface.normal,
    }
}

/// The (unnormalised) tilted normal, following nested normals at most
/// [`MAX_NORMAL_NESTING`] deep. `outer_point` is the point in the normal's outer space:
/// the world point, or inside a uv-mapped normal `<u, v, 0>`.
fn tilt(
    normal: &Normal,
    outer_point: DVec3,
    uv: Option<DVec2>,
    surface: &SurfaceContext,
    depth: u32,
) -> DVec3 {
    let facing = surface.normal;
    if depth >= MAX_NORMAL_NESTING {
        return facing;
    }
    // A uv-mapped normal sees `<u, v, 0>` (the world point's x and y on shapes without uv
    // coordinates, as pigments do), and so do the normals it is made of.
    let outer_point = match (normal.uv_mapped, uv) {
        (true, Some(uv)) => uv.extend(0.0),
        _ => outer_point,
    };
    let point = normal.transform.point_to_inner(outer_point);
    if !point.is_finite() {
        return facing;
    }
    match &normal.source {
        NormalSource::Pattern { pattern, slope_map } => {
            let facing_in_pattern = normal.transform.outer_from_inner.matrix3.transpose() * facing;
            if let Some(faceted) = pattern.facets_normal(point, unit(facing_in_pattern, facing)) {
                return normal.transform.normal_to_outer(faceted);
            }
            let perturbation = match pattern.normal_perturbation(point) {
                Some(vector) => vector,
                None => {
                    let moved = pattern.moved_point(point);
                    let height = |p: DVec3| {
                        let value = pattern.value_of_moved(p, surface);
                        match slope_map {
                            Some(entries) => slope_map_height(entries, value),
                            None => value,
                        }
                    };
                    -TILT_PER_SLOPE * pattern_slope(height, moved, normal.accuracy)
                }
            };
            facing + normal.amount * to_world(normal, perturbation, facing)
        }
        NormalSource::BumpMap(image) => {
            facing + normal.amount * to_world(normal, bump_map_tilt(image, point), facing)
        }
        NormalSource::Map { pattern, map } => match map {
            BlendMap::Blocks(blocks) => {
                let index = block_index(pattern, point, blocks.len(), surface);
                match blocks.get(index).or(blocks.last()) {
                    Some(block) => unit(tilt(block, outer_point, uv, surface, depth + 1), facing),
                    None => facing,
                }
            }
            BlendMap::Entries(entries) => {
                let value = pattern.value_at(point, surface);
                let Some((low, high, fraction)) = blend_position(entries, value) else {
                    return facing;
                };
                let below = unit(
                    tilt(&entries[low].1, outer_point, uv, surface, depth + 1),
                    facing,
                );
                if fraction == 0.0 {
                    return below;
                }
                let above = unit(
                    tilt(&entries[high].1, outer_point, uv, surface, depth + 1),
                    facing,
                );
                below * (1.0 - fraction) + above * fraction
            }
        },
        NormalSource::Average(entries) => {
            let mut sum = DVec3::ZERO;
            for (weight, entry) in entries {
                sum += *weight * unit(tilt(entry, outer_point, uv, surface, depth + 1), facing);
            }
            sum
        }
    }
}

/// `vector` normalised, or `fallback` when it cannot be.
fn unit(vector: DVec3, fallback: DVec3) -> DVec3 {
    vector.try_normalize().unwrap_or(fallback)
}

/// A pattern-space perturbation (or slope) expressed in world space, with POV-Ray's bump
/// scaling unless `no_bump_scale`.
fn to_world(normal: &Normal, vector: DVec3, facing: DVec3) -> DVec3 {
    let world = normal.transform.normal_to_outer(vector);
    if normal.no_bump_scale {
        return world;
    }
    let scale = (normal.transform.outer_from_inner.matrix3.transpose() * facing).length();
    if scale.is_finite() {
        world * scale
    } else {
        world
    }
}

/// The slope (gradient) of `height` at `point`, from samples at the corners of a
/// tetrahedron `accuracy` away; exact for linear functions.
fn pattern_slope(height: impl Fn(DVec3) -> f64, point: DVec3, accuracy: f64) -> DVec3 {
    let accuracy = if accuracy > 0.0 && accuracy.is_finite() {
        accuracy
    } else {
        0.02
    };
    let mut sum = DVec3::ZERO;
    for direction in TETRAHEDRON {
        sum += height(point + accuracy * direction) * direction;
    }
    sum * (0.75 / accuracy)
}

/// The height a `slope_map` gives at pattern value `value`: cubic Hermite interpolation
/// between the neighbouring entries' heights with their slopes.
fn slope_map_height(entries: &[SlopeEntry], value: f64) -> f64 {
    let Some(first) = entries.first() else {
        return value;
    };
    if value.is_nan() || value <= first.key {
        return first.height;
    }
    let Some(upper) = entries.iter().position(|entry| entry.key >= value) else {
        return entries[entries.len() - 1].height;
    };
    let (low, high) = (entries[upper - 1], entries[upper]);
    let span = high.key - low.key;
    if span <= 0.0 {
        return high.height;
    }
    let t = (value - low.key) / span;
    let (t2, t3) = (t * t, t * t * t);
    (2.0 * t3 - 3.0 * t2 + 1.0) * low.height
        + (t3 - 2.0 * t2 + t) * low.slope
        + (-2.0 * t3 + 3.0 * t2) * high.height
        + (t3 - t2) * high.slope
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{
        math::Transform,
        texture::pattern::{Pattern, PatternKind},
    };

    fn gradient_normal(direction: DVec3, amount: f64) -> Normal {
        let mut normal = Normal::new(NormalSource::Pattern {
            pattern: Pattern::new(PatternKind::Gradient(direction)),
            slope_map: None,
        });
        normal.amount = amount;
        normal
    }

    #[test]
    fn gradient_tilt_matches_povray() {
        // POV-Ray: plane y, `normal { gradient x 1 }`, light overhead: N·L = 0.99123.
        let normal = gradient_normal(DVec3::X, 1.0);
        let tilted = perturbed_normal(&normal, DVec3::new(0.4, 0.0, 0.0), None, DVec3::Y);
        assert!((tilted.y - 0.99123).abs() < 2e-5, "{tilted}");
        assert!(tilted.x < 0.0);
        // `scale <1,2,1>`: twice as steep (0.96623); uniform scale: unchanged.
        let mut steep = gradient_normal(DVec3::X, 1.0);
        steep.transform(&Transform::scaling(DVec3::new(1.0, 2.0, 1.0)).unwrap());
        let tilted = perturbed_normal(&steep, DVec3::new(0.4, 0.0, 0.0), None, DVec3::Y);
        assert!((tilted.y - 0.96623).abs() < 2e-5, "{tilted}");
        let mut flat = gradient_normal(DVec3::X, 1.0);
        flat.transform(&Transform::scaling(DVec3::splat(2.0)).unwrap());
        flat.no_bump_scale = true;
        let tilted = perturbed_normal(&flat, DVec3::new(0.4, 0.0, 0.0), None, DVec3::Y);
        assert!((tilted.y - 0.99779).abs() < 2e-5, "{tilted}");
    }

    #[test]
    fn uv_mapped_normal_tilts_the_world_normal_by_the_uv_slope() {
        // POV-Ray: a box face facing -z with `normal { uv_mapping gradient x 1 }` tilts
        // like `gradient x 1` in world space (N = <-0.13217, 0, -0.99123>), wherever the
        // face is and however the object is turned.
        let mut normal = gradient_normal(DVec3::X, 1.0);
        normal.uv_mapped = true;
        let uv = Some(DVec2::new(0.3, 0.5));
        let tilted = perturbed_normal(&normal, DVec3::new(5.0, -2.0, 7.0), uv, -DVec3::Z);
        assert!(
            (tilted - DVec3::new(-0.13217, 0.0, -0.99123)).length() < 2e-5,
            "{tilted}"
        );
        // Transformations applied once it is uv-mapped (an object's) leave it be; its own,
        // written in its block before it is marked uv-mapped, apply.
        let quarter_turn = Transform::rotation_degrees(DVec3::new(0.0, 0.0, 90.0));
        normal.transform(&quarter_turn);
        let turned = perturbed_normal(&normal, DVec3::ZERO, uv, -DVec3::Z);
        assert!((turned - tilted).length() < 1e-12, "{turned}");
        let mut normal = gradient_normal(DVec3::X, 1.0);
        normal.transform(&quarter_turn);
        normal.uv_mapped = true;
        let turned = perturbed_normal(&normal, DVec3::ZERO, uv, -DVec3::Z);
        assert!(
            (turned - DVec3::new(0.0, -0.13217, -0.99123)).length() < 2e-5,
            "{turned}"
        );
    }

    #[test]
    fn slope_map_interpolates_heights() {
        let entries = [
            SlopeEntry {
                key: 0.0,
                height: 0.0,
                slope: 1.0,
            },
            SlopeEntry {
                key: 1.0,
                height: 1.0,
                slope: 1.0,
            },
        ];
        assert!((slope_map_height(&entries, 0.25) - 0.25).abs() < 1e-12);
        assert_eq!(slope_map_height(&entries, -1.0), 0.0);
        assert_eq!(slope_map_height(&entries, 2.0), 1.0);
    }
}
