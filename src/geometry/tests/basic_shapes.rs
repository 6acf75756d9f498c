//! Property tests of the basic shapes (sphere, box, cylinder, cone, torus, plane, quadrics,
//! disc, triangle) through [`Leaf`]: crossings flip inside and outside, normals are unit length
//! and point outwards, known answers, transforms baked in or kept agree, grazing torus hits,
//! and degenerate input gives empty leaves that never panic.

use crate::geometry::leaf::Leaf;
use crate::geometry::roots::Roots;
use crate::geometry::test_support::Random;
use crate::geometry::Ray;
use crate::{math::Transform, scene::Shape};
use glam::{DAffine3, DVec3};

/// How far before and after a crossing the inside test is probed.
const PROBE: f64 = 1e-7;

/// One solid shape of each kind, for the inside/outside tests.
fn solid_shapes() -> Vec<(&'static str, Shape)> {
    vec![
        (
            "sphere",
            Shape::Sphere {
                centre: DVec3::new(0.1, -0.2, 0.3),
                radius: 1.2,
            },
        ),
        (
            "box",
            Shape::Box {
                corner1: DVec3::new(1.0, -0.5, 0.7),
                corner2: DVec3::new(-1.2, 0.9, -0.4),
            },
        ),
        (
            "cylinder",
            Shape::Cylinder {
                base: DVec3::new(-0.5, -1.0, 0.2),
                cap: DVec3::new(0.4, 1.1, -0.3),
                radius: 0.7,
                open: false,
            },
        ),
        (
            "cone",
            Shape::Cone {
                base: DVec3::new(0.3, -1.0, 0.1),
                base_radius: 1.0,
                cap: DVec3::new(-0.2, 1.0, 0.4),
                cap_radius: 0.2,
                open: false,
            },
        ),
        (
            "pointed cone",
            Shape::Cone {
                base: DVec3::new(0.0, -1.0, 0.0),
                base_radius: 0.0,
                cap: DVec3::new(0.0, 1.0, 0.0),
                cap_radius: 0.9,
                open: false,
            },
        ),
        (
            "torus",
            Shape::Torus {
                major: 1.0,
                minor: 0.35,
            },
        ),
        (
            "plane",
            Shape::Plane {
                normal: DVec3::new(0.3, 1.0, -0.2),
                distance: 0.4,
            },
        ),
        (
            "ellipsoid quadric",
            Shape::Quadric {
                coefficients: Box::new([1.0, 2.0, 0.5, 0.2, 0.0, -0.3, 0.1, 0.0, 0.2, -1.0]),
            },
        ),
        (
            "hyperboloid quadric",
            Shape::Quadric {
                coefficients: Box::new([1.0, -1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.5]),
            },
        ),
    ]
}

/// The sorted crossings of a leaf along a ray.
fn crossings(leaf: &Leaf, ray: &Ray) -> Vec<(f64, u8)> {
    let mut roots = Roots::new();
    leaf.intersect(ray, &mut roots);
    let mut found: Vec<(f64, u8)> = roots.iter().collect();
    found.sort_by(|a, b| a.0.total_cmp(&b.0));
    found
}

/// Leaves for `shape`: untransformed, and under a few transforms (some absorbed into the shape,
/// some kept).
fn placements(shape: &Shape, random: &mut Random) -> Vec<(Leaf, Transform)> {
    let mut transforms = vec![
        Transform::IDENTITY,
        Transform::translation(DVec3::new(0.3, -0.2, 0.1)),
        Transform::scaling(DVec3::splat(1.7))
            .unwrap()
            .then(&Transform::rotation_degrees(DVec3::new(10.0, 20.0, 30.0))),
    ];
    for _ in 0..3 {
        transforms.push(random.transform());
    }
    transforms
        .into_iter()
        .map(|transform| (Leaf::new(shape, &transform, 0, false).0, transform))
        .collect()
}

