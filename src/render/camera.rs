//! Camera rays: which ray samples each point of the image.
//!
//! In: a resolved [`Camera`] and the image size. Out: the primary [`Ray`] through any point
//! of the image (pixel centres, anti-aliasing sub-samples) and focal-blur lens rays.
//! Holds: no allocation; `None` where a projection has no ray (outside a fisheye's circle,
//! degenerate vectors), which POV-Ray shows as black.
//!
//! Image point (x, y) in pixels (pixel (i, j) has its centre at (i + 0.5, j + 0.5), row 0 at
//! the top) has image coordinates u = x/W − 0.5 and v = 0.5 − y/H. With D, R, U the
//! camera's direction, right and up, D̂, R̂, Û their unit vectors, a = |R|/|U| (the aspect)
//! and A the camera angle, every projection was measured against POV-Ray 3.7 by rendering
//! a sphere around the camera whose colour encodes the ray direction (all agree within the
//! 1/255 quantisation of those renders):
//! - perspective: from the eye along D + uR + vU; orthographic: from the eye + uR + vU
//!   along D.
//! - fisheye: (x₀, y₀) = (2ua, 2v); no ray when r = |(x₀, y₀)| > 1; θ = r·A/2, φ the polar
//!   angle of (x₀, y₀); direction cos θ D̂ + sin θ (cos φ R̂ + sin φ Û). Default A = 90.
//! - ultra_wide_angle: α = uA, β = vA/a; direction sin α R̂ + sin β Û + cos α cos β D̂
//!   (a point of the surface x² + y² + z² = x²y² + 1).
//! - panoramic: λ = uπ, ψ = vπ; direction cos ψ (sin λ R + cos λ D) + sin ψ U (the vectors'
//!   lengths are the axes of an ellipsoid; `angle` does not matter).
//! - spherical: λ = u·A, ψ = v·A_v; direction cos ψ (sin λ R̂ + cos λ D̂) + sin ψ Û; without
//!   `angle` A = 360 and A_v = 180, with one angle A_v = A/2.
//! - cylinder 1: λ = uA; direction cos λ D̂ + sin λ R̂ + vU. cylinder 2: ψ = vA;
//!   direction cos ψ D̂ + sin ψ Û + uR. cylinder 3: as 1 without the vU term, starting
//!   at the eye + vU. cylinder 4: as 2 without uR, starting at the eye + uR.
//! - omnimax: s = min(a, 1.283458); x₀ = 2ua/s, y₀ = (2v + max(s − 1, 0))/s; no ray when
//!   r = |(x₀, y₀)| > 1; θ = 1.4112689 r − 0.0943896 r³ + 0.2567397 r⁵ (a lens polynomial,
//!   90.16° at r = 1), φ the polar angle of (x₀, y₀), direction as the fisheye's; no ray
//!   either where the direction points more than 45° below D̂ towards −Û (cos θ + sin θ sin φ
//!   < 0), which cuts the bottom of the dome into an egg. So the top of the image is the top
//!   of the dome; up to s = 1.283458 the width spans the dome and beyond it the height spans
//!   from the top to the 45° cut. Measured with 16-bit renders at aspects 0.3 to 4 and
//!   several image sizes: every ray within 2.7e-5 (the renders' quantisation) and no pixel
//!   with or without a ray where POV-Ray has the opposite; `angle` does not matter.
//!
//! Focal blur: all rays through one image point meet on the plane of focus (through
//! `focal_point`, parallel to the image plane); a lens sample (s, t) in the unit disc moves
//! the ray's start by `aperture/4 · (s R̂ + t Û)` and aims it at that meeting point. The
//! quarter was measured: a POV-Ray render with `aperture 0.4` is matched best by a uniform
//! lens disc of radius 0.1 (0.10% of pixels over, against 0.25% and 0.20% for radii 0.08
//! and 0.12, and 2.1% for radius 0.2).
//!
//! Camera `normal { }` (measured, identical renders for `gradient`, `onion` and `wood`):
//! the unit ray direction is perturbed exactly as a surface normal would be, with the
//! pattern evaluated at the image point (u, v, 0); the camera's transformations do not move
//! the pattern.

