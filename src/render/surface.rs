//! The texture at a surface hit: which plain textures a compound texture shows there, and
//! with what weight.
//!
//! In: a [`Texture`] whose transforms map world space to pattern space, and a surface hit.
//! Out: calls to a visitor with each plain texture (one without `compound`), the colour
//! weight of its shaded result, and whether light may pass through it. Holds: no allocation
//! (the visitor is called recursively), nesting is bounded.
//!
//! Rules (POV-Ray 3.7 manual, checked with renders):
//! - texture maps, block textures and tiles blend the fully shaded textures (lighting,
//!   highlights, reflection, transparency) with the map's weights.
//! - `average` blends the shaded textures with weights divided by their sum.
//! - layered textures: the top layer is shaded with weight 1; each layer below is seen
//!   through the layers above it, weighted by the product of their transmission
//!   (`filter · pigment + transmit`). Only the bottom layer lets rays pass on through the
//!   surface.
//! - a texture map's two neighbouring entries are visited upper first, then lower. After a
//!   plain texture with a `normal` has been visited, the surface-dependent patterns (`slope`,
//!   `aoi`) of the maps evaluated later at the same hit see its perturbed normal instead of
//!   the surface's (measured: `texture_map { [0 T] [1 V] }`, T a `slope` map and V bumpy,
//!   gives T a bumpy slope boundary; with the entries swapped T's boundary stays smooth).

use super::optics::transmission;
use crate::geometry::SurfaceHit;
use crate::texture::image_map::material_choice;
use crate::texture::normal::perturbed_normal_at;
use crate::texture::pattern::SurfaceContext;
use crate::texture::pigment::{blend_position, block_index, pigment_colour_at};
use crate::{
    math::Colour,
    texture::{BlendMap, CompoundTexture, Normal, Pigment, Texture},
};
use glam::DVec3;
use std::cell::Cell;

/// How far nested compound textures are followed.
const MAX_TEXTURE_NESTING: u32 = 32;

/// Calls `visit(texture, weight, passes_light)` for every plain texture that contributes
/// at `hit` on the surface `surface` (world space; see `hit_surface`).
pub fn for_each_component(
    texture: &Texture,
    hit: &SurfaceHit,
    surface: &SurfaceContext,
    visit: &mut dyn FnMut(&Texture, DVec3, bool),
) {
    let place = Place {
        hit,
        surface,
        last_normal: Cell::new(None),
    };
    components(texture, &place, DVec3::ONE, true, 0, visit);
}

/// Where textures are evaluated: the hit (point and uv coordinates) and the surface there.
struct Place<'a> {
    hit: &'a SurfaceHit,
    surface: &'a SurfaceContext,
    /// The `normal` of the plain texture visited last that has one, if any.
    last_normal: Cell<Option<&'a Normal>>,
}

impl Place<'_> {
    /// The surface a map's `pattern` sees: the surface itself, or for a surface-dependent
    /// pattern after a plain texture with a `normal` was visited, the surface with that
    /// texture's perturbed normal.
    fn surface_for(&self, pattern: &crate::texture::pattern::Pattern) -> SurfaceContext {
        match self.last_normal.get() {
            Some(normal) if pattern.depends_on_surface() => SurfaceContext {
                normal: perturbed_normal_at(normal, self.hit.point, self.hit.uv, self.surface),
                ..*self.surface
            },
            _ => *self.surface,
        }
    }
}

/// The pigment colour the surface shows at `hit` (the blend of its components' pigments,
/// uv-mapped ones at the hit's uv coordinates), for what shadow rays and the layers below
/// a layer see.
pub fn surface_pigment(texture: &Texture, hit: &SurfaceHit, surface: &SurfaceContext) -> Colour {
    if texture.compound.is_none() {
        return pigment_at_hit(&texture.pigment, hit, surface);
    }
    let mut sum = [0.0; 5];
    for_each_component(texture, hit, surface, &mut |plain, weight, passes_light| {
        if passes_light {
            let colour = pigment_at_hit(&plain.pigment, hit, surface).to_array();
            let weight = weight.dot(DVec3::splat(1.0 / 3.0));
            for (acc, component) in sum.iter_mut().zip(colour) {
                *acc += weight * component;
            }
        }
    });
    Colour::from_array(sum)
}

