//! The mesh camera: rays start on mesh faces and run along their normals.
//!
//! In: a [`MeshCamera`] (faces in world space), the image size and a pixel. Out: the mean
//! colour of the pixel's rays, or `None` when no face belongs to the pixel (the pixel is
//! then black, like a pixel a projection has no ray for). Holds: no allocation.
//!
//! Rules (POV-Ray 3.7 manual, "Mesh projection", and measurements of POV-Ray where it
//! departs from the manual): a pixel's face number is p = width · y + column with
//! y = max(row − 1, 0), row 0 at the top — POV-Ray shows the mesh one row lower than the
//! manual says, rows 0 and 1 both showing the faces of the mesh's first row.
//! Distribution 0: ray r of the pixel uses face p of mesh r. Distribution 1: the faces of
//! all meshes form one list and the pixel's one ray uses face p (POV-Ray shoots no more
//! rays per pixel, whatever the count says). Distribution 2: the image is cut into as many
//! side-by-side parts of width w = width / meshes as there are meshes (the last mesh also
//! takes the columns left over), one ray per pixel; the face is w · y + column with the
//! image's column, not the part's. Distribution 3: the pixel picks the uv coordinates
//! u = x / width, v = 1 − y / height, with x the column (the last column: column − 0.5)
//! and y the row (the top row: 0.5); the ray starts from the point with those uv
//! coordinates on the first face whose uv triangle holds it. Rays without a face are not
//! shot and do not count in the mean. A ray starts `offset` along the normal (the camera's
//! `location` z) and runs along the normal, or against it when the camera's `direction` z
//! is negative; the normal is the face normal, or with `smooth` (distribution 3) the
//! corner normals interpolated at the ray's origin.

use crate::geometry::Ray;
use crate::scene::{CameraFace, MeshCamera, MeshDistribution};
use glam::{DVec2, DVec3};

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
    if camera.distribution == MeshDistribution::UvMapped {
        return uv_ray(camera, width, height, column, row).map(|ray| trace(&ray));
    }
    let mut sum = DVec3::ZERO;
    let mut count = 0u32;
    for ray_number in 0..camera.rays_per_pixel {
        let Some(face) = pixel_face(camera, width, column, row, ray_number) else {
            continue;
        };
        if let Some(ray) = face_ray(camera, face) {
            sum += trace(&ray);
            count += 1;
        }
    }
    (count > 0).then(|| sum / f64::from(count))
}

/// The row POV-Ray numbers faces by for image row `row`. Measured: POV-Ray takes the
/// integer part (rounding toward zero) of the pixel centre's row less one, so row 0 and
/// row 1 both show the faces of mesh row 0 and every lower row shows the faces of the
/// row above it.
fn face_row(row: u32) -> u64 {
    u64::from(row.saturating_sub(1))
}

/// The face ray `ray_number` of pixel (`column`, `row`) starts from, if any.
fn pixel_face(
    camera: &MeshCamera,
    width: u32,
    column: u32,
    row: u32,
    ray_number: u32,
) -> Option<&CameraFace> {
    let pixel = face_row(row) * u64::from(width) + u64::from(column);
    match camera.distribution {
        MeshDistribution::PerMesh => camera
            .meshes
            .get(ray_number as usize)?
            .get(usize::try_from(pixel).ok()?),
        MeshDistribution::Summed => {
            // Measured: POV-Ray shoots only the first ray of a pixel in this distribution.
            if ray_number > 0 {
                return None;
            }
            let mut index = usize::try_from(pixel).ok()?;
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
            let meshes = u32::try_from(camera.meshes.len()).ok()?;
            let column_width = (width / meshes).max(1);
            // Measured: the columns left over when the width does not divide belong to
            // the last mesh, and a column's face is numbered with the image's column,
            // not the column within the mesh's part of the image.
            let mesh = (column / column_width).min(meshes - 1);
            let index = face_row(row) * u64::from(column_width) + u64::from(column);
            camera
                .meshes
                .get(mesh as usize)?
                .get(usize::try_from(index).ok()?)
        }
        // Uv-mapped pixels find a point on a face, not a face number (see `uv_ray`).
        MeshDistribution::UvMapped => None,
    }
}

/// The uv coordinates distribution 3 looks up for pixel (`column`, `row`). Measured:
/// u = x / width and v = 1 − y / height with x the column and y the row, except that the
/// last column takes x = column − 0.5 and the top row y = 0.5.
fn pixel_uv(width: u32, height: u32, column: u32, row: u32) -> DVec2 {
    let x = if column + 1 == width {
        f64::from(column) - 0.5
    } else {
        f64::from(column)
    };
    let y = if row == 0 { 0.5 } else { f64::from(row) };
    DVec2::new(x / f64::from(width), 1.0 - y / f64::from(height))
}