use crate::geometry::Ray;
use crate::texture::normal::perturbed_normal;
use crate::{
    scene::{Camera, CylinderKind, Projection},
    texture::Normal,
};
use glam::{DVec2, DVec3};
use std::f64::consts::PI;

/// Precomputed camera data for generating primary rays.
#[derive(Clone, Debug)]
pub struct CameraRays {
    projection: Projection,
    location: DVec3,
    direction: DVec3,
    right: DVec3,
    up: DVec3,
    unit_direction: DVec3,
    unit_right: DVec3,
    unit_up: DVec3,
    /// |right| / |up|.
    aspect: f64,
    /// Horizontal angle in radians.
    angle: f64,
    /// Vertical angle in radians (spherical camera).
    vertical_angle: f64,
    width: f64,
    height: f64,
    lens: Option<Lens>,
    /// Camera `normal { }` bending each ray's direction.
    normal: Option<Normal>,
}

/// The focal-blur lens: where rays start on it and where they meet.
#[derive(Clone, Copy, Debug)]
struct Lens {
    /// A quarter of the aperture.
    radius: f64,
    /// Distance from the eye to the plane of focus, along the view direction.
    focal_distance: f64,
}

impl CameraRays {
    /// Camera rays for an image `width` × `height` pixels.
    pub fn new(camera: &Camera, width: u32, height: u32) -> CameraRays {
        let unit_direction = camera.direction.normalize_or(DVec3::Z);
        let up_length = camera.up.length();
        let aspect = if up_length > 0.0 {
            camera.right.length() / up_length
        } else {
            1.0
        };
        let lens = camera.focal_blur.as_ref().and_then(|blur| {
            let focal_distance = (blur.focal_point - camera.location).dot(unit_direction);
            let usable = blur.aperture > 0.0 && focal_distance.is_finite() && blur.max_samples > 0;
            usable.then_some(Lens {
                radius: blur.aperture / 4.0,
                focal_distance,
            })
        });
        CameraRays {
            projection: camera.projection,
            location: camera.location,
            direction: camera.direction,
            right: camera.right,
            up: camera.up,
            unit_direction,
            unit_right: camera.right.normalize_or(DVec3::X),
            unit_up: camera.up.normalize_or(DVec3::Y),
            aspect,
            angle: camera.angle.to_radians(),
            vertical_angle: camera.vertical_angle.to_radians(),
            width: f64::from(width.max(1)),
            height: f64::from(height.max(1)),
            lens,
            normal: camera.normal.clone(),
        }
    }

    /// Whether the camera blurs by depth (rays then need lens samples).
    pub fn has_focal_blur(&self) -> bool {
        self.lens.is_some()
    }

    /// The ray through the centre of pixel (`column`, `row`).
    pub fn ray(&self, column: u32, row: u32) -> Option<Ray> {
        self.ray_at(f64::from(column) + 0.5, f64::from(row) + 0.5)
    }

    /// The ray through image point (`x`, `y`) in pixels (row 0 at the top); `None` where
    /// the projection has no ray or the camera's vectors are degenerate.
    pub fn ray_at(&self, x: f64, y: f64) -> Option<Ray> {
        let u = x / self.width - 0.5;
        let v = 0.5 - y / self.height;
        let (origin, direction) = self.projected(u, v)?;
        let mut direction = direction.try_normalize()?;
        if let Some(normal) = &self.normal {
            direction = perturbed_direction(direction, DVec2::new(u, v), |point, unbent| {
                perturbed_normal(normal, point, None, unbent)
            });
        }
        (origin.is_finite() && direction.is_finite()).then_some(Ray { origin, direction })
    }

    /// The pinhole `ray` moved to lens sample `offset` (in the unit disc), aimed at the point
    /// where it meets the plane of focus. Without focal blur the ray is returned unchanged.
    pub fn through_lens(&self, ray: Ray, offset: DVec2) -> Ray {
        let Some(lens) = self.lens else {
            return ray;
        };
        let along = ray.direction.dot(self.unit_direction);
        if along.abs() < 1e-12 {
            return ray;
        }
        let focus = ray.origin + ray.direction * (lens.focal_distance / along);
        let origin =
            ray.origin + lens.radius * (offset.x * self.unit_right + offset.y * self.unit_up);
        match (focus - origin).try_normalize() {
            Some(direction) => Ray { origin, direction },
            None => ray,
        }
    }

