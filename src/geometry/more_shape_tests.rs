//! World-level tests of the shapes added after the basic ones: meshes, prisms, polynomial
//! surfaces, `clipped_by`, and the object flags carried by materials.

use super::test_support::{all_hits, csg, scene_of};
use super::{Ray, World};
use crate::scene::{CsgOperation, Extrusion, Mesh, MeshTriangle, Object, Shape};
use glam::{DVec2, DVec3};
use std::sync::Arc;

fn distances(objects: Vec<Object>, ray: Ray) -> Vec<f64> {
    let world = World::build(&scene_of(objects));
    all_hits(&world, &ray)
        .iter()
        .map(|hit| (hit.distance * 1e9).round() / 1e9)
        .collect()
}

fn unit_sphere() -> Object {
    Object::new(Shape::Sphere {
        centre: DVec3::ZERO,
        radius: 1.0,
    })
}

fn slab(low: f64, high: f64) -> Object {
    Object::new(Shape::Box {
        corner1: DVec3::new(low, -5.0, -5.0),
        corner2: DVec3::new(high, 5.0, 5.0),
    })
}

#[test]
fn clipped_sphere_keeps_only_the_inside_part() {
    let along_x = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    let mut sphere = unit_sphere();
    sphere.clipped_by.push(slab(-0.5, 5.0));
    // The front of the sphere (x = -1) is clipped away; the clip's own face is invisible.
    assert_eq!(distances(vec![sphere.clone()], along_x), vec![6.0]);
    // A clipped object subtracted from a slab: inside the clipped sphere is removed only
    // where the clip holds.
    let difference = csg(
        CsgOperation::Difference,
        vec![slab(-3.0, 3.0), sphere.clone()],
    );
    assert_eq!(distances(vec![difference], along_x), vec![2.0, 6.0, 8.0]);
    let mut inverted_clip = unit_sphere();
    let mut outside = slab(-0.5, 5.0);
    outside.inverse = true;
    inverted_clip.clipped_by.push(outside);
    assert_eq!(distances(vec![inverted_clip], along_x), vec![4.0]);
    // Flags reach the materials.
    sphere.no_image = true;
    sphere.double_illuminate = true;
    let world = World::build(&scene_of(vec![sphere]));
    assert!(world
        .materials
        .iter()
        .any(|m| m.no_image && m.double_illuminate));
}

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
fn prism_and_poly_in_the_world() {
    let square = [
        DVec2::new(-1.0, -1.0),
        DVec2::new(1.0, -1.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(-1.0, 1.0),
    ];
    let segments = (0..4)
        .map(|i| {
            let (a, b) = (square[i], square[(i + 1) % 4]);
            [a, a + (b - a) / 3.0, a + (b - a) * (2.0 / 3.0), b]
        })
        .collect();
    let prism = Object::new(Shape::Prism(Arc::new(Extrusion {
        segments,
        depth: (0.0, 2.0),
        open: false,
        conic: false,
    })));
    let down = Ray::new(DVec3::new(0.5, 5.0, 0.5), -DVec3::Y);
    assert_eq!(distances(vec![prism], down), vec![3.0, 5.0]);
    // x² + y² + z² - 1 as a poly of order 2.
    let mut coefficients = vec![0.0; 10];
    for index in [0, 4, 7] {
        coefficients[index] = 1.0;
    }
    coefficients[9] = -1.0;
    let poly = Object::new(Shape::Poly(Arc::new(crate::scene::Poly {
        order: 2,
        coefficients,
        sturm: false,
    })));
    let along_x = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    assert_eq!(distances(vec![poly], along_x), vec![4.0, 6.0]);
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
    use super::test_support::marked_texture;
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
    let blend = hit.corner_blend.expect("corner textures blend in CSG");
    assert_eq!(blend.materials[0], blend.materials[2]);
    assert_ne!(blend.materials[0], blend.materials[1]);
    let expected = [0.5, 0.25, 0.25];
    assert!(blend
        .weights
        .iter()
        .zip(expected)
        .all(|(found, wanted)| (found - wanted).abs() < 1e-12));
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
