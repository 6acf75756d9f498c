//! The World's queries: known hits of shapes placed in a scene (sphere, plane, prism, poly),
//! the BVH against brute force, degenerate scenes and rays, and sharing between threads.

use super::support::{
    along_x, csg, distances, marked, marked_texture, random_csg, random_shape, scene_of, sphere_a,
    sphere_b,
};
use crate::geometry::test_support::Random;
use crate::geometry::{Ray, World};
use crate::math::Transform;
use crate::scene::{CsgOperation, Extrusion, Object, Shape};
use glam::{DAffine3, DVec2, DVec3};
use std::sync::Arc;

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
    assert_eq!(world.unbounded_count(), 1);
    let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
    let hit = world.first_hit(&ray, 1e-6, f64::INFINITY).unwrap();
    assert_eq!(hit.distance, 4.0);
    assert_eq!(hit.point, DVec3::new(0.0, 0.0, -1.0));
    assert_eq!(hit.normal, -DVec3::Z);
    // Hits at or before min_distance are skipped: the far side is next.
    let far = world.first_hit(&ray, 4.0, f64::INFINITY).unwrap();
    assert_eq!(far.distance, 6.0);
    assert_eq!(far.normal, DVec3::Z);
    assert!(world.first_hit(&ray, 0.0, 4.0).is_none());
    let down = Ray::new(DVec3::new(3.0, 0.0, 0.0), -DVec3::Y);
    let hit = world.first_hit(&down, 1e-6, f64::INFINITY).unwrap();
    assert_eq!(hit.distance, 2.0);
    assert_eq!(hit.normal, DVec3::Y);
    assert_eq!(hit.material, 0);
    assert_eq!(world.materials.len(), 1);
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
fn bvh_matches_brute_force() {
    let mut random = Random::new(0xb0b_0001);
    let mut objects = Vec::new();
    for index in 0..1500 {
        let mut object = marked(random_shape(&mut random), index as f64);
        // Keep the few unbounded shapes from hiding everything else.
        if matches!(object.shape, Shape::Plane { .. } | Shape::Quadric { .. }) && index % 50 != 0 {
            object.shape = Shape::Sphere {
                centre: DVec3::ZERO,
                radius: 0.3,
            };
        }
        let mut transform = random.transform();
        transform = transform.then(&Transform::translation(random.vector(30.0)));
        object.set_transform(transform);
        object.inverse = random.next() < 0.05;
        objects.push(object);
    }
    for _ in 0..60 {
        let mut object = random_csg(&mut random, 2);
        object.set_transform(Transform::translation(random.vector(30.0)));
        object.inverse = random.next() < 0.1;
        objects.push(object);
    }
    let world = World::build(&scene_of(objects));
    assert!(world.object_count() > 1500);
    let mut hits = 0;
    for _ in 0..3000 {
        let ray = random.ray(40.0);
        let min_distance = if random.next() < 0.5 {
            0.0
        } else {
            random.range(0.0, 5.0)
        };
        let fast = world.first_hit(&ray, min_distance, f64::INFINITY);
        let slow = world.first_hit_brute_force(&ray, min_distance, f64::INFINITY);
        match (fast, slow) {
            (Some(fast), Some(slow)) => {
                assert_eq!(fast.distance, slow.distance, "{ray:?}");
                if fast.material != slow.material {
                    // Only an exact tie between two objects may pick either.
                    assert_eq!(fast.point, slow.point);
                } else {
                    assert_eq!(fast.normal, slow.normal);
                }
                hits += 1;
            }
            (None, None) => {}
            (fast, slow) => panic!("BVH {fast:?} but brute force {slow:?} for {ray:?}"),
        }
    }
    assert!(hits > 500, "only {hits} hits");
}

#[test]
fn degenerate_scenes_never_panic() {
    let nan = f64::NAN;
    let broken = Transform {
        outer_from_inner: DAffine3::from_scale(DVec3::ZERO),
        inner_from_outer: DAffine3::from_scale(DVec3::splat(nan)),
    };
    let mut objects = vec![
        Object::new(Shape::Sphere {
            centre: DVec3::ZERO,
            radius: 0.0,
        }),
        Object::new(Shape::Cylinder {
            base: DVec3::ONE,
            cap: DVec3::ONE,
            radius: 1.0,
            open: false,
        }),
        Object::new(Shape::Torus {
            major: nan,
            minor: nan,
        }),
        Object::new(Shape::Plane {
            normal: DVec3::ZERO,
            distance: 0.0,
        }),
        csg(CsgOperation::Intersection, vec![]),
        csg(CsgOperation::Difference, vec![]),
        csg(
            CsgOperation::Merge,
            vec![Object::new(Shape::Quadric {
                coefficients: Box::new([nan; 10]),
            })],
        ),
        csg(CsgOperation::Union, vec![csg(CsgOperation::Union, vec![])]),
        csg(
            CsgOperation::Difference,
            vec![Object::new(Shape::Sphere {
                centre: DVec3::ZERO,
                radius: 1.0,
            })],
        ),
    ];
    let mut singular = Object::new(Shape::Sphere {
        centre: DVec3::ZERO,
        radius: 1.0,
    });
    singular.set_transform(broken);
    objects.push(singular.clone());
    let mut singular_group = csg(CsgOperation::Intersection, vec![singular, sphere_a()]);
    singular_group.set_transform(broken);
    objects.push(singular_group);
    let mut textured = Object::new(Shape::Box {
        corner1: DVec3::splat(nan),
        corner2: DVec3::ONE,
    });
    textured.texture = Some(marked_texture(0.5));
    objects.push(textured);
    let world = World::build(&scene_of(objects));
    let mut random = Random::new(0xdead_0001);
    for _ in 0..500 {
        let _ = world.first_hit(&random.ray(3.0), 0.0, f64::INFINITY);
    }
    for (ray, min, max) in [
        (Ray::new(DVec3::splat(nan), DVec3::X), 0.0, 1.0),
        (Ray::new(DVec3::ZERO, DVec3::ZERO), 0.0, 1.0),
        (Ray::new(DVec3::ZERO, DVec3::X), 1.0, 0.0),
        (Ray::new(DVec3::ZERO, DVec3::X), nan, nan),
    ] {
        assert!(world.first_hit(&ray, min, max).is_none());
    }
    let empty = World::build(&scene_of(vec![]));
    assert!(empty.first_hit(&along_x(), 0.0, f64::INFINITY).is_none());
    assert_eq!(empty.object_count(), 0);
}

#[test]
fn world_can_be_shared_between_threads() {
    fn shareable<T: Send + Sync>() {}
    shareable::<World>();
    let world = World::build(&scene_of(vec![csg(
        CsgOperation::Intersection,
        vec![sphere_a(), sphere_b()],
    )]));
    std::thread::scope(|scope| {
        for _ in 0..4 {
            scope.spawn(|| {
                let hit = world.first_hit(&along_x(), 0.0, f64::INFINITY).unwrap();
                assert_eq!(hit.distance, 4.5);
            });
        }
    });
}
