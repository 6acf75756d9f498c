//! World-level tests: known answers, transforms, CSG truth tables, BVH against brute force.

use super::*;
use crate::scene::{Object, Scene, Shape};

/// A scene holding just `objects`.
fn scene_of(objects: Vec<Object>) -> Scene {
    Scene {
        camera: Default::default(),
        lights: Vec::new(),
        objects,
        background: crate::scene::Colour::BLACK,
        settings: Default::default(),
    }
}

#[test]
fn sphere_and_plane_known_hits() {
    let world = World::build(&scene_of(vec![
        Object::new(Shape::Sphere {
            centre: DVec3::ZERO,
            radius: 1.0,
        }),
        Object::new(Shape::Plane {
            normal: DVec3::Y,
            distance: -2.0,
        }),
    ]));
    assert_eq!(world.object_count(), 2);
    let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
    let hit = world.first_hit(&ray, 1e-6, f64::INFINITY).unwrap();
    assert_eq!(hit.distance, 4.0);
    assert_eq!(hit.normal, -DVec3::Z);
    let down = Ray::new(DVec3::new(3.0, 0.0, 0.0), -DVec3::Y);
    let hit = world.first_hit(&down, 1e-6, f64::INFINITY).unwrap();
    assert_eq!(hit.distance, 2.0);
    assert_eq!(hit.normal, DVec3::Y);
}