    /// The start and (unnormalised) direction of the ray at image coordinates (u, v).
    fn projected(&self, u: f64, v: f64) -> Option<(DVec3, DVec3)> {
        let (d, r, up) = (self.unit_direction, self.unit_right, self.unit_up);
        Some(match self.projection {
            Projection::Perspective => {
                (self.location, self.direction + u * self.right + v * self.up)
            }
            Projection::Orthographic => {
                (self.location + u * self.right + v * self.up, self.direction)
            }
            Projection::Fisheye => {
                let (x0, y0) = (2.0 * u * self.aspect, 2.0 * v);
                let radius = x0.hypot(y0);
                if radius > 1.0 {
                    return None;
                }
                let theta = radius * self.angle / 2.0;
                let phi = y0.atan2(x0);
                let across = phi.cos() * r + phi.sin() * up;
                (self.location, theta.cos() * d + theta.sin() * across)
            }
            Projection::UltraWideAngle => {
                let alpha = u * self.angle;
                let beta = v * self.angle / self.aspect;
                let direction = alpha.sin() * r + beta.sin() * up + alpha.cos() * beta.cos() * d;
                (self.location, direction)
            }
            // Mesh cameras shoot their rays from faces (`render::mesh_camera`).
            Projection::Mesh => return None,
            Projection::Omnimax => (
                self.location,
                omnimax_direction(u, v, self.aspect, d, r, up)?,
            ),
            Projection::Panoramic => {
                let (longitude, latitude) = (u * PI, v * PI);
                let level = longitude.sin() * self.right + longitude.cos() * self.direction;
                (
                    self.location,
                    latitude.cos() * level + latitude.sin() * self.up,
                )
            }
            Projection::Spherical => {
                let longitude = u * self.angle;
                let latitude = v * self.vertical_angle;
                let level = longitude.sin() * r + longitude.cos() * d;
                (self.location, latitude.cos() * level + latitude.sin() * up)
            }
            Projection::Cylinder(kind) => {
                let around_up = |angle: f64| angle.cos() * d + angle.sin() * r;
                let around_right = |angle: f64| angle.cos() * d + angle.sin() * up;
                match kind {
                    CylinderKind::VerticalFixed => {
                        (self.location, around_up(u * self.angle) + v * self.up)
                    }
                    CylinderKind::HorizontalFixed => {
                        (self.location, around_right(v * self.angle) + u * self.right)
                    }
                    CylinderKind::VerticalMoving => {
                        (self.location + v * self.up, around_up(u * self.angle))
                    }
                    CylinderKind::HorizontalMoving => {
                        (self.location + u * self.right, around_right(v * self.angle))
                    }
                }
            }
        })
    }
}

/// The omnimax lens: the angle off the view direction is this odd polynomial of the
/// distance r from the dome's centre, `θ = Σ cₖ r^(2k+1)` in radians (measured, see the
/// module documentation).
const OMNIMAX_LENS: [f64; 3] = [1.411_268_9, -0.094_389_6, 0.256_739_7];

/// The aspect (|right| / |up|) beyond which an omnimax image stops widening the dome: the
/// image height then spans from the dome's top to its 45° cut at the bottom.
const OMNIMAX_WIDEST_ASPECT: f64 = 1.283_458;