/// Distribution 3: the ray from the point of the first face whose uv triangle holds the
/// pixel's uv coordinates, along the face normal (or the interpolated corner normals with
/// `smooth`); `None` when no face holds them.
fn uv_ray(camera: &MeshCamera, width: u32, height: u32, column: u32, row: u32) -> Option<Ray> {
    let hit = camera.uv_faces.find(pixel_uv(width, height, column, row))?;
    let normal = if camera.smooth {
        hit.smooth_normal()
    } else {
        hit.face.normal
    };
    ray_along(camera, hit.position(), normal)
}

/// The ray leaving `face`; `None` for a face without a normal.
fn face_ray(camera: &MeshCamera, face: &CameraFace) -> Option<Ray> {
    ray_along(camera, face.centre, face.normal)
}

/// The ray from `point` along the unit `normal` (against it when the camera is reversed),
/// starting the camera's offset along the normal; `None` for a zero normal.
fn ray_along(camera: &MeshCamera, point: DVec3, normal: DVec3) -> Option<Ray> {
    if normal == DVec3::ZERO {
        return None;
    }
    let direction = if camera.reversed { -normal } else { normal };
    let origin = point + camera.offset * normal;
    origin.is_finite().then_some(Ray { origin, direction })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{UvFace, UvFaces};

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
            uv_faces: UvFaces::default(),
            smooth: false,
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
        assert_eq!(origin_mean(&camera, 2, 3, 0, 2), None);
    }

    #[test]
    fn rows_below_the_top_show_the_faces_of_the_row_above() {
        let meshes = vec![(0..6).map(|x| face(f64::from(x))).collect()];
        let camera = camera(MeshDistribution::PerMesh, 1, meshes);
        let rows: Vec<_> = (0..3)
            .map(|row| origin_mean(&camera, 2, 3, 1, row))
            .collect();
        assert_eq!(rows, [Some(1.0), Some(1.0), Some(3.0)]);
    }

    #[test]
    fn summed_meshes_continue_each_other_with_one_ray() {
        let meshes = vec![vec![face(0.0), face(1.0)], vec![face(2.0), face(3.0)]];
        let camera = camera(MeshDistribution::Summed, 2, meshes);
        // A 2x3 image: row 2 takes faces 2 and 3 from the second mesh, and the second
        // ray (faces 6 and 7) is not shot.
        assert_eq!(origin_mean(&camera, 2, 3, 0, 0), Some(0.0));
        assert_eq!(origin_mean(&camera, 2, 3, 0, 2), Some(2.0));
        assert_eq!(origin_mean(&camera, 2, 3, 1, 2), Some(3.0));
    }

    #[test]
    fn side_by_side_meshes_number_faces_by_the_image_column() {
        let meshes = vec![
            (0..6).map(|x| face(f64::from(x))).collect(),
            (10..16).map(|x| face(f64::from(x))).collect(),
        ];
        let camera = camera(MeshDistribution::SideBySide, 1, meshes);
        // A 5x3 image: parts 2 wide, the fifth column belongs to the second mesh.
        let row = |row| -> Vec<_> { (0..5).map(|c| origin_mean(&camera, 5, 3, c, row)).collect() };
        let faces = |list: [f64; 5]| list.map(Some).to_vec();
        assert_eq!(row(0), faces([0.0, 1.0, 12.0, 13.0, 14.0]));
        assert_eq!(row(1), faces([0.0, 1.0, 12.0, 13.0, 14.0]));
        let mut last = faces([2.0, 3.0, 14.0, 15.0, 0.0]);
        last[4] = None; // face 6 of a mesh of 6
        assert_eq!(row(2), last);
    }

    #[test]
    fn uv_mapped_pixels_find_their_point_on_the_mesh() {
        // Two faces covering the uv square, placed at 10 times their uv coordinates.
        let face = |uvs: [DVec2; 3]| UvFace {
            corners: uvs.map(|uv| (uv * 10.0).extend(0.0)),
            corner_normals: [DVec3::Z; 3],
            normal: DVec3::Z,
            uvs,
        };
        let mut camera = camera(MeshDistribution::UvMapped, 1, Vec::new());
        camera.uv_faces = UvFaces::new(vec![
            face([DVec2::ZERO, DVec2::X, DVec2::ONE]),
            face([DVec2::ZERO, DVec2::ONE, DVec2::Y]),
        ]);
        let origin = |column, row| {
            mesh_pixel(&camera, 4, 3, column, row, &|ray| ray.origin).map(|o| o.truncate())
        };
        // Measured in POV-Ray at 4x3: x = 0, 2.5, 5, 6.25 and y = 8.33, 6.67, 3.33.
        let close = |a: Option<DVec2>, b: DVec2| (a.unwrap() - b).length() < 1e-9;
        assert!(close(origin(0, 0), DVec2::new(0.0, 10.0 - 10.0 / 6.0)));
        assert!(close(origin(1, 1), DVec2::new(2.5, 10.0 - 10.0 / 3.0)));
        assert!(close(origin(3, 2), DVec2::new(6.25, 10.0 - 20.0 / 3.0)));
        // A one-column image looks up u = -0.5 / 1, outside every face.
        assert_eq!(mesh_pixel(&camera, 1, 1, 0, 0, &|_| DVec3::ONE), None);
    }
}
