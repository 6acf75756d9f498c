//! The mesh camera: rays start at the centres of mesh faces and run along their normals.
//!
//! In: a [`MeshCamera`] (faces in world space), the image size and a pixel. Out: the mean
//! colour of the pixel's rays, or `None` when no face belongs to the pixel (the pixel is
//! then black, like a pixel a projection has no ray for). Holds: no allocation.
//!
//! Rules (POV-Ray 3.7 manual, "Mesh projection"): pixel number p = width · row + column
//! (row 0 at the top). Distribution 0: ray r of the pixel uses face p of mesh r.
//! Distribution 1: the faces of all meshes form one list and ray r uses face
//! r · width · height + p. Distribution 2: the image is cut into as many side-by-side
//! columns of width w as there are meshes, one ray per pixel; the manual has each column
//! number its pixels from its own left edge, but POV-Ray takes face
//! `row · w + column − w` (measured with 2 and 4 meshes: mesh k appears k − 1 rows
//! shifted), except in the first mesh's top row, which shows its own faces. Rays without a face are not shot and do not count in the mean. A ray
//! starts `offset` along the face normal from the centroid (the camera's `location` z) and
//! runs along the normal, or against it when the camera's `direction` z is negative.

use crate::geometry::Ray;
use crate::scene::{CameraFace, MeshCamera, MeshDistribution};
use glam::DVec3;

/// The mean colour `trace` gives the rays of pixel (`column`, `row`) of an image
/// `width` × `height`; `None` when the pixel has no face.
pub fn mesh_pixel(
    camera: &MeshCamera,
    width: u32,
    height: u32,
    column: u32,
    row: u32,
    trace: &dyn Fn(&Ray) -> DVec3,
) -> Option<DVec3> {
    let mut sum = DVec3::ZERO;
    let mut count = 0u32;
    for ray_number in 0..camera.rays_per_pixel {
        let Some(face) = pixel_face(camera, width, height, column, row, ray_number) else {
            continue;
        };
        if let Some(ray) = face_ray(camera, face) {
            sum += trace(&ray);
            count += 1;
        }
    }
    (count > 0).then(|| sum / f64::from(count))
}

/// The face ray `ray_number` of pixel (`column`, `row`) starts from, if any.
fn pixel_face(
    camera: &MeshCamera,
    width: u32,
    height: u32,
    column: u32,
    row: u32,
    ray_number: u32,
) -> Option<&CameraFace> {
    let pixel = u64::from(row) * u64::from(width) + u64::from(column);
    match camera.distribution {
        MeshDistribution::PerMesh => camera
            .meshes
            .get(ray_number as usize)?
            .get(usize::try_from(pixel).ok()?),
        MeshDistribution::Summed => {
            let image = u64::from(width) * u64::from(height);
            let mut index = usize::try_from(u64::from(ray_number) * image + pixel).ok()?;
            for faces in &camera.meshes {
                match faces.get(index) {
                    Some(face) => return Some(face),
                    None => index -= faces.len(),
                }
            }
            None
        }
        MeshDistribution::SideBySide => {
            if ray_number > 0 {
                return None;
            }
            let columns = u32::try_from(camera.meshes.len()).ok()?;
            let column_width = (width / columns).max(1);
            let mesh = column / column_width;
            // Measured: the face is row · column_width + column − column_width with the
            // image's column, so mesh k shows its rows k − 1 lower; the top row of the
            // first mesh, where that is negative, shows its own faces.
            let row_start = i64::from(row) * i64::from(column_width);
            let shifted = row_start + i64::from(column) - i64::from(column_width);
            let local = if shifted >= 0 {
                shifted
            } else {
                row_start + i64::from(column - mesh * column_width)
            };
            camera
                .meshes
                .get(mesh as usize)?
                .get(usize::try_from(local).ok()?)
        }
    }
}

/// The ray leaving `face`; `None` for a face without a normal.
fn face_ray(camera: &MeshCamera, face: &CameraFace) -> Option<Ray> {
    if face.normal == DVec3::ZERO {
        return None;
    }
    let direction = if camera.reversed {
        -face.normal
    } else {
        face.normal
    };
    let origin = face.centre + camera.offset * face.normal;
    origin.is_finite().then_some(Ray { origin, direction })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn face(x: f64) -> CameraFace {
        CameraFace {
            centre: DVec3::new(x, 0.0, 0.0),
            normal: DVec3::Z,
        }
    }

    fn camera(
        distribution: MeshDistribution,
        rays: u32,
        meshes: Vec<Vec<CameraFace>>,
    ) -> MeshCamera {
        MeshCamera {
            rays_per_pixel: rays,
            distribution,
            max_distance: 0.0,
            meshes,
            offset: 0.0,
            reversed: false,
        }
    }

    /// The mean of the traced rays' origin x, as the colour's red.
    fn origin_mean(
        camera: &MeshCamera,
        width: u32,
        height: u32,
        column: u32,
        row: u32,
    ) -> Option<f64> {
        mesh_pixel(camera, width, height, column, row, &|ray| {
            DVec3::splat(ray.origin.x)
        })
        .map(|colour| colour.x)
    }

    #[test]
    fn per_mesh_rays_average_the_meshes_faces() {
        let meshes = vec![vec![face(0.0), face(1.0)], vec![face(10.0)]];
        let camera = camera(MeshDistribution::PerMesh, 2, meshes);
        assert_eq!(origin_mean(&camera, 2, 1, 0, 0), Some(5.0));
        // The second mesh has no face for pixel 1: only the first ray counts.
        assert_eq!(origin_mean(&camera, 2, 1, 1, 0), Some(1.0));
        assert_eq!(origin_mean(&camera, 2, 2, 0, 1), None);
    }

    #[test]
    fn summed_meshes_continue_each_other() {
        let meshes = vec![vec![face(0.0), face(1.0), face(2.0)], vec![face(3.0)]];
        let camera = camera(MeshDistribution::Summed, 2, meshes);
        // A 2x1 image: pixel 0 takes faces 0 and 2, pixel 1 faces 1 and 3.
        assert_eq!(origin_mean(&camera, 2, 1, 0, 0), Some(1.0));
        assert_eq!(origin_mean(&camera, 2, 1, 1, 0), Some(2.0));
    }

    #[test]
    fn side_by_side_meshes_split_the_image() {
        let meshes = vec![vec![face(0.0), face(1.0)], vec![face(5.0), face(6.0)]];
        let camera = camera(MeshDistribution::SideBySide, 1, meshes);
        // The first mesh's top row shows its own face; below, rows show the row above.
        assert_eq!(origin_mean(&camera, 2, 2, 0, 0), Some(0.0));
        assert_eq!(origin_mean(&camera, 2, 2, 0, 1), Some(0.0));
        assert_eq!(origin_mean(&camera, 2, 2, 1, 0), Some(5.0));
        assert_eq!(origin_mean(&camera, 2, 2, 1, 1), Some(6.0));
    }
}
