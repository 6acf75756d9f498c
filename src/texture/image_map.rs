//! Image maps: the colour (or height) an image gives at a pattern-space point.
//!
//! In: an [`ImageMap`] (pixels already linear) and a point in the image's pattern space.
//! Out: a [`Colour`] (rgb, filter, transmit), a height or an `image_pattern` value. Holds: no allocation, no panic;
//! non-finite points give a clear colour.
//!
//! Projections (`map_type`), as the manual describes them:
//! - 0 planar: the image covers the unit square of the XY plane, x to the right, y up,
//!   repeated in both directions (unless `once`, where outside is clear).
//! - 1 spherical: u is the longitude around Y, v the latitude from the south pole (0) to
//!   the north pole (1).
//! - 2 cylindrical: u is the angle around Y, v is y (one unit high).
//! - 5 torus: u the angle around Y, v the angle around the tube of a unit major radius,
//!   starting (v = 0) on the tube's inner rim (measured: half a turn from the angle
//!   `atan2(y, distance from the Y axis − 1)`).
//!
//! Measured (planar maps, 16-bit output): pixel (column, row) covers
//! `[column/width, (column+1)/width)` in u and rows count down from v = 1; `interpolate 2`
//! is bilinear between the four nearest pixel centres; `interpolate 4` weights those four by
//! the inverse square of the distance to each centre (in pixels).

use crate::{
    math::Colour,
    texture::{ImageMap, ImageProjection},
};
use glam::DVec3;
use std::f64::consts::TAU;

/// The colour of the image at a pattern-space point.
pub fn image_colour(image: &ImageMap, point: DVec3) -> Colour {
    let Some((u, v)) = image_coordinates(image, point) else {
        return Colour::rgbft(1.0, 1.0, 1.0, 0.0, 1.0);
    };
    let [red, green, blue, alpha] = sample(image, u, v);
    let alpha = f64::from(alpha);
    let (mut filter, mut transmit) = (image.filter_all, image.transmit_all);
    if let Some(indices) = &image.palette_indices {
        let (column, row) = pixel_position(image, u, v);
        let entry = |amounts: &[(u8, f64)]| {
            let index = pixel_index(image, column, row);
            let palette = *indices.get(index)?;
            amounts
                .iter()
                .find(|(entry, _)| *entry == palette)
                .map(|&(_, amount)| amount)
        };
        filter = entry(&image.palette_filter).unwrap_or(filter);
        transmit = entry(&image.palette_transmit).unwrap_or(transmit);
    }
    Colour::rgbft(
        f64::from(red),
        f64::from(green),
        f64::from(blue),
        filter,
        transmit + (1.0 - alpha),
    )
}

/// The tilt a `bump_map` of `bump_size` 1 gives the normal at a pattern-space point, in
/// pattern space (x along the image's u, y along v); zero outside a `once` image.
///
/// Measured on a plane with grazing parallel lights and random 8×8 grey images: the tilt is
/// constant over each pixel (row r counted from the top, column c) and, with h the grey
/// level (stored value, 0 to 1) and rows and columns wrapping,
/// x = ½·(h(r+1, c−1) − h(r+1, c+1)) and y = ½·(h(r+1, c−1) + h(r+1, c+1)) − h(r, c)
/// (least-squares fit over a 3×3 neighbourhood: these weights within 0.002, the others
/// below 0.002), linear in `bump_size`. With `use_index` on a palette image h is the
/// palette index itself (0 to 255, not scaled; measured the same way to 1e-5).
pub fn bump_map_tilt(image: &ImageMap, point: DVec3) -> DVec3 {
    let Some((u, v)) = image_coordinates(image, point) else {
        return DVec3::ZERO;
    };
    let (column, row) = pixel_position(image, u, v);
    let palette = image.palette_indices.as_deref().filter(|_| image.use_index);
    let height = |column: i64, row: i64| match palette {
        Some(indices) => indices
            .get(pixel_index(image, column, row))
            .map_or(0.0, |&index| f64::from(index)),
        None => grey(pixel(image, column, row)),
    };
    let below_left = height(column - 1, row + 1);
    let below_right = height(column + 1, row + 1);
    DVec3::new(
        0.5 * (below_left - below_right),
        0.5 * (below_left + below_right) - height(column, row),
        0.0,
    )
}

