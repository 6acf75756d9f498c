//! Image maps: the colour (or height) an image gives at a pattern-space point.
//!
//! In: an [`ImageMap`] (pixels already linear) and a point in the image's pattern space.
//! Out: a [`Colour`] (rgb, filter, transmit) or a height. Holds: no allocation, no panic;
//! non-finite points give a clear colour.
//!
//! Projections (`map_type`), as the manual describes them:
//! - 0 planar: the image covers the unit square of the XY plane, x to the right, y up,
//!   repeated in both directions (unless `once`, where outside is clear).
//! - 1 spherical: u is the longitude around Y, v the latitude from the south pole (0) to
//!   the north pole (1).
//! - 2 cylindrical: u is the angle around Y, v is y (one unit high).
//! - 5 torus: u the angle around Y, v the angle around the tube of a unit major radius.

use crate::scene::{Colour, ImageMap, ImageProjection};
use glam::DVec3;
use std::f64::consts::TAU;

/// The colour of the image at a pattern-space point.
pub fn image_colour(image: &ImageMap, point: DVec3) -> Colour {
    let Some((u, v)) = image_coordinates(image, point) else {
        return Colour::rgbft(1.0, 1.0, 1.0, 0.0, 1.0);
    };
    let [red, green, blue, alpha] = sample(image, u, v);
    let alpha = f64::from(alpha);
    Colour::rgbft(
        f64::from(red),
        f64::from(green),
        f64::from(blue),
        image.filter_all,
        image.transmit_all + (1.0 - alpha),
    )
}

/// The height (grey value) of the image at a pattern-space point, for bump maps.
pub fn image_height(image: &ImageMap, point: DVec3) -> f64 {
    let Some((u, v)) = image_coordinates(image, point) else {
        return 0.0;
    };
    let [red, green, blue, _] = sample(image, u, v);
    0.297 * f64::from(red) + 0.587 * f64::from(green) + 0.114 * f64::from(blue)
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
            let tube = point.y.atan2(radial).rem_euclid(TAU) / TAU;
            (longitude(point), tube)
        }
    };
    if image.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return None;
    }
    Some((u.rem_euclid(1.0), v.rem_euclid(1.0)))
}

/// The angle around the Y axis as a fraction of a turn, 0 on the -Z side... measured from
/// the +X axis towards -Z... (POV-Ray's convention for image projections).
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
        return pixel(image, x.floor() as i64, y.floor() as i64);
    }
    // Bilinear (and normalised distance, approximated by it) between pixel centres.
    let x = x - 0.5;
    let y = y - 0.5;
    let (column, row) = (x.floor(), y.floor());
    let (fx, fy) = ((x - column) as f32, (y - row) as f32);
    let (column, row) = (column as i64, row as i64);
    let corners = [
        (pixel(image, column, row), (1.0 - fx) * (1.0 - fy)),
        (pixel(image, column + 1, row), fx * (1.0 - fy)),
        (pixel(image, column, row + 1), (1.0 - fx) * fy),
        (pixel(image, column + 1, row + 1), fx * fy),
    ];
    let mut result = [0.0f32; 4];
    for (value, weight) in corners {
        for (acc, channel) in result.iter_mut().zip(value) {
            *acc += weight * channel;
        }
    }
    result
}

/// The pixel at `column`, `row`, wrapping around the image's edges.
fn pixel(image: &ImageMap, column: i64, row: i64) -> [f32; 4] {
    let width = i64::from(image.width.max(1));
    let height = i64::from(image.height.max(1));
    let index = row.rem_euclid(height) * width + column.rem_euclid(width);
    image
        .pixels
        .get(index as usize)
        .copied()
        .unwrap_or([0.0, 0.0, 0.0, 1.0])
}