/// The part of the light a shadow ray keeps crossing the surface at `hit`: a layered
/// texture passes what every layer passes, colour by colour (measured in POV-Ray 3.7: a
/// red filtering layer over a clear `transmit 0.9` one casts a red shadow, 0.9 times the
/// red layer's alone); other textures pass what the blend of their pigments passes.
pub fn surface_transmission(
    texture: &Texture,
    hit: &SurfaceHit,
    surface: &SurfaceContext,
) -> DVec3 {
    surface_transmission_at(texture, hit, surface, 0)
}

fn surface_transmission_at(
    texture: &Texture,
    hit: &SurfaceHit,
    surface: &SurfaceContext,
    depth: u32,
) -> DVec3 {
    match texture.compound.as_deref() {
        Some(CompoundTexture::Layered(layers)) if depth < MAX_TEXTURE_NESTING => {
            let mut passed = DVec3::ONE;
            for layer in layers {
                passed *= surface_transmission_at(layer, hit, surface, depth + 1);
                if passed == DVec3::ZERO {
                    break;
                }
            }
            passed
        }
        _ => transmission(surface_pigment(texture, hit, surface)),
    }
}

/// The colour of a texture's own pigment at `hit`: a uv-mapped pigment, and any nested in
/// the pigment's maps, is evaluated at the hit's `<u, v, 0>` (shapes without uv
/// coordinates give the world point's x and y, as in POV-Ray), any other at the hit point.
pub fn pigment_at_hit(pigment: &Pigment, hit: &SurfaceHit, surface: &SurfaceContext) -> Colour {
    let surface = &SurfaceContext {
        uv: hit.uv,
        ..*surface
    };
    match (pigment.uv_mapped(), hit.uv) {
        (Some(inner), Some(uv)) => pigment_colour_at(inner, uv.extend(0.0), surface),
        _ => pigment_colour_at(pigment, hit.point, surface),
    }
}

/// Visits the components of `texture`, whose results are weighted by `weight`.
fn components<'a>(
    texture: &'a Texture,
    place: &Place<'a>,
    weight: DVec3,
    passes_light: bool,
    depth: u32,
    visit: &mut dyn FnMut(&Texture, DVec3, bool),
) {
    let Some(compound) = &texture.compound else {
        visit(texture, weight, passes_light);
        if let Some(normal) = &texture.normal {
            place.last_normal.set(Some(normal));
        }
        return;
    };
    if depth >= MAX_TEXTURE_NESTING {
        return;
    }
    let mut recurse = |inner: &'a Texture, share: DVec3, passes: bool| {
        components(inner, place, weight * share, passes, depth + 1, visit)
    };
    match &**compound {
        CompoundTexture::Layered(layers) => {
            let mut seen = DVec3::ONE;
            for (index, layer) in layers.iter().enumerate().rev() {
                let bottom = index == 0;
                recurse(layer, seen, passes_light && bottom);
                if bottom {
                    break;
                }
                seen *= transmission(surface_pigment(layer, place.hit, place.surface));
                if seen == DVec3::ZERO {
                    break;
                }
            }
        }
        CompoundTexture::Pattern {
            pattern,
            map,
            transform,
        } => {
            let point = transform.point_to_inner(place.hit.point);
            if !point.is_finite() {
                return;
            }
            match map {
                BlendMap::Blocks(blocks) => {
                    let surface = place.surface_for(pattern);
                    let index = block_index(pattern, point, blocks.len(), &surface);
                    if let Some(block) = blocks.get(index).or(blocks.last()) {
                        recurse(block, DVec3::ONE, passes_light);
                    }
                }
                BlendMap::Entries(entries) => {
                    let value = pattern.value_at(point, &place.surface_for(pattern));
                    if let Some((low, high, fraction)) = blend_position(entries, value) {
                        if fraction > 0.0 {
                            recurse(&entries[high].1, DVec3::splat(fraction), passes_light);
                        }
                        if fraction < 1.0 {
                            recurse(&entries[low].1, DVec3::splat(1.0 - fraction), passes_light);
                        }
                    }
                }
            }
        }
        CompoundTexture::MaterialMap {
            image,
            textures,
            transform,
        } => {
            let point = transform.point_to_inner(place.hit.point);
            let chosen = material_choice(image, point, textures.len());
            if let Some(texture) = chosen.and_then(|index| textures.get(index)) {
                recurse(texture, DVec3::ONE, passes_light);
            }
        }
        CompoundTexture::Average(entries) => {
            let total: f64 = entries.iter().map(|entry| entry.0).sum();
            if total == 0.0 || !total.is_finite() {
                return;
            }
            for (share, entry) in entries {
                recurse(entry, DVec3::splat(share / total), passes_light);
            }
        }
    }
}
