//! Pigment evaluation: the colour of a pigment at a world-space point.
//!
//! In: a [`Pigment`] whose pattern transforms map world space to pattern space, and a world
//! point. Out: a five-component [`Colour`] (rgb, filter, transmit). Holds: evaluation never
//! allocates and never panics; non-finite input gives black rather than garbage.
//!
//! The rules, measured against POV-Ray 3.7 renders:
//! - `checker`: block `(⌊x+ε⌋ + ⌊y+ε⌋ + ⌊z+ε⌋) mod 2` with ε = 1e-10, so a point exactly on
//!   a cube face belongs to the cube above it (and a point 1e-10 below still does).
//! - `gradient d`: the projection `v = p · d/|d|`; values above 1 wrap with `fmod(v, 1)`;
//!   then POV-Ray's ramp wave `fmod(v, 1.00001)`, adding 1 when negative. So `x = 1` gives 1
//!   (the last colour), `x = 2` gives 0, `x = -0.3` gives 0.7, `x = -2` gives 0.00001.
//! - colour and pigment maps: below the first key the first colour, above the last key the last colour;
//!   otherwise the first entry whose key is `>= v` and the entry before it are interpolated
//!   linearly in all five components (so at a repeated key the earlier entry wins).
//! - `average`: the weighted mean of the entries' colours (weights divided by their sum).

use super::image_map::image_colour;
use crate::texture::pattern::SurfaceContext;
use crate::{
    math::Colour,
    texture::{pattern::Pattern, Pigment, PigmentMap},
};
use glam::DVec3;

/// How far nested pigments (a block of a checker holding another checker...) are followed.
const MAX_PIGMENT_NESTING: u32 = 64;

/// The colour of `pigment` at `world_point`, away from any surface.
pub fn pigment_colour(pigment: &Pigment, world_point: DVec3) -> Colour {
    colour_at_depth(pigment, world_point, &SurfaceContext::default(), 0)
}

/// The colour of `pigment` at `world_point` on a surface (`surface` in world space), for
/// the patterns that depend on the surface (`slope`, `aoi`).
pub fn pigment_colour_at(
    pigment: &Pigment,
    world_point: DVec3,
    surface: &SurfaceContext,
) -> Colour {
    colour_at_depth(pigment, world_point, surface, 0)
}

/// The surface a ray meets at `point`: the unit geometric normal `normal` turned towards
/// the ray (or the reversed ray when the normal is not finite) and the ray's unit direction.
pub fn hit_surface(point: DVec3, ray_direction: DVec3, normal: DVec3) -> SurfaceContext {
    let facing = if ray_direction.dot(normal) <= 0.0 {
        normal
    } else {
        -normal
    };
    SurfaceContext {
        point,
        normal: if facing.is_finite() {
            facing
        } else {
            -ray_direction
        },
        ray_direction,
        uv: None,
    }
}

/// Evaluates `pigment`, following nested pigments at most [`MAX_PIGMENT_NESTING`] deep.
fn colour_at_depth(
    pigment: &Pigment,
    world_point: DVec3,
    surface: &SurfaceContext,
    depth: u32,
) -> Colour {
    if depth >= MAX_PIGMENT_NESTING {
        return Colour::BLACK;
    }
    match pigment {
        Pigment::Solid(colour) => *colour,
        Pigment::Pattern {
            pattern,
            map,
            transform,
        } => {
            let point = transform.point_to_inner(world_point);
            if !point.is_finite() {
                return Colour::BLACK;
            }
            match pattern.block_count() {
                Some(_) => {
                    let block = pattern.block(point);
                    block_colour(map, block, block as f64, world_point, surface, depth)
                }
                None => {
                    let value = pattern.value_at(point, surface);
                    match map {
                        PigmentMap::Blocks(blocks) => {
                            let index = spread_index(value, blocks.len());
                            block_colour(map, index, value, world_point, surface, depth)
                        }
                        _ => block_colour(map, 0, value, world_point, surface, depth),
                    }
                }
            }
        }
        Pigment::Average {
            entries,
            transform,
            warps,
        } => {
            let total: f64 = entries.iter().map(|entry| entry.0).sum();
            if total == 0.0 || !total.is_finite() {
                return Colour::BLACK;
            }
            // The entries carry the average's transformations, so the warped point goes back
            // out of the average's pattern space before they see it.
            let world_point = match warps {
                Some(pattern) => transform
                    .point_to_outer(pattern.moved_point(transform.point_to_inner(world_point))),
                None => world_point,
            };
            let mut sum = [0.0; 5];
            for (weight, entry) in entries {
                let colour = colour_at_depth(entry, world_point, surface, depth + 1).to_array();
                for (acc, component) in sum.iter_mut().zip(colour) {
                    *acc += weight / total * component;
                }
            }
            Colour::from_array(sum)
        }
        Pigment::Image {
            image,
            transform,
            warps,
        } => {
            let point = transform.point_to_inner(world_point);
            match warps {
                Some(pattern) => image_colour(image, pattern.moved_point(point)),
                None => image_colour(image, point),
            }
        }
        // Nested in another pigment, a uv-mapped pigment is looked up at the hit's uv
        // coordinates too (measured: `average pigment_map { [1 uv_mapping ..] }` shows the
        // same uv as a uv-mapped pigment of its own); away from a surface the point passes.
        Pigment::UvMapped(inner) => {
            let point = surface.uv.map_or(world_point, |uv| uv.extend(0.0));
            colour_at_depth(inner, point, surface, depth + 1)
        }
    }
}