#[test]
fn crossings_flip_inside_and_normals_point_out() {
    let mut random = Random::new(0x5eed_0001);
    for (name, shape) in solid_shapes() {
        for (leaf, _) in placements(&shape, &mut random) {
            let mut checked = 0;
            for _ in 0..3000 {
                let ray = random.ray(2.5);
                let found = crossings(&leaf, &ray);
                // Skip rays with (nearly) coincident crossings: tangents, edges, rims.
                if found.windows(2).any(|pair| pair[1].0 - pair[0].0 < 1e-4) {
                    continue;
                }
                // Far crossings are grazing ones, where the probes cannot resolve the sides.
                for &(distance, part) in found.iter().filter(|hit| hit.0.abs() < 10.0) {
                    let before = leaf.inside(ray.at(distance - PROBE));
                    let after = leaf.inside(ray.at(distance + PROBE));
                    assert_ne!(before, after, "{name}: no flip at {distance} on {ray:?}");
                    let point = ray.at(distance);
                    let normal = leaf.normal(point, part);
                    assert!(
                        (normal.length() - 1.0).abs() < 1e-12,
                        "{name}: normal {normal}"
                    );
                    let entering = normal.dot(ray.direction) < 0.0;
                    assert_eq!(entering, after, "{name}: normal not outward at {point}");
                    checked += 1;
                }
            }
            assert!(checked > 100, "{name}: only {checked} crossings checked");
        }
    }
}

#[test]
fn disc_and_triangle_hits() {
    let mut random = Random::new(0x5eed_0002);
    let disc = Shape::Disc {
        centre: DVec3::new(0.1, 0.2, 0.0),
        normal: DVec3::new(0.2, 1.0, 0.1),
        radius: 1.0,
        hole_radius: 0.3,
    };
    let triangle = Shape::Triangle {
        corners: Box::new([
            DVec3::new(-1.0, -0.5, 0.2),
            DVec3::new(1.0, -0.4, 0.0),
            DVec3::new(0.1, 1.0, -0.3),
        ]),
    };
    for (leaf, _) in placements(&disc, &mut random) {
        for _ in 0..2000 {
            let ray = random.ray(2.0);
            for (distance, part) in crossings(&leaf, &ray) {
                // A disc's inside is the half-space behind it, so every hit crosses it.
                let before = leaf.inside(ray.at(distance - PROBE));
                let after = leaf.inside(ray.at(distance + PROBE));
                assert_ne!(before, after);
                assert!((leaf.normal(ray.at(distance), part).length() - 1.0).abs() < 1e-12);
            }
        }
    }
    for (leaf, _) in placements(&triangle, &mut random) {
        let mut hits = 0;
        for _ in 0..2000 {
            let origin = random.vector(3.0);
            let ray = Ray::new(origin, (random.vector(1.0) - origin).normalize());
            for (distance, part) in crossings(&leaf, &ray) {
                assert!(!leaf.inside(ray.at(distance)));
                assert!((leaf.normal(ray.at(distance), part).length() - 1.0).abs() < 1e-12);
                hits += 1;
            }
        }
        assert!(hits > 50);
    }
}