/// The omnimax direction at image coordinates (u, v), or `None` outside the dome's image
/// (see the module documentation for the mapping).
fn omnimax_direction(
    u: f64,
    v: f64,
    aspect: f64,
    direction: DVec3,
    right: DVec3,
    up: DVec3,
) -> Option<DVec3> {
    let scale = aspect.min(OMNIMAX_WIDEST_ASPECT);
    let x0 = 2.0 * u * aspect / scale;
    let y0 = (2.0 * v + (scale - 1.0).max(0.0)) / scale;
    let radius = x0.hypot(y0);
    if radius.is_nan() || radius > 1.0 {
        return None;
    }
    let squared = radius * radius;
    let [linear, cubic, quintic] = OMNIMAX_LENS;
    let theta = radius * (linear + squared * (cubic + squared * quintic));
    let (sin_theta, cos_theta) = theta.sin_cos();
    let (cos_phi, sin_phi) = if radius > 0.0 {
        (x0 / radius, y0 / radius)
    } else {
        (1.0, 0.0)
    };
    if cos_theta + sin_theta * sin_phi < 0.0 {
        return None;
    }
    Some(cos_theta * direction + sin_theta * (cos_phi * right + sin_phi * up))
}

/// Perturbs a camera ray's `direction` by a camera `normal { }`: `perturbation` maps the
/// image point (u, v, 0) and the unperturbed direction to the perturbed direction.
pub fn perturbed_direction(
    direction: DVec3,
    image_point: DVec2,
    perturbation: impl Fn(DVec3, DVec3) -> DVec3,
) -> DVec3 {
    let point = DVec3::new(image_point.x, image_point.y, 0.0);
    perturbation(point, direction)
        .try_normalize()
        .unwrap_or(direction)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::FocalBlur;

    fn camera(projection: Projection) -> Camera {
        Camera {
            projection,
            ..Camera::default()
        }
    }

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
            ..Camera::default()
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

    #[test]
    fn fisheye_edge_is_half_the_angle_and_corners_have_no_ray() {
        let fisheye = Camera {
            angle: 180.0,
            right: DVec3::X,
            ..camera(Projection::Fisheye)
        };
        let rays = CameraRays::new(&fisheye, 100, 100);
        // The right edge of the circle looks sideways (90 degrees off the axis).
        let edge = rays.ray_at(100.0, 50.0).unwrap();
        assert!((edge.direction - DVec3::X).length() < 1e-12);
        assert!(rays.ray(0, 0).is_none());
    }

    /// Directions POV-Ray 3.7 gives some pixels (read from 16-bit renders of a sky coloured
    /// by direction); `None` where it traces no ray.
    #[test]
    fn omnimax_matches_povray_pixels() {
        let default_omnimax = CameraRays::new(&camera(Projection::Omnimax), 160, 120);
        let tall_omnimax = CameraRays::new(
            &Camera {
                right: DVec3::new(0.3, 0.0, 0.0),
                ..camera(Projection::Omnimax)
            },
            100,
            400,
        );
        let between_omnimax = CameraRays::new(
            &Camera {
                right: DVec3::new(1.2, 0.0, 0.0),
                ..camera(Projection::Omnimax)
            },
            480,
            400,
        );
        let cases: [(&CameraRays, u32, u32, Option<[f64; 3]>); 12] = [
            (&default_omnimax, 80, 60, Some([0.00899, 0.29714, 0.9548])),
            (
                &default_omnimax,
                120,
                100,
                Some([0.65313, -0.37981, 0.65512]),
            ),
            (&default_omnimax, 75, 119, Some([-0.0739, -0.6997, 0.7106])),
            (&default_omnimax, 100, 5, Some([0.27413, 0.95862, 0.07701])),
            // Outside the dome, and inside it but below the 45° cut.
            (&default_omnimax, 40, 10, None),
            (&default_omnimax, 60, 119, None),
            (&tall_omnimax, 50, 200, Some([0.01411, -0.01176, 0.99982])),
            (&tall_omnimax, 20, 190, Some([-0.73349, 0.19683, 0.6506])),
            (&tall_omnimax, 70, 230, None),
            (
                &between_omnimax,
                300,
                100,
                Some([0.31075, 0.71655, 0.62448]),
            ),
            (
                &between_omnimax,
                200,
                350,
                Some([-0.21328, -0.59661, 0.77368]),
            ),
            (&between_omnimax, 100, 390, None),
        ];
        for (rays, column, row, expected) in cases {
            let ray = rays.ray(column, row);
            match expected {
                Some(direction) => {
                    let error = (ray.unwrap().direction - DVec3::from(direction)).length();
                    assert!(error < 1e-4, "pixel ({column}, {row}) off by {error}");
                }
                None => assert!(ray.is_none(), "pixel ({column}, {row}) has a ray"),
            }
        }
    }

    #[test]
    fn omnimax_looks_ahead_below_the_centre_and_up_at_the_top() {
        // Wider than 1.283458: the dome's centre is 0.283458 / 2 image heights low.
        let wide = Camera {
            right: DVec3::new(2.0, 0.0, 0.0),
            ..camera(Projection::Omnimax)
        };
        let rays = CameraRays::new(&wide, 200, 100);
        let ahead = rays.ray_at(100.0, 50.0 + 0.283_458 / 2.0 * 100.0).unwrap();
        assert!((ahead.direction - DVec3::Z).length() < 1e-12);
        let top = rays.ray_at(100.0, 0.0).unwrap();
        assert!(top.direction.y > 0.9999 && top.direction.z < 0.0);
        let degenerate = Camera {
            right: DVec3::ZERO,
            ..camera(Projection::Omnimax)
        };
        assert!(CameraRays::new(&degenerate, 4, 4).ray(1, 1).is_none());
    }

    #[test]
    fn ultra_wide_angle_lies_on_its_quartic() {
        let rays = CameraRays::new(&camera(Projection::UltraWideAngle), 160, 120);
        let (_, d) = rays.projected(0.3, -0.2).unwrap();
        assert!((d.length_squared() - (1.0 + d.x * d.x * d.y * d.y)).abs() < 1e-12);
    }

    #[test]
    fn spherical_and_panoramic_angles() {
        let spherical = Camera {
            angle: 360.0,
            vertical_angle: 180.0,
            ..camera(Projection::Spherical)
        };
        let rays = CameraRays::new(&spherical, 4, 2);
        // u = -0.25 looks 90 degrees to the left.
        let left = rays.ray_at(1.0, 1.0).unwrap();
        assert!((left.direction + DVec3::X).length() < 1e-12);
        let top = rays.ray_at(2.0, 0.0).unwrap();
        assert!((top.direction - DVec3::Y).length() < 1e-12);
        let panoramic = Camera {
            right: DVec3::X,
            ..camera(Projection::Panoramic)
        };
        let rays = CameraRays::new(&panoramic, 4, 2);
        let edge = rays.ray_at(0.0, 1.0).unwrap();
        assert!((edge.direction + DVec3::X).length() < 1e-12);
    }

    #[test]
    fn moving_cylinders_shift_the_start() {
        let cylinder = Camera {
            angle: 90.0,
            ..camera(Projection::Cylinder(CylinderKind::HorizontalMoving))
        };
        let rays = CameraRays::new(&cylinder, 2, 2);
        let ray = rays.ray_at(2.0, 1.0).unwrap();
        assert!((ray.origin - DVec3::new(0.665, 0.0, 0.0)).length() < 1e-12);
        assert!((ray.direction - DVec3::Z).length() < 1e-12);
    }

    #[test]
    fn lens_rays_meet_on_the_plane_of_focus() {
        let blurred = Camera {
            focal_blur: Some(FocalBlur {
                aperture: 0.5,
                focal_point: DVec3::new(0.0, 0.0, 4.0),
                min_samples: 4,
                max_samples: 16,
                confidence: 0.9,
                variance: 1.0 / 128.0,
            }),
            ..Camera::default()
        };
        let rays = CameraRays::new(&blurred, 10, 10);
        let pinhole = rays.ray(2, 7).unwrap();
        let moved = rays.through_lens(pinhole, DVec2::new(1.0, 0.0));
        assert!((moved.origin - DVec3::new(0.125, 0.0, 0.0)).length() < 1e-12);
        let meet = |ray: Ray| ray.origin + ray.direction * ((4.0 - ray.origin.z) / ray.direction.z);
        assert!((meet(pinhole) - meet(moved)).length() < 1e-12);
    }

    #[test]
    fn camera_normal_perturbs_directions() {
        let bent = perturbed_direction(DVec3::Z, DVec2::new(0.1, 0.2), |point, direction| {
            direction + point
        });
        assert!((bent - DVec3::new(0.1, 0.2, 1.0).normalize()).length() < 1e-12);
    }
}
