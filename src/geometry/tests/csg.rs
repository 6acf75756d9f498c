//! CSG in the world: union, merge, intersection and difference truth tables, inversion pushed
//! down the tree, transforms composing through CSG children, coincident faces, wide nodes'
//! child indexes against a plain scan, and `clipped_by`.

use super::support::{
    all_hits, along_x, csg, distances, mark_of, marked, random_csg, random_shape, scene_of, slab,
    sphere_a, sphere_b,
};
use crate::geometry::test_support::Random;
use crate::geometry::{Ray, World};
use crate::math::Transform;
use crate::scene::{CsgOperation, Object, Shape};
use glam::DVec3;

/// Every hit of `objects` along [`along_x`] as (distance, normal x sign, mark).
fn profile(objects: Vec<Object>) -> Vec<(f64, f64, f64)> {
    let world = World::build(&scene_of(objects));
    all_hits(&world, &along_x())
        .iter()
        .map(|hit| {
            assert!((hit.normal.length() - 1.0).abs() < 1e-12);
            let distance = (hit.distance * 1e9).round() / 1e9;
            (distance, hit.normal.x.signum(), mark_of(&world, hit))
        })
        .collect()
}

/// An object with `inverse` set.
fn inverted(mut object: Object) -> Object {
    object.inverse = true;
    object
}

fn unit_sphere() -> Object {
    Object::new(Shape::Sphere {
        centre: DVec3::ZERO,
        radius: 1.0,
    })
}

#[test]
fn csg_truth_tables() {
    use CsgOperation::{Difference, Intersection, Merge, Union};
    let (a, b) = (0.25, 0.75);
    assert_eq!(
        profile(vec![csg(Union, vec![sphere_a(), sphere_b()])]),
        vec![(3.5, -1.0, a), (4.5, -1.0, b), (5.5, 1.0, a), (6.5, 1.0, b)]
    );
    assert_eq!(
        profile(vec![csg(Merge, vec![sphere_a(), sphere_b()])]),
        vec![(3.5, -1.0, a), (6.5, 1.0, b)]
    );
    assert_eq!(
        profile(vec![csg(Intersection, vec![sphere_a(), sphere_b()])]),
        vec![(4.5, -1.0, b), (5.5, 1.0, a)]
    );
    // A minus B: B's surface bounds the result, its normal pointing out of A - B.
    assert_eq!(
        profile(vec![csg(Difference, vec![sphere_a(), sphere_b()])]),
        vec![(3.5, -1.0, a), (4.5, 1.0, b)]
    );
    assert_eq!(
        profile(vec![csg(Difference, vec![sphere_b(), sphere_a()])]),
        vec![(5.5, -1.0, a), (6.5, 1.0, b)]
    );
}

#[test]
fn inversion_flips_normals_and_changes_unions() {
    use CsgOperation::{Difference, Intersection, Union};
    let (a, b) = (0.25, 0.75);
    // A lone inverted sphere: same surface, normals pointing inwards.
    assert_eq!(
        profile(vec![inverted(sphere_a())]),
        vec![(3.5, 1.0, a), (5.5, -1.0, a)]
    );
    // An inverted intersection keeps the lens surface with flipped normals.
    assert_eq!(
        profile(vec![inverted(csg(
            Intersection,
            vec![sphere_a(), sphere_b()]
        ))]),
        vec![(4.5, 1.0, b), (5.5, -1.0, a)]
    );
    // POV-Ray turns an inverted union into an intersection of the inverted children, which
    // drops the surfaces inside the other child.
    assert_eq!(
        profile(vec![inverted(csg(Union, vec![sphere_a(), sphere_b()]))]),
        vec![(3.5, 1.0, a), (6.5, -1.0, b)]
    );
    // The same happens to a subtracted union: a big sphere minus A ∪ B, seen from inside.
    let big = marked(
        Shape::Sphere {
            centre: DVec3::ZERO,
            radius: 10.0,
        },
        0.5,
    );
    assert_eq!(
        profile(vec![csg(
            Difference,
            vec![big, csg(Union, vec![sphere_a(), sphere_b()])]
        )]),
        vec![(3.5, 1.0, a), (6.5, -1.0, b), (15.0, 1.0, 0.5)]
    );
    // A union inside an intersection keeps its inner surfaces.
    let slab = marked(
        Shape::Box {
            corner1: DVec3::new(-1.0, -5.0, -5.0),
            corner2: DVec3::new(1.0, 5.0, 5.0),
        },
        0.5,
    );
    assert_eq!(
        profile(vec![csg(
            Intersection,
            vec![csg(Union, vec![sphere_a(), sphere_b()]), slab]
        )]),
        vec![
            (4.0, -1.0, 0.5),
            (4.5, -1.0, b),
            (5.5, 1.0, a),
            (6.0, 1.0, 0.5)
        ]
    );
    // Triangles cannot be inverted: subtracting one removes everything of the first child.
    let triangle = marked(
        Shape::Triangle {
            corners: Box::new([
                DVec3::new(0.0, -5.0, -5.0),
                DVec3::new(0.0, 5.0, -5.0),
                DVec3::new(0.0, 0.0, 5.0),
            ]),
        },
        0.5,
    );
    assert_eq!(
        profile(vec![csg(Difference, vec![sphere_a(), triangle.clone()])]),
        vec![(5.0, -1.0, 0.5)]
    );
    assert_eq!(profile(vec![inverted(triangle)]), vec![(5.0, -1.0, 0.5)]);
}