/// The colour `map` gives for block `index` (block maps) or for the pattern `value` (colour
/// and pigment maps).
fn block_colour(
    map: &PigmentMap,
    index: usize,
    value: f64,
    world_point: DVec3,
    surface: &SurfaceContext,
    depth: u32,
) -> Colour {
    match map {
        PigmentMap::Blocks(blocks) => match blocks.get(index).or(blocks.last()) {
            Some(block) => colour_at_depth(block, world_point, surface, depth + 1),
            None => Colour::BLACK,
        },
        PigmentMap::Colours(entries) => colour_map_lookup(entries, value),
        PigmentMap::Pigments(entries) => {
            let Some((low, high, fraction)) = blend_position(entries, value) else {
                return Colour::BLACK;
            };
            let below = colour_at_depth(&entries[low].1, world_point, surface, depth + 1);
            if fraction == 0.0 {
                return below;
            }
            let above = colour_at_depth(&entries[high].1, world_point, surface, depth + 1);
            below.lerp(above, fraction)
        }
    }
}

/// The block a pattern selects at a pattern-space point among `count` blocks: the pattern's
/// own block for block patterns, else the value's share of [0, 1].
pub fn block_index(
    pattern: &Pattern,
    point: DVec3,
    count: usize,
    surface: &SurfaceContext,
) -> usize {
    match pattern.block_count() {
        Some(_) => pattern.block(point),
        None => spread_index(pattern.value_at(point, surface), count),
    }
}

/// Index of the block a value in [0, 1] selects when `count` blocks share the range evenly.
fn spread_index(value: f64, count: usize) -> usize {
    if count == 0 {
        return 0;
    }
    let scaled = (value * count as f64).floor();
    if scaled >= 1.0 {
        (scaled as usize).min(count - 1)
    } else {
        0
    }
}

/// Where `value` falls among the sorted keys of a map: the entries below and above it and
/// how far it is from the one below (0 when only one entry applies). `None` for an empty map.
///
/// Below the first key the first entry applies, above the last key the last; otherwise the
/// first entry whose key is `>= value` and the entry before it (at a repeated key the
/// earlier entry wins).
pub fn blend_position<T>(entries: &[(f64, T)], value: f64) -> Option<(usize, usize, f64)> {
    let first = entries.first()?;
    if value.is_nan() || value <= first.0 {
        return Some((0, 0, 0.0));
    }
    let Some(upper) = entries.iter().position(|entry| entry.0 >= value) else {
        let last = entries.len() - 1;
        return Some((last, last, 0.0));
    };
    let span = entries[upper].0 - entries[upper - 1].0;
    if span > 0.0 {
        Some((upper - 1, upper, (value - entries[upper - 1].0) / span))
    } else {
        Some((upper, upper, 0.0))
    }
}

