//! Meshes in the world: triangles hit and degenerate ones skipped (alone and in CSG), instances
//! sharing one prepared geometry under their own transforms, corner uvs and textures kept
//! inside CSG, and textures shared between placements.

use super::support::{all_hits, csg, distances, scene_of, slab};
use crate::geometry::{Ray, World};
use crate::scene::{CsgOperation, Mesh, MeshTriangle, Object, Shape};
use glam::{DVec2, DVec3};
use std::sync::Arc;

#[test]
fn mesh_triangles_are_hit_and_degenerate_ones_skipped() {
    let triangle = |z: f64| MeshTriangle {
        corners: [
            DVec3::new(-1.0, -1.0, z),
            DVec3::new(1.0, -1.0, z),
            DVec3::new(0.0, 1.0, z),
        ],
        normals: None,
    };
    let degenerate = MeshTriangle {
        corners: [DVec3::ZERO; 3],
        normals: Some([DVec3::ZERO; 3]),
    };
    let mesh = Object::new(Shape::Mesh(Arc::new(Mesh::from_triangles(&[
        triangle(1.0),
        degenerate,
        triangle(2.0),
    ]))));
    let along_z = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
    assert_eq!(distances(vec![mesh.clone()], along_z), vec![6.0, 7.0]);
    let in_csg = csg(CsgOperation::Intersection, vec![mesh, slab(-5.0, 5.0)]);
    assert_eq!(distances(vec![in_csg], along_z), vec![6.0, 7.0]);
}

#[test]
fn mesh_instances_share_geometry_and_keep_their_transforms() {
    let mesh = Arc::new(Mesh::from_triangles(&[MeshTriangle {
        corners: [
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ],
        normals: None,
    }]));
    let mut near = Object::new(Shape::Mesh(Arc::clone(&mesh)));
    near.set_transform(crate::math::Transform::translation(DVec3::new(
        0.0, 0.0, 1.0,
    )));
    let mut far = Object::new(Shape::Mesh(Arc::clone(&mesh)));
    far.set_transform(
        crate::math::Transform::scaling(DVec3::new(2.0, 2.0, 2.0))
            .unwrap()
            .then(&crate::math::Transform::translation(DVec3::new(
                0.0, 0.0, 3.0,
            ))),
    );
    let world = World::build(&scene_of(vec![near, far]));
    assert_eq!(world.object_count(), 2);
    let along_z = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
    let hits = all_hits(&world, &along_z);
    let found: Vec<f64> = hits
        .iter()
        .map(|h| (h.distance * 1e9).round() / 1e9)
        .collect();
    assert_eq!(found, vec![6.0, 8.0]);
    assert!(hits
        .iter()
        .all(|h| h.normal.abs_diff_eq(DVec3::Z, 1e-12) || h.normal.abs_diff_eq(-DVec3::Z, 1e-12)));
    // The scaled copy reaches further out than the plain one.
    let off_axis = Ray::new(DVec3::new(1.5, -1.5, -5.0), DVec3::Z);
    let found: Vec<f64> = all_hits(&world, &off_axis)
        .iter()
        .map(|h| h.distance)
        .collect();
    assert_eq!(found.len(), 1);
    assert!((found[0] - 8.0).abs() < 1e-9);
}

/// A one-triangle mesh in the z = 0 plane whose corners have uv coordinates and the texture
/// slots 1, 2, 1 (two marked textures), with a uv-mapped texture of its own.
fn textured_triangle_mesh() -> Arc<Mesh> {
    use super::support::marked_texture;
    use crate::{
        math::Colour,
        texture::{Pigment, Texture},
    };
    let mut mesh = Mesh::from_triangles(&[MeshTriangle {
        corners: [
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(-1.0, 1.0, 0.0),
        ],
        normals: None,
    }]);
    mesh.uvs = vec![DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(0.0, 2.0)];
    mesh.face_uvs = vec![[0, 1, 2]];
    mesh.face_textures = vec![[1, 2, 1]];
    let uv_mapped = Arc::new(Texture {
        pigment: Pigment::UvMapped(Box::new(Pigment::Solid(Colour::rgb(0.5, 0.0, 0.0)))),
        ..Texture::default()
    });
    mesh.textures = vec![uv_mapped, marked_texture(0.25)];
    Arc::new(mesh)
}

#[test]
fn mesh_triangles_in_csg_keep_corner_uvs_and_textures() {
    let mesh = Object::new(Shape::Mesh(textured_triangle_mesh()));
    let in_csg = csg(CsgOperation::Intersection, vec![mesh, slab(-5.0, 5.0)]);
    let world = World::build(&scene_of(vec![in_csg]));
    // At the point with barycentric weights (0.5, 0.25, 0.25).
    let ray = Ray::new(DVec3::new(-0.5, -0.5, -5.0), DVec3::Z);
    let hit = world.first_hit(&ray, 0.0, f64::INFINITY).expect("a hit");
    let uv = hit.uv.expect("uv coordinates in CSG");
    assert!((uv - DVec2::new(1.0, 0.5)).length() < 1e-12, "{uv}");
    let blend = hit.blend.expect("corner textures blend in CSG");
    let parts: Vec<(u32, f64)> = blend.iter().collect();
    assert_eq!(parts.len(), 3);
    assert_eq!(parts[0].0, parts[2].0);
    assert_ne!(parts[0].0, parts[1].0);
    let expected = [0.5, 0.25, 0.25];
    assert!(parts
        .iter()
        .zip(expected)
        .all(|((_, found), wanted)| (found - wanted).abs() < 1e-12));
}

#[test]
fn mesh_textures_are_shared_between_placements() {
    let mesh = textured_triangle_mesh();
    let placed = |z: f64| {
        let mut object = Object::new(Shape::Mesh(Arc::clone(&mesh)));
        object.set_transform(crate::math::Transform::translation(DVec3::new(0.0, 0.0, z)));
        object
    };
    let in_csg = csg(
        CsgOperation::Intersection,
        vec![placed(3.0), slab(-5.0, 5.0)],
    );
    let world = World::build(&scene_of(vec![placed(1.0), placed(2.0), in_csg]));
    // The default texture (the meshes' own and the slab's) and the solid triangle texture
    // do not depend on position, so every placement shares them; the uv-mapped one does, so
    // each moved placement has its own copy: 2 + 3 materials.
    assert_eq!(world.materials.len(), 5);
}