#[test]
fn known_answers() {
    let along_z = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
    let cases = [
        (
            Shape::Sphere {
                centre: DVec3::ZERO,
                radius: 1.0,
            },
            4.0,
            -DVec3::Z,
        ),
        (
            Shape::Box {
                corner1: DVec3::splat(-1.0),
                corner2: DVec3::splat(2.0),
            },
            4.0,
            -DVec3::Z,
        ),
        (
            Shape::Cylinder {
                base: DVec3::Z * -2.0,
                cap: DVec3::Z * 2.0,
                radius: 1.0,
                open: false,
            },
            3.0,
            -DVec3::Z,
        ),
        (
            Shape::Cone {
                base: DVec3::Z * 3.0,
                base_radius: 1.0,
                cap: DVec3::Z * 1.0,
                cap_radius: 0.5,
                open: false,
            },
            6.0,
            -DVec3::Z,
        ),
        (
            Shape::Torus {
                major: 2.0,
                minor: 0.5,
            },
            2.5,
            -DVec3::Z,
        ),
        (
            Shape::Plane {
                normal: -DVec3::Z,
                distance: 1.0,
            },
            4.0,
            -DVec3::Z,
        ),
        (
            Shape::Disc {
                centre: DVec3::Z,
                normal: DVec3::Z,
                radius: 1.0,
                hole_radius: 0.0,
            },
            6.0,
            DVec3::Z,
        ),
        (
            Shape::Triangle {
                corners: Box::new([
                    DVec3::new(-1.0, -1.0, 0.5),
                    DVec3::new(1.0, -1.0, 0.5),
                    DVec3::Y,
                ]),
            },
            5.25,
            // POV-Ray's orientation: (c - a) x (b - a).
            DVec3::new(0.0, -1.0, -4.0).normalize(),
        ),
    ];
    for (shape, distance, normal) in cases {
        let (leaf, _) = Leaf::new(&shape, &Transform::IDENTITY, 0, false);
        let nearest = leaf.nearest(&along_z, 0.0, f64::INFINITY);
        let (found, part) = nearest.unwrap_or_else(|| panic!("no hit on {shape:?}"));
        assert!((found - distance).abs() < 1e-12, "{shape:?}: {found}");
        let found_normal = leaf.normal(along_z.at(found), part);
        assert!(
            (found_normal - normal).length() < 1e-12,
            "{shape:?}: {found_normal}"
        );
    }
}

#[test]
fn transformed_sphere_hits_where_expected() {
    // A unit sphere scaled by 2 along x, rotated 90° about z (so the long axis is y), then
    // moved to (0, 0, 10).
    let transform = Transform::scaling(DVec3::new(2.0, 1.0, 1.0))
        .unwrap()
        .then(&Transform::rotation_degrees(DVec3::new(0.0, 0.0, 90.0)))
        .then(&Transform::translation(DVec3::new(0.0, 0.0, 10.0)));
    let shape = Shape::Sphere {
        centre: DVec3::ZERO,
        radius: 1.0,
    };
    let (leaf, bounds) = Leaf::new(&shape, &transform, 0, false);
    let surface = bounds.surface.unwrap();
    assert!((surface.min - DVec3::new(-1.0, -2.0, 9.0)).length() < 1e-9);
    assert!((surface.max - DVec3::new(1.0, 2.0, 11.0)).length() < 1e-9);
    let down = Ray::new(DVec3::new(0.0, 5.0, 10.0), -DVec3::Y);
    let (distance, part) = leaf.nearest(&down, 0.0, f64::INFINITY).unwrap();
    assert!((distance - 3.0).abs() < 1e-12);
    assert!((leaf.normal(down.at(distance), part) - DVec3::Y).length() < 1e-12);
    // Along z it is one unit thick.
    let along = Ray::new(DVec3::new(0.0, 0.0, 0.0), DVec3::Z);
    assert!((leaf.nearest(&along, 0.0, f64::INFINITY).unwrap().0 - 9.0).abs() < 1e-12);
    // An oblique normal on the ellipse x² + (y/2)² = 1 at (√½, √2): gradient (2x, y/2).
    let point = DVec3::new(0.5f64.sqrt(), 2.0f64.sqrt(), 10.0);
    let expected = DVec3::new(2.0 * point.x, point.y / 2.0, 0.0).normalize();
    assert!((leaf.normal(point, 0) - expected).length() < 1e-12);
}