/// Looks `value` up in sorted (key, colour) entries, interpolating between neighbours.
pub fn colour_map_lookup(entries: &[(f64, Colour)], value: f64) -> Colour {
    match blend_position(entries, value) {
        None => Colour::BLACK,
        Some((low, _, 0.0)) => entries[low].1,
        Some((low, high, fraction)) => entries[low].1.lerp(entries[high].1, fraction),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::pattern::{checker_block, gradient_value};
    use crate::{
        math::Transform,
        texture::pattern::{Pattern, PatternKind},
    };

    fn checker(a: Colour, b: Colour) -> Pigment {
        Pigment::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Checker)),
            map: PigmentMap::Blocks(vec![Pigment::Solid(a), Pigment::Solid(b)]),
            transform: Transform::IDENTITY,
        }
    }

    #[test]
    fn checker_blocks_and_boundary_offset() {
        assert_eq!(checker_block(DVec3::new(0.5, 0.5, 0.0)), 0);
        assert_eq!(checker_block(DVec3::new(0.5, 1.5, 0.0)), 1);
        assert_eq!(checker_block(DVec3::new(0.5, 0.5, -0.5)), 1);
        // Within 1e-10 below a face still counts as above it, as in POV-Ray.
        assert_eq!(checker_block(DVec3::new(0.5, 0.5, -5e-11)), 0);
        assert_eq!(checker_block(DVec3::new(0.5, 0.5, -1e-9)), 1);
        assert_eq!(checker_block(DVec3::new(-3.5, 2.5, 7.0)), 1);
        assert_eq!(checker_block(DVec3::new(-3.5, 2.5, 6.0)), 0);
    }

    #[test]
    fn nested_checker_uses_its_own_transform() {
        let inner = Pigment::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Checker)),
            map: PigmentMap::Blocks(vec![
                Pigment::Solid(Colour::grey(0.25)),
                Pigment::Solid(Colour::grey(0.75)),
            ]),
            transform: Transform::scaling(DVec3::splat(0.5)).unwrap(),
        };
        let outer = Pigment::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Checker)),
            map: PigmentMap::Blocks(vec![inner, Pigment::Solid(Colour::WHITE)]),
            transform: Transform::IDENTITY,
        };
        assert_eq!(
            pigment_colour(&outer, DVec3::new(0.25, 0.25, 0.25)).red,
            0.25
        );
        assert_eq!(
            pigment_colour(&outer, DVec3::new(0.75, 0.25, 0.25)).red,
            0.75
        );
        assert_eq!(
            pigment_colour(&outer, DVec3::new(1.25, 0.25, 0.25)).red,
            1.0
        );
        let plain = checker(Colour::BLACK, Colour::WHITE);
        assert_eq!(
            pigment_colour(&plain, DVec3::new(1.5, 0.5, 0.5)),
            Colour::WHITE
        );
    }

    #[test]
    fn gradient_values_match_povray() {
        let x = DVec3::X;
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(gradient_value(DVec3::new(0.3, 0.0, 0.0), x), 0.3));
        assert!(close(gradient_value(DVec3::new(-0.3, 0.0, 0.0), x), 0.7));
        assert_eq!(gradient_value(DVec3::new(1.0, 0.0, 0.0), x), 1.0);
        assert_eq!(gradient_value(DVec3::new(2.0, 0.0, 0.0), x), 0.0);
        assert!(close(
            gradient_value(DVec3::new(-2.0, 0.0, 0.0), x),
            0.00001
        ));
        assert!(close(
            gradient_value(DVec3::new(0.3, 0.0, 0.0), 2.0 * x),
            0.3
        ));
        let diagonal = gradient_value(DVec3::new(0.3, 0.2, 0.0), DVec3::new(1.0, 1.0, 0.0));
        assert!(close(diagonal, 0.5 / 2f64.sqrt()));
        assert_eq!(gradient_value(DVec3::ONE, DVec3::ZERO), 0.0);
        assert_eq!(gradient_value(DVec3::splat(f64::NAN), x), 0.0);
    }

    #[test]
    fn colour_map_edges_and_repeated_keys() {
        let red = Colour::rgb(1.0, 0.0, 0.0);
        let green = Colour::rgb(0.0, 1.0, 0.0);
        let blue = Colour::rgb(0.0, 0.0, 1.0);
        let map = [(0.2, red), (0.5, green), (0.5, blue), (0.8, Colour::WHITE)];
        assert_eq!(colour_map_lookup(&map, 0.1), red);
        assert_eq!(colour_map_lookup(&map, 0.5), green);
        assert_eq!(colour_map_lookup(&map, 0.9), Colour::WHITE);
        let mid = colour_map_lookup(&map, 0.35);
        assert!((mid.red - 0.5).abs() < 1e-12 && (mid.green - 0.5).abs() < 1e-12);
        let past = colour_map_lookup(&map, 0.65);
        assert!((past.blue - 1.0).abs() < 1e-12 && (past.red - 0.5).abs() < 1e-12);
        assert_eq!(colour_map_lookup(&[], 0.5), Colour::BLACK);
        assert_eq!(colour_map_lookup(&map, f64::NAN), red);
    }
}
