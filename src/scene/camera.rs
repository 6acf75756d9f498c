//! The evaluated camera: projection type, resolved vectors and focal blur.
//!
//! In: nothing (data definition). Out: [`Camera`], [`Projection`], [`FocalBlur`]. Holds:
//! vectors are final (look_at, angle, sky and transformations applied); angles in degrees.

use super::uv_faces::UvFaces;
use crate::texture::Normal;
use glam::DVec3;
use std::sync::Arc;

/// The kind of projection a camera makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Projection {
    /// Rays fan out from `location` through the image plane.
    Perspective,
    /// Parallel rays along `direction`; the image spans `right` by `up`.
    Orthographic,
    /// Polar projection onto a circle: the distance from the image centre is the angle from
    /// `direction` (`angle` across the circle).
    Fisheye,
    /// Like fisheye but onto a rectangle (`x²+y²+z² = x²y² + 1`).
    UltraWideAngle,
    /// A 180 degree fisheye squeezed vertically, as for Omnimax domes.
    Omnimax,
    /// Cylindrical equirectangular: 180 degrees across, 90 degrees high.
    Panoramic,
    /// Projection onto a cylinder; the number (1 to 4) is POV-Ray's cylinder type.
    Cylinder(CylinderKind),
    /// Rectangular longitude/latitude coordinates on a sphere.
    Spherical,
    /// `mesh_camera`: each pixel's rays start on faces of meshes (`Camera::mesh`).
    Mesh,
}

/// The four cylindrical camera types of POV-Ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CylinderKind {
    /// 1: vertical cylinder, fixed viewpoint.
    VerticalFixed,
    /// 2: horizontal cylinder, fixed viewpoint.
    HorizontalFixed,
    /// 3: vertical cylinder, viewpoint moving along the axis.
    VerticalMoving,
    /// 4: horizontal cylinder, viewpoint moving along the axis.
    HorizontalMoving,
}

impl CylinderKind {
    /// The kind for POV-Ray's `cylinder N` number; `None` outside 1 to 4.
    pub fn from_number(number: f64) -> Option<CylinderKind> {
        match number {
            1.0 => Some(CylinderKind::VerticalFixed),
            2.0 => Some(CylinderKind::HorizontalFixed),
            3.0 => Some(CylinderKind::VerticalMoving),
            4.0 => Some(CylinderKind::HorizontalMoving),
            _ => None,
        }
    }
}

/// A camera with all vectors resolved (look_at, angle, sky and transformations applied).
///
/// A perspective ray through image coordinates (u, v) in [-0.5, 0.5] (v up) has direction
/// `direction + u * right + v * up`, starting at `location`. An orthographic ray starts at
/// `location + u * right + v * up` and runs along `direction`. The other projections are
/// described in `render::camera`.
#[derive(Clone, Debug)]
pub struct Camera {
    /// Projection type.
    pub projection: Projection,
    /// The eye point (centre of the image plane for orthographic).
    pub location: DVec3,
    /// From the eye to the centre of the image plane.
    pub direction: DVec3,
    /// The full width of the image plane (POV-Ray's default is `<1.33, 0, 0>`).
    pub right: DVec3,
    /// The full height of the image plane.
    pub up: DVec3,
    /// Horizontal viewing angle in degrees for the non-planar projections.
    pub angle: f64,
    /// Vertical viewing angle in degrees of the spherical camera.
    pub vertical_angle: f64,
    /// Depth of field, when `aperture` and `blur_samples` ask for it.
    pub focal_blur: Option<FocalBlur>,
    /// Camera `normal { }`: bends every ray's direction as if it were a surface normal.
    pub normal: Option<Normal>,
    /// The faces of a `mesh_camera` (with [`Projection::Mesh`]).
    pub mesh: Option<Arc<MeshCamera>>,
}

impl Default for Camera {
    fn default() -> Self {
        Camera {
            projection: Projection::Perspective,
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            angle: DEFAULT_ANGLE,
            vertical_angle: DEFAULT_ANGLE / 2.0,
            focal_blur: None,
            normal: None,
            mesh: None,
        }
    }
}

/// POV-Ray's camera angle when the scene gives none.
pub const DEFAULT_ANGLE: f64 = 90.0;

/// Focal blur: rays start from points on a lens disc around the eye (its size set by
/// `aperture`) and meet again on the plane of focus.
#[derive(Clone, Debug, PartialEq)]
pub struct FocalBlur {
    /// Size of the lens (POV-Ray's arbitrary unit; see `render::camera`).
    pub aperture: f64,
    /// A point on the plane of focus (the plane through it parallel to the image plane).
    pub focal_point: DVec3,
    /// Samples taken before the confidence test may stop sampling.
    pub min_samples: u32,
    /// Largest number of samples per pixel.
    pub max_samples: u32,
    /// Probability that the mean is within the variance when sampling stops (default 0.9).
    pub confidence: f64,
    /// Accepted variance of the samples' mean (default 1/128).
    pub variance: f64,
}

/// `mesh_camera { rays_per_pixel distribution [max_distance] mesh { .. } .. }`: rays start
/// at the centres of mesh faces and run along the faces' normals.
#[derive(Clone, Debug)]
pub struct MeshCamera {
    /// Rays shot into each pixel (at least 1); their colours are averaged.
    pub rays_per_pixel: u32,
    /// How pixels are assigned to faces.
    pub distribution: MeshDistribution,
    /// Rays do not see objects farther than this; 0 means no limit.
    pub max_distance: f64,
    /// The faces of each `mesh`, in the order written, in world space (distributions 0-2).
    pub meshes: Vec<Vec<CameraFace>>,
    /// The faces of all meshes indexed by uv coordinates (distribution 3; empty otherwise).
    pub uv_faces: UvFaces,
    /// `smooth` (distribution 3 only): rays run along the corner normals interpolated at
    /// the ray's origin instead of the face normal.
    pub smooth: bool,
    /// How far ray origins move along the face normals (the camera's `location` z).
    pub offset: f64,
    /// Rays run against the face normals (the camera's `direction` z is negative).
    pub reversed: bool,
}

/// A `max_distance` at or below this means no limit (POV-Ray: "greater than EPSILON").
const MESH_REACH_EPSILON: f64 = 1e-10;

impl MeshCamera {
    /// How far the camera's rays see objects, from their origin: `max_distance` when it is
    /// given (above a tiny epsilon), else infinitely far.
    pub fn reach(&self) -> f64 {
        if self.max_distance > MESH_REACH_EPSILON {
            self.max_distance
        } else {
            f64::INFINITY
        }
    }
}

/// POV-Ray's mesh camera distribution types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshDistribution {
    /// 0: ray r of a pixel uses mesh r; the pixel's number picks the face.
    PerMesh,
    /// 1: the meshes' faces are summed into one list and the pixel's number picks the face;
    /// only the first ray of a pixel is shot, as in POV-Ray.
    Summed,
    /// 2: the image is split into side-by-side columns, one per mesh.
    SideBySide,
    /// 3: the pixel's position in the image, as uv coordinates, picks the first face whose
    /// uv triangle holds it and the point on that face the ray starts from.
    UvMapped,
}

/// One face of a camera mesh: where its ray starts and where it points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFace {
    /// The face's centroid.
    pub centre: DVec3,
    /// Unit normal: `(c − a) × (b − a)` for corners a, b, c.
    pub normal: DVec3,
}
