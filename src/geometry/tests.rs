//! World-level tests: known answers, CSG truth tables, inversion, materials and texture
//! inheritance, BVH against brute force, degenerate scenes.

use super::test_support::{all_hits, csg, mark_of, marked, random_csg, random_shape, scene_of};
use super::test_support::{marked_texture, Random};
use super::*;
use crate::math::{Colour, Transform};
use crate::{
    scene::{CsgOperation, Interior, Object, Shape},
    texture::{
        pattern::{Pattern, PatternKind},
        Pigment, PigmentMap,
    },
};
use glam::DAffine3;

/// Sphere A: centre (-0.5, 0, 0), radius 1; crossed by the x axis at x = -1.5 and 0.5.
fn sphere_a() -> Object {
    marked(
        Shape::Sphere {
            centre: DVec3::new(-0.5, 0.0, 0.0),
            radius: 1.0,
        },
        0.25,
    )
}

/// Sphere B: centre (0.5, 0, 0), radius 1; crossed by the x axis at x = -0.5 and 1.5.
fn sphere_b() -> Object {
    marked(
        Shape::Sphere {
            centre: DVec3::new(0.5, 0.0, 0.0),
            radius: 1.0,
        },
        0.75,
    )
}

/// The ray along +x from x = -5 used by the truth tables: A at 3.5 and 5.5, B at 4.5 and 6.5.
fn along_x() -> Ray {
    Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X)
}

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
fn materials_inherit_and_share_textures() {
    let checker = Pigment::Pattern {
        pattern: Box::new(Pattern::new(PatternKind::Checker)),
        map: PigmentMap::Blocks(vec![
            Pigment::Solid(Colour::WHITE),
            Pigment::Pattern {
                pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::Y))),
                map: PigmentMap::Colours(vec![(0.0, Colour::BLACK), (1.0, Colour::WHITE)]),
                transform: Transform::translation(DVec3::Y),
            },
        ]),
        transform: Transform::scaling(DVec3::splat(0.5)).unwrap(),
    };
    let owner_texture = Arc::new(Texture {
        pigment: checker,
        ..Texture::default()
    });
    let first = Object::new(Shape::Sphere {
        centre: DVec3::ZERO,
        radius: 1.0,
    });
    let mut second = Object::new(Shape::Sphere {
        centre: DVec3::X * 3.0,
        radius: 1.0,
    });
    second.no_shadow = true;
    let mut own = marked(
        Shape::Sphere {
            centre: DVec3::X * 6.0,
            radius: 1.0,
        },
        0.5,
    );
    own.interior = Some(Box::new(Interior {
        ior: 2.0,
        ..Interior::default()
    }));
    let mut group = csg(CsgOperation::Union, vec![first, second, own]);
    group.texture = Some(owner_texture);
    group.interior = Some(Box::new(Interior {
        ior: 1.5,
        ..Interior::default()
    }));
    let world_from_group = Transform::translation(DVec3::new(0.0, 0.0, 10.0));
    group.set_transform(world_from_group);
    let plain = Object::new(Shape::Sphere {
        centre: DVec3::Y * 5.0,
        radius: 1.0,
    });
    let world = World::build(&scene_of(vec![group, plain]));
    assert_eq!(world.object_count(), 4);
    let hit_at = |x: f64, y: f64| {
        let ray = Ray::new(DVec3::new(x, y, 0.0), DVec3::Z);
        world.first_hit(&ray, 0.0, f64::INFINITY).unwrap()
    };
    let first_material = &world.materials[hit_at(0.0, 0.0).material as usize];
    let second_material = &world.materials[hit_at(3.0, 0.0).material as usize];
    let own_material = &world.materials[hit_at(6.0, 0.0).material as usize];
    let plain_material = &world.materials[world
        .first_hit(
            &Ray::new(DVec3::new(0.0, 5.0, -5.0), DVec3::Z),
            0.0,
            f64::INFINITY,
        )
        .unwrap()
        .material as usize];
    // Both children inherit one converted texture, shared.
    assert!(Arc::ptr_eq(
        &first_material.texture,
        &second_material.texture
    ));
    assert_eq!(first_material.interior.ior, 1.5);
    assert!(!first_material.no_shadow);
    assert!(second_material.no_shadow);
    assert_eq!(own_material.interior.ior, 2.0);
    assert!(matches!(own_material.texture.pigment, Pigment::Solid(_)));
    assert_eq!(plain_material.interior.ior, 1.0);
    assert!(matches!(plain_material.texture.pigment, Pigment::Solid(c) if c == Colour::BLACK));
    // Pattern transforms now map pattern space to world space, in nested block maps too.
    let Pigment::Pattern {
        transform,
        map: PigmentMap::Blocks(blocks),
        ..
    } = &first_material.texture.pigment
    else {
        panic!("expected the checker pattern");
    };
    let expected = Transform::scaling(DVec3::splat(0.5))
        .unwrap()
        .then(&world_from_group);
    assert_eq!(*transform, expected);
    assert_eq!(
        transform.point_to_outer(DVec3::ONE),
        DVec3::new(0.5, 0.5, 10.5)
    );
    let Pigment::Pattern {
        transform: inner, ..
    } = &blocks[1]
    else {
        panic!("expected the gradient block");
    };
    assert_eq!(
        *inner,
        Transform::translation(DVec3::Y).then(&world_from_group)
    );
    // Shadow queries skip the shadowless child.
    let through = Ray::new(DVec3::new(3.0, 0.0, 0.0), DVec3::Z);
    assert!(world.first_hit(&through, 0.0, f64::INFINITY).is_some());
    assert!(world
        .first_shadow_hit(&through, 0.0, f64::INFINITY)
        .is_none());
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