#[test]
fn absorbed_and_kept_transforms_agree() {
    // The same shape placed through a transform must behave the same whether the leaf bakes
    // the transform into the shape or keeps the inverse map.
    let mut random = Random::new(0x5eed_0003);
    let similarity = Transform::scaling(DVec3::splat(1.3))
        .unwrap()
        .then(&Transform::rotation_degrees(DVec3::new(30.0, 40.0, 50.0)))
        .then(&Transform::translation(DVec3::new(0.5, -1.0, 2.0)));
    let axis_scale = Transform::scaling(DVec3::new(2.0, 0.5, 1.5))
        .unwrap()
        .then(&Transform::translation(DVec3::new(0.5, -1.0, 2.0)));
    let cases = [
        (
            Shape::Sphere {
                centre: DVec3::new(0.2, 0.1, 0.0),
                radius: 0.8,
            },
            similarity,
        ),
        (
            Shape::Box {
                corner1: -DVec3::ONE,
                corner2: DVec3::new(1.0, 2.0, 0.5),
            },
            axis_scale,
        ),
        (
            Shape::Plane {
                normal: DVec3::new(1.0, 2.0, 3.0),
                distance: 0.5,
            },
            similarity,
        ),
    ];
    for (shape, transform) in cases {
        let (baked, _) = Leaf::new(&shape, &transform, 0, false);
        let (plain, _) = Leaf::new(&shape, &Transform::IDENTITY, 0, false);
        let mut disagreements = 0;
        for _ in 0..500 {
            let ray = Ray::new(random.vector(4.0), random.unit_vector());
            let local = Ray::new(
                transform.point_to_inner(ray.origin),
                transform.vector_to_inner(ray.direction),
            );
            let expected = plain.nearest(&local, 0.0, f64::INFINITY);
            let found = baked.nearest(&ray, 0.0, f64::INFINITY);
            match (expected, found) {
                (Some(expected), Some(found)) => {
                    assert!((expected.0 - found.0).abs() < 1e-9 * (1.0 + expected.0.abs()));
                    let local_normal = plain.normal(local.at(expected.0), expected.1);
                    let world_normal = transform.normal_to_outer(local_normal).normalize();
                    let normal = baked.normal(ray.at(found.0), found.1);
                    assert!((world_normal - normal).length() < 1e-9, "{shape:?}");
                }
                (None, None) => {}
                // Only rays grazing an edge may disagree.
                _ => disagreements += 1,
            }
        }
        assert!(disagreements <= 2, "{shape:?}: {disagreements}");
    }
}

#[test]
fn torus_does_not_miss_grazing_hits() {
    let (leaf, _) = Leaf::new(
        &Shape::Torus {
            major: 1.0,
            minor: 0.25,
        },
        &Transform::IDENTITY,
        0,
        false,
    );
    // Rays skimming the top of the tube at height 0.25 - gap along x (through the centre) hit
    // the tube twice on each side.
    for gap in [1e-2, 1e-4, 1e-6, 1e-8, 1e-10] {
        let ray = Ray::new(DVec3::new(-3.0, 0.25 - gap, 0.0), DVec3::X);
        let found = crossings(&leaf, &ray);
        assert_eq!(found.len(), 4, "gap {gap}: {found:?}");
    }
    let above = Ray::new(DVec3::new(-3.0, 0.25 + 1e-9, 0.0), DVec3::X);
    assert!(crossings(&leaf, &above).is_empty());
    // Rays grazing the outer equator from outside, in the XZ plane at x = 1.25 - gap.
    for gap in [1e-3, 1e-6, 1e-9] {
        let ray = Ray::new(DVec3::new(1.25 - gap, 0.0, -3.0), DVec3::Z);
        assert_eq!(crossings(&leaf, &ray).len(), 2, "gap {gap}");
    }
    // Dense sampling of the inside test along random rays agrees with the root count.
    let mut random = Random::new(0x5eed_0004);
    for _ in 0..300 {
        let origin = random.vector(2.0);
        let direction = (random.vector(0.6) - origin).normalize();
        let ray = Ray::new(origin, direction);
        let found = crossings(&leaf, &ray);
        let steps = 20000;
        let length = 5.0;
        let mut flips = 0;
        let mut previous = leaf.inside(ray.at(0.0));
        for step in 1..=steps {
            let now = leaf.inside(ray.at(length * step as f64 / steps as f64));
            flips += usize::from(now != previous);
            previous = now;
        }
        let in_range = found
            .iter()
            .filter(|hit| hit.0 > 0.0 && hit.0 < length)
            .count();
        if found.windows(2).all(|pair| pair[1].0 - pair[0].0 > 1e-3) {
            assert_eq!(flips, in_range, "{ray:?}: {found:?}");
        }
    }
}