/// Which of `count` textures a `material_map` shows at a pattern-space point; `None`
/// outside a `once` image or without textures.
///
/// The index is the pixel's palette index, or for images without a palette its 8-bit red
/// value (the manual's rule, measured). Measured with 3 and 4 textures, unlike the manual's
/// plain modulo: an index equal to the count picks the last texture, a larger one wraps
/// modulo the count (with 4 textures, indices 4, 5, 8, 255 pick 3, 1, 0, 3).
pub fn material_choice(image: &ImageMap, point: DVec3, count: usize) -> Option<usize> {
    if count == 0 {
        return None;
    }
    let index = material_index(image, point)?;
    Some(if index > count {
        index % count
    } else {
        index.min(count - 1)
    })
}

/// The palette index (or 8-bit red value) of the pixel at a pattern-space point.
fn material_index(image: &ImageMap, point: DVec3) -> Option<usize> {
    let (u, v) = image_coordinates(image, point)?;
    let (column, row) = pixel_position(image, u, v);
    let index = pixel_index(image, column, row);
    match &image.palette_indices {
        Some(indices) => indices.get(index).map(|&palette| usize::from(palette)),
        None => {
            let red = image.pixels.get(index)?[0];
            Some((f64::from(red).clamp(0.0, 1.0) * 255.0).round() as usize)
        }
    }
}

/// The grey level of a pixel: 0.297 R + 0.589 G + 0.114 B (measured).
fn grey([red, green, blue, _]: [f32; 4]) -> f64 {
    0.297 * f64::from(red) + 0.589 * f64::from(green) + 0.114 * f64::from(blue)
}

/// The value of an `image_pattern` at a pattern-space point: the stored grey level
/// 0.297 R + 0.589 G + 0.114 B (measured; at most 1, measured with HDR files brighter than
/// that), or with `use_alpha` the transparency 1 − alpha (measured); 0 outside a `once` image.
pub fn image_value(image: &ImageMap, point: DVec3) -> f64 {
    let Some((u, v)) = image_coordinates(image, point) else {
        return 0.0;
    };
    let sampled = sample(image, u, v);
    if image.use_alpha {
        return 1.0 - f64::from(sampled[3]);
    }
    grey(sampled).min(1.0)
}

/// The image coordinates (u right, v up, both in [0, 1)) of a pattern-space point;
/// `None` outside the image of a `once` map or for a non-finite point.
fn image_coordinates(image: &ImageMap, point: DVec3) -> Option<(f64, f64)> {
    if !point.is_finite() {
        return None;
    }
    let (u, v) = match image.projection {
        ImageProjection::Planar => (point.x, point.y),
        ImageProjection::Spherical => {
            let length = point.length();
            if length == 0.0 {
                (0.0, 0.5)
            } else {
                let latitude = (point.y / length).clamp(-1.0, 1.0).asin();
                (longitude(point), latitude / std::f64::consts::PI + 0.5)
            }
        }
        ImageProjection::Cylindrical => (longitude(point), point.y),
        ImageProjection::Torus => {
            let radial = (point.x * point.x + point.z * point.z).sqrt() - 1.0;
            let tube = (-point.y).atan2(-radial).rem_euclid(TAU) / TAU;
            (longitude(point), tube)
        }
    };
    if image.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return None;
    }
    Some((u.rem_euclid(1.0), v.rem_euclid(1.0)))
}

/// The angle around the Y axis as a fraction of a turn, from the +X axis towards +Z
/// (matches POV-Ray's spherical and cylindrical image maps).
fn longitude(point: DVec3) -> f64 {
    (point.z.atan2(point.x) / TAU).rem_euclid(1.0)
}

