//! Focal blur: averaging rays from points of the lens that meet on the plane of focus.
//!
//! In: the pixel's image point, the [`CameraRays`] and the camera's [`FocalBlur`]. Out: the
//! pixel's linear colour. Holds: deterministic (lens points come from a Halton sequence,
//! sub-pixel offsets from a hash of the pixel), no allocation.
//!
//! POV-Ray shoots at least `min_samples` and at most `max_samples` rays per pixel from
//! jittered points of the pixel, stopping once the mean colour is known well enough
//! (`confidence`, `variance`). durer follows the same plan; its stopping rule is its own:
//! stop when z² · s² / n ≤ variance in every channel, with s² the sample variance and z
//! the two-sided normal quantile of `confidence`. Renders therefore agree with POV-Ray's
//! only within the noise of both. At most [`MAX_SAMPLES`] rays are traced per pixel.

use super::antialias::jitter_offset;
use super::camera::CameraRays;
use crate::scene::FocalBlur;
use glam::{DVec2, DVec3};

/// At most this many lens rays are traced per pixel, whatever `blur_samples` asks for, so a
/// huge count cannot stall a render.
pub const MAX_SAMPLES: u32 = 4096;

/// The mean colour of lens rays through the pixel at (`column`, `row`); `trace` gives the
/// colour of an image point seen from a lens point (`None`: no ray there, black).
pub fn blurred_pixel(
    column: u32,
    row: u32,
    camera: &CameraRays,
    blur: &FocalBlur,
    trace: &impl Fn(&crate::geometry::Ray) -> DVec3,
) -> DVec3 {
    let max_samples = blur.max_samples.clamp(1, MAX_SAMPLES);
    let min_samples = blur.min_samples.clamp(1, max_samples);
    let z = normal_quantile(blur.confidence);
    let mut mean = DVec3::ZERO;
    let mut squares = DVec3::ZERO;
    let mut count = 0u32;
    for index in 0..max_samples {
        let offset = jitter_offset(column, row, index, 1.0);
        let x = f64::from(column) + 0.5 + offset.x;
        let y = f64::from(row) + 0.5 + offset.y;
        let colour = match camera.ray_at(x, y) {
            Some(ray) => trace(&camera.through_lens(ray, lens_point(index))),
            None => DVec3::ZERO,
        };
        // Welford's running mean and sum of squared deviations.
        count += 1;
        let delta = colour - mean;
        mean += delta / f64::from(count);
        squares += delta * (colour - mean);
        if count >= min_samples && count > 1 {
            let variance_of_mean = squares / f64::from(count - 1) / f64::from(count);
            if (variance_of_mean * z * z).max_element() <= blur.variance {
                break;
            }
        }
    }
    mean
}

/// Lens point `index` in the unit disc: the Halton sequence in bases 2 and 3 mapped to the
/// disc with equal area.
fn lens_point(index: u32) -> DVec2 {
    let radius = halton(index + 1, 2).sqrt();
    let angle = std::f64::consts::TAU * halton(index + 1, 3);
    DVec2::new(angle.cos(), angle.sin()) * radius
}

/// The radical inverse of `index` in `base`.
fn halton(mut index: u32, base: u32) -> f64 {
    let mut result = 0.0;
    let mut fraction = 1.0 / f64::from(base);
    while index > 0 {
        result += fraction * f64::from(index % base);
        index /= base;
        fraction /= f64::from(base);
    }
    result
}

/// The two-sided standard normal quantile for probability `confidence` in [0, 1)
/// (Abramowitz and Stegun 26.2.23, error below 4.5e-4).
fn normal_quantile(confidence: f64) -> f64 {
    let tail = ((1.0 - confidence) / 2.0).clamp(1e-12, 0.5);
    let t = (-2.0 * tail.ln()).sqrt();
    let numerator = 2.515517 + 0.802853 * t + 0.010328 * t * t;
    let denominator = 1.0 + 1.432788 * t + 0.189269 * t * t + 0.001308 * t * t * t;
    (t - numerator / denominator).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halton_and_lens_points() {
        assert_eq!(halton(1, 2), 0.5);
        assert_eq!(halton(3, 2), 0.75);
        assert!((halton(1, 3) - 1.0 / 3.0).abs() < 1e-15);
        for index in 0..100 {
            assert!(lens_point(index).length() <= 1.0);
        }
    }

    #[test]
    fn normal_quantiles() {
        assert!((normal_quantile(0.9) - 1.645).abs() < 1e-3);
        assert!((normal_quantile(0.95) - 1.960).abs() < 1e-3);
        assert_eq!(normal_quantile(0.0), 0.0);
    }
}
