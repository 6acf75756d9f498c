//! Camera rays: which ray samples each pixel.
//!
//! In: a resolved [`Camera`] and the image size. Out: one primary [`Ray`] per pixel centre.
//! Holds: pixel (i, j) of a W×H image samples image coordinates u = (i + 0.5)/W − 0.5 and
//! v = 0.5 − (j + 0.5)/H (row 0 at the top). A perspective ray starts at `location` along
//! `normalize(direction + u right + v up)`; an orthographic ray starts at
//! `location + u right + v up` along `normalize(direction)`. Checked against POV-Ray 3.7:
//! the hit masks of off-centre spheres agree pixel for pixel for both projections.

use crate::geometry::Ray;
use crate::scene::{Camera, Projection};
use glam::DVec3;

/// Precomputed camera data for generating primary rays.
#[derive(Clone, Debug)]
pub struct CameraRays {
    projection: Projection,
    location: DVec3,
    direction: DVec3,
    right: DVec3,
    up: DVec3,
    width: f64,
    height: f64,
}

impl CameraRays {
    /// Camera rays for an image `width` × `height` pixels.
    pub fn new(camera: &Camera, width: u32, height: u32) -> CameraRays {
        CameraRays {
            projection: camera.projection,
            location: camera.location,
            direction: camera.direction,
            right: camera.right,
            up: camera.up,
            width: f64::from(width.max(1)),
            height: f64::from(height.max(1)),
        }
    }

    /// The ray through the centre of pixel (`column`, `row`); `None` when the camera's
    /// vectors are degenerate (zero or non-finite direction).
    pub fn ray(&self, column: u32, row: u32) -> Option<Ray> {
        let u = (f64::from(column) + 0.5) / self.width - 0.5;
        let v = 0.5 - (f64::from(row) + 0.5) / self.height;
        let (origin, direction) = match self.projection {
            Projection::Perspective => {
                (self.location, self.direction + u * self.right + v * self.up)
            }
            Projection::Orthographic => {
                (self.location + u * self.right + v * self.up, self.direction)
            }
        };
        let direction = direction.try_normalize()?;
        (origin.is_finite() && direction.is_finite()).then_some(Ray { origin, direction })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_pixels_of_default_camera() {
        let camera = Camera {
            location: DVec3::new(0.0, 0.0, -5.0),
            ..Camera::default()
        };
        let rays = CameraRays::new(&camera, 2, 2);
        let top_left = rays.ray(0, 0).unwrap();
        let expected = DVec3::new(-0.25 * 1.33, 0.25, 1.0).normalize();
        assert!((top_left.direction - expected).length() < 1e-15);
        assert_eq!(top_left.origin, camera.location);
    }

    #[test]
    fn orthographic_offsets_origins() {
        let camera = Camera {
            projection: Projection::Orthographic,
            location: DVec3::new(1.0, 2.0, -10.0),
            direction: DVec3::new(0.0, 0.0, 3.0),
            right: DVec3::new(4.0, 0.0, 0.0),
            up: DVec3::new(0.0, 3.0, 0.0),
        };
        let rays = CameraRays::new(&camera, 4, 3);
        let ray = rays.ray(3, 2).unwrap();
        assert_eq!(ray.direction, DVec3::Z);
        assert!((ray.origin - DVec3::new(2.5, 1.0, -10.0)).length() < 1e-12);
    }

    #[test]
    fn degenerate_camera_gives_no_ray() {
        let camera = Camera {
            direction: DVec3::ZERO,
            right: DVec3::ZERO,
            up: DVec3::ZERO,
            ..Camera::default()
        };
        assert!(CameraRays::new(&camera, 1, 1).ray(0, 0).is_none());
        let nan = Camera {
            location: DVec3::splat(f64::NAN),
            ..Camera::default()
        };
        assert!(CameraRays::new(&nan, 1, 1).ray(0, 0).is_none());
    }
}