#[test]
fn degenerate_shapes_are_empty_and_never_panic() {
    let nan = f64::NAN;
    let shapes = [
        Shape::Sphere {
            centre: DVec3::ZERO,
            radius: 0.0,
        },
        Shape::Sphere {
            centre: DVec3::ZERO,
            radius: nan,
        },
        Shape::Sphere {
            centre: DVec3::splat(nan),
            radius: 1.0,
        },
        Shape::Sphere {
            centre: DVec3::ZERO,
            radius: f64::INFINITY,
        },
        Shape::Box {
            corner1: DVec3::ZERO,
            corner2: DVec3::splat(nan),
        },
        Shape::Plane {
            normal: DVec3::ZERO,
            distance: 1.0,
        },
        Shape::Plane {
            normal: DVec3::Y,
            distance: nan,
        },
        Shape::Cylinder {
            base: DVec3::ONE,
            cap: DVec3::ONE,
            radius: 1.0,
            open: false,
        },
        Shape::Cylinder {
            base: DVec3::ZERO,
            cap: DVec3::Y,
            radius: 0.0,
            open: true,
        },
        Shape::Cone {
            base: DVec3::ZERO,
            base_radius: 0.0,
            cap: DVec3::Y,
            cap_radius: 0.0,
            open: false,
        },
        Shape::Torus {
            major: 1.0,
            minor: 0.0,
        },
        Shape::Torus {
            major: nan,
            minor: 1.0,
        },
        Shape::Disc {
            centre: DVec3::ZERO,
            normal: DVec3::ZERO,
            radius: 1.0,
            hole_radius: 0.0,
        },
        Shape::Disc {
            centre: DVec3::ZERO,
            normal: DVec3::Y,
            radius: 1.0,
            hole_radius: 2.0,
        },
        Shape::Quadric {
            coefficients: Box::new([0.0; 10]),
        },
        Shape::Quadric {
            coefficients: Box::new([nan; 10]),
        },
        Shape::Triangle {
            corners: Box::new([DVec3::ZERO, DVec3::X, DVec3::X * 2.0]),
        },
        Shape::Triangle {
            corners: Box::new([DVec3::ZERO; 3]),
        },
    ];
    let mut random = Random::new(0x5eed_0005);
    for shape in &shapes {
        let (leaf, _) = Leaf::new(shape, &Transform::IDENTITY, 0, false);
        assert!(leaf.is_empty(), "{shape:?}");
        for _ in 0..100 {
            assert!(leaf.nearest(&random.ray(2.0), 0.0, f64::INFINITY).is_none());
        }
    }
    // Singular and non-finite transforms make any shape empty.
    let singular = Transform {
        outer_from_inner: DAffine3::from_scale(DVec3::new(1.0, 0.0, 1.0)),
        inner_from_outer: DAffine3::from_scale(DVec3::new(1.0, f64::INFINITY, 1.0)),
    };
    let not_finite = Transform {
        outer_from_inner: DAffine3::from_translation(DVec3::splat(nan)),
        inner_from_outer: DAffine3::from_translation(DVec3::splat(nan)),
    };
    let sphere = Shape::Sphere {
        centre: DVec3::ZERO,
        radius: 1.0,
    };
    for transform in [singular, not_finite] {
        let (leaf, _) = Leaf::new(&sphere, &transform, 0, false);
        assert!(leaf.is_empty());
        assert!(!leaf.inside(DVec3::ZERO));
    }
    // Odd rays on a good shape.
    let (leaf, _) = Leaf::new(&sphere, &Transform::IDENTITY, 0, false);
    for ray in [
        Ray::new(DVec3::splat(nan), DVec3::X),
        Ray::new(DVec3::ZERO, DVec3::ZERO),
        Ray::new(DVec3::ZERO, DVec3::splat(f64::INFINITY)),
    ] {
        let _ = leaf.nearest(&ray, 0.0, f64::INFINITY);
        let _ = leaf.normal(ray.origin, 0);
    }
}