/// The pixel value at image coordinates (u, v), interpolated as the map asks.
fn sample(image: &ImageMap, u: f64, v: f64) -> [f32; 4] {
    let width = f64::from(image.width);
    let height = f64::from(image.height);
    let x = u * width;
    let y = (1.0 - v) * height;
    if image.interpolation == 0 {
        let (column, row) = pixel_position(image, u, v);
        return pixel(image, column, row);
    }
    // Between the four nearest pixel centres.
    let x = x - 0.5;
    let y = y - 0.5;
    let (column, row) = (x.floor(), y.floor());
    let (fx, fy) = (x - column, y - row);
    let (column, row) = (column as i64, row as i64);
    let offsets = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
    let mut weights = [0.0f64; 4];
    for (weight, (dx, dy)) in weights.iter_mut().zip(offsets) {
        *weight = if image.interpolation == 4 {
            let squared = (fx - dx) * (fx - dx) + (fy - dy) * (fy - dy);
            if squared == 0.0 {
                return pixel(image, column + dx as i64, row + dy as i64);
            }
            1.0 / squared
        } else {
            (1.0 - (fx - dx).abs()) * (1.0 - (fy - dy).abs())
        };
    }
    let total: f64 = weights.iter().sum();
    let mut result = [0.0f32; 4];
    for (weight, (dx, dy)) in weights.iter().zip(offsets) {
        let value = pixel(image, column + dx as i64, row + dy as i64);
        for (acc, channel) in result.iter_mut().zip(value) {
            *acc += (weight / total) as f32 * channel;
        }
    }
    result
}

/// The column and row (from the top) of the pixel covering image coordinates (u, v).
fn pixel_position(image: &ImageMap, u: f64, v: f64) -> (i64, i64) {
    let column = (u * f64::from(image.width)).floor() as i64;
    // v = 0 exactly gives the bottom row (y = height), as POV-Ray renders it.
    let row =
        (((1.0 - v) * f64::from(image.height)).floor() as i64).min(i64::from(image.height) - 1);
    (column, row)
}

/// The position in the pixel list of `column`, `row`, wrapping around the image's edges.
fn pixel_index(image: &ImageMap, column: i64, row: i64) -> usize {
    let width = i64::from(image.width.max(1));
    let height = i64::from(image.height.max(1));
    (row.rem_euclid(height) * width + column.rem_euclid(width)) as usize
}

/// The pixel at `column`, `row`, wrapping around the image's edges.
fn pixel(image: &ImageMap, column: i64, row: i64) -> [f32; 4] {
    image
        .pixels
        .get(pixel_index(image, column, row))
        .copied()
        .unwrap_or([0.0, 0.0, 0.0, 1.0])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_pixels(use_alpha: bool) -> ImageMap {
        ImageMap {
            width: 2,
            height: 1,
            pixels: vec![[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 0.25]],
            projection: ImageProjection::Planar,
            once: false,
            interpolation: 0,
            filter_all: 0.0,
            transmit_all: 0.0,
            use_index: false,
            use_alpha,
            palette_indices: None,
            palette_filter: Vec::new(),
            palette_transmit: Vec::new(),
            file: None,
        }
    }

    #[test]
    fn image_pattern_value_is_weighted_grey_or_transparency() {
        let image = two_pixels(false);
        assert!((image_value(&image, DVec3::new(0.25, 0.5, 0.0)) - 0.297).abs() < 1e-12);
        assert!((image_value(&image, DVec3::new(0.75, 0.5, 0.0)) - 0.589).abs() < 1e-12);
        let image = two_pixels(true);
        assert!(image_value(&image, DVec3::new(0.25, 0.5, 0.0)).abs() < 1e-12);
        assert!((image_value(&image, DVec3::new(0.75, 0.5, 0.0)) - 0.75).abs() < 1e-12);
    }

    #[test]
    fn bump_map_tilt_uses_the_row_below() {
        // One row: the row below is the row itself; left and right neighbours wrap.
        let image = two_pixels(false);
        let tilt = bump_map_tilt(&image, DVec3::new(0.25, 0.5, 0.0));
        // Neighbours of column 0 are both column 1 (grey 0.589); own grey 0.297.
        assert!(tilt.x.abs() < 1e-12);
        assert!((tilt.y - (0.589 - 0.297)).abs() < 1e-12);
    }
}