#[test]
fn transformed_csg_children_compose() {
    // A union scaled by 2 and moved to x = 10 holding A moved by +1: A's centre ends at
    // (10 + 2 * 0.5, 0, 0) = (11, 0, 0) with radius 2.
    let mut child = sphere_a();
    child.set_transform(Transform::translation(DVec3::X));
    let mut group = csg(CsgOperation::Intersection, vec![child]);
    group.set_transform(
        Transform::scaling(DVec3::splat(2.0))
            .unwrap()
            .then(&Transform::translation(DVec3::new(10.0, 0.0, 0.0))),
    );
    let world = World::build(&scene_of(vec![group]));
    let hits = all_hits(&world, &along_x());
    let distances: Vec<f64> = hits.iter().map(|hit| hit.distance).collect();
    assert_eq!(distances, vec![14.0, 18.0]);
    assert_eq!(world.object_count(), 1);
}

#[test]
fn coincident_faces_subtract_cleanly_on_axis() {
    // A box minus a notch sharing its front face: POV-Ray counts the faces of a box as inside,
    // so along an axis-aligned ray the shared face is removed and the notch's back wall shows.
    let cube = marked(
        Shape::Box {
            corner1: -DVec3::ONE,
            corner2: DVec3::ONE,
        },
        0.25,
    );
    let notch = marked(
        Shape::Box {
            corner1: DVec3::new(-0.5, -0.5, -1.0),
            corner2: DVec3::new(0.5, 0.5, 0.0),
        },
        0.75,
    );
    let world = World::build(&scene_of(vec![csg(
        CsgOperation::Difference,
        vec![cube, notch],
    )]));
    let ray = Ray::new(DVec3::new(0.1, 0.2, -5.0), DVec3::Z);
    let hit = world.first_hit(&ray, 1e-6, f64::INFINITY).unwrap();
    assert!(hit.distance == 4.0 || hit.distance == 5.0, "{hit:?}");
    assert_eq!(mark_of(&world, &hit), 0.75);
}

#[test]
fn wide_csg_nodes_index_their_children_exactly() {
    use CsgOperation::{Difference, Intersection, Merge, Union};
    let mut random = Random::new(0xc5_9001);
    let mut objects = Vec::new();
    for (place, operation) in [Difference, Intersection, Merge, Union, Difference]
        .into_iter()
        .enumerate()
    {
        // A large base shape and many small children scattered around it, some of them
        // nested CSG and some inverted.
        let mut children = vec![marked(
            Shape::Box {
                corner1: DVec3::splat(-2.0),
                corner2: DVec3::splat(2.0),
            },
            0.0,
        )];
        for index in 1..60 {
            let mut child = if index % 7 == 0 {
                random_csg(&mut random, 1)
            } else {
                marked(random_shape(&mut random), index as f64)
            };
            if matches!(child.shape, Shape::Plane { .. } | Shape::Quadric { .. })
                && operation != Intersection
            {
                child.shape = Shape::Sphere {
                    centre: DVec3::ZERO,
                    radius: 0.4,
                };
            }
            let scale = Transform::scaling(DVec3::splat(0.3)).unwrap();
            child.set_transform(
                random
                    .transform()
                    .then(&scale)
                    .then(&Transform::translation(random.vector(2.5))),
            );
            child.inverse = random.next() < 0.1;
            children.push(child);
        }
        let mut object = csg(operation, children);
        object.set_transform(Transform::translation(DVec3::new(
            place as f64 * 8.0,
            0.0,
            0.0,
        )));
        object.inverse = place == 4;
        objects.push(object);
    }
    let indexed = World::build(&scene_of(objects.clone()));
    let plain = World::build(&scene_of(objects)).without_csg_child_indexes();
    let mut hits = 0;
    for _ in 0..4000 {
        let mut ray = random.ray(4.0);
        ray.origin.x += random.range(-2.0, 36.0);
        let min_distance = random.range(0.0, 2.0);
        let fast = indexed.first_hit(&ray, min_distance, f64::INFINITY);
        let slow = plain.first_hit(&ray, min_distance, f64::INFINITY);
        match (fast, slow) {
            (Some(fast), Some(slow)) => {
                assert_eq!(fast.distance, slow.distance, "{ray:?}");
                assert_eq!(fast.material, slow.material, "{ray:?}");
                assert_eq!(fast.normal, slow.normal, "{ray:?}");
                hits += 1;
            }
            (None, None) => {}
            (fast, slow) => panic!("indexed {fast:?} but plain {slow:?} for {ray:?}"),
        }
    }
    assert!(hits > 1000, "only {hits} hits");
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
