//! Shapes found numerically or from samples: the isosurface (known answers, POV-Ray's
//! max_gradient holes), the height field (known answers, the cell split, smoothed normals as
//! POV-Ray's) and the sphere sweep; crossings flip the inside test and normals point out.

use crate::geometry::height_field::HeightField;
use crate::geometry::isosurface::Isosurface;
use crate::geometry::roots::Roots;
use crate::geometry::sphere_sweep::SphereSweep;
use crate::geometry::test_support::assert_crossings_flip_inside;
use crate::scene::{
    Container, HeightField as HeightFieldSpec, Isosurface as IsosurfaceSpec,
    SphereSweep as SphereSweepSpec, SweepSpline,
};
use crate::texture::function::{Binary, Function, Internal, Node};
use glam::DVec3;
use std::sync::Arc;

/// `f_sphere(x, y, z, radius)` as a compiled function of x, y, z.
fn sphere_function(radius: f64) -> Arc<Function> {
    let arguments = vec![
        Node::Parameter(0),
        Node::Parameter(1),
        Node::Parameter(2),
        Node::Constant(radius),
    ];
    Arc::new(Function::new(
        Node::Internal(Internal::Sphere, arguments.into_boxed_slice()),
        3,
    ))
}

fn isosurface(function: Arc<Function>, max_gradient: f64, max_trace: usize) -> Isosurface {
    Isosurface::new(&IsosurfaceSpec {
        function,
        container: Container::Box {
            corner1: DVec3::splat(-1.0),
            corner2: DVec3::splat(1.0),
        },
        threshold: 0.0,
        accuracy: 1e-6,
        max_gradient,
        open: false,
        max_trace,
    })
    .unwrap()
}

fn crossings(
    intersect: impl Fn(DVec3, DVec3, &mut Roots),
    origin: DVec3,
    direction: DVec3,
) -> Vec<f64> {
    let mut roots = Roots::new();
    intersect(origin, direction, &mut roots);
    let mut found: Vec<f64> = roots.iter().map(|(t, _)| t).collect();
    found.sort_by(f64::total_cmp);
    found
}

#[test]
fn isosurface_sphere_known_answer() {
    let shape = isosurface(sphere_function(0.5), 1.1, 8);
    let hits = crossings(
        |o, d, r| shape.intersect(o, d, r),
        DVec3::new(0.0, 0.0, -3.0),
        DVec3::Z,
    );
    assert_eq!(hits.len(), 2, "{hits:?}");
    assert!((hits[0] - 2.5).abs() < 1e-5 && (hits[1] - 3.5).abs() < 1e-5);
    let normal = shape.normal(DVec3::new(0.0, 0.0, -0.5), 0).normalize();
    assert!(normal.abs_diff_eq(-DVec3::Z, 1e-4));
    // max_trace 1 keeps only the nearest crossing.
    let first = isosurface(sphere_function(0.5), 1.1, 1);
    let hits = crossings(
        |o, d, r| first.intersect(o, d, r),
        DVec3::new(0.0, 0.0, -3.0),
        DVec3::Z,
    );
    assert_eq!(hits.len(), 1);
}

#[test]
fn isosurface_with_too_low_max_gradient_loses_the_surface() {
    // f = 4 |p| - 2 has slope 4: with max_gradient 0.5 the whole ray is rejected.
    let steep = Arc::new(Function::new(
        Node::Binary(
            Binary::Subtract,
            Box::new([
                Node::Binary(
                    Binary::Multiply,
                    Box::new([
                        Node::Constant(4.0),
                        Node::Internal(
                            Internal::Radius,
                            vec![Node::Parameter(0), Node::Parameter(1), Node::Parameter(2)]
                                .into_boxed_slice(),
                        ),
                    ]),
                ),
                Node::Constant(2.0),
            ]),
        ),
        3,
    ));
    let low = isosurface(steep.clone(), 0.5, 8);
    let high = isosurface(steep, 4.5, 8);
    let ray = (DVec3::new(0.0, 0.0, -3.0), DVec3::Z);
    assert!(crossings(|o, d, r| low.intersect(o, d, r), ray.0, ray.1).is_empty());
    assert_eq!(
        crossings(|o, d, r| high.intersect(o, d, r), ray.0, ray.1).len(),
        2
    );
}

#[test]
fn isosurface_crossings_flip_inside() {
    let shape = isosurface(sphere_function(0.7), 1.1, 8);
    assert_crossings_flip_inside(
        3,
        2.0,
        1e-3,
        1e-4,
        |o, d, r| shape.intersect(o, d, r),
        |p| shape.inside(p),
    );
}

fn wavy_height_field(smooth: bool) -> HeightField {
    let (columns, rows) = (9, 7);
    let heights = (0..rows)
        .flat_map(|row| {
            (0..columns).map(move |column| {
                0.5 + 0.3 * (column as f64 * 0.9).sin() * (row as f64 * 0.7).cos()
            })
        })
        .collect();
    HeightField::new(&HeightFieldSpec {
        columns,
        rows,
        heights,
        smooth,
        water_level: 0.0,
        source: None,
    })
    .unwrap()
}

#[test]
fn height_field_known_answer_and_split() {
    // Corner heights 0 (x0 z0), 1 (x1 z0), 0 (x0 z1), 1 (x1 z1) on a single cell: the
    // lower triangle (x0 z0, x1 z0, x0 z1) at u = 0.3, v = 0.2 is 0.3 high.
    let field = HeightField::new(&HeightFieldSpec {
        columns: 2,
        rows: 2,
        heights: vec![0.0, 1.0, 0.0, 1.0],
        smooth: false,
        water_level: 0.0,
        source: None,
    })
    .unwrap();
    let hits = crossings(
        |o, d, r| field.intersect(o, d, r),
        DVec3::new(0.3, 5.0, 0.2),
        -DVec3::Y,
    );
    assert_eq!(hits.len(), 1);
    assert!((5.0 - hits[0] - 0.3).abs() < 1e-12);
    assert!(field.inside(DVec3::new(0.3, 0.1, 0.2)));
    assert!(field.inside(DVec3::new(0.3, -1.0, 0.2)));
    assert!(!field.inside(DVec3::new(0.3, 0.5, 0.2)));
    assert!(!field.inside(DVec3::new(1.3, 0.1, 0.2)));
}

#[test]
fn height_field_crossings_flip_inside_and_normals_point_up() {
    for smooth in [false, true] {
        let field = wavy_height_field(smooth);
        assert_crossings_flip_inside(
            5,
            1.5,
            1e-6,
            1e-7,
            |o, d, r| field.intersect(o, d, r),
            |p| field.inside(p),
        );
        for (x, z) in [(0.31, 0.52), (0.77, 0.13), (0.05, 0.95)] {
            let hits = crossings(
                |o, d, r| field.intersect(o, d, r),
                DVec3::new(x, 3.0, z),
                -DVec3::Y,
            );
            let point = DVec3::new(x, 3.0 - hits[0], z);
            let normal = field.normal(point).normalize();
            assert!(normal.y > 0.0);
            assert!(field.inside(point - normal * 1e-6));
            assert!(!field.inside(point + normal * 1e-6));
        }
    }
}

/// A smooth 4 by 4 field scaled by <1, 5, 2>: POV-Ray's normals at points over it
/// (`trace` in POV-Ray 3.7; heights in 16-bit units, row by row from z = 0).
#[test]
fn smooth_height_field_normals_match_povray() {
    let levels = [
        26214.0, 36535.0, 38114.0, 10858.0, 15291.0, 25970.0, 31025.0, 50250.0, 8738.0, 16006.0,
        27912.0, 50613.0, 6553.0, 7767.0, 16262.0, 39321.0,
    ];
    let field = HeightField::new(&HeightFieldSpec {
        columns: 4,
        rows: 4,
        heights: levels.iter().map(|level| level / 65536.0).collect(),
        smooth: true,
        water_level: 0.0,
        source: None,
    })
    .unwrap();
    // Normals map through the inverse transpose of scale <1, 5, 2>.
    let world_from_local_normal = glam::DMat3::from_diagonal(DVec3::new(1.0, 0.2, 0.5));
    let known = [
        (
            (0.04359, 0.23673),
            (-0.857528884584, 0.316899456125, 0.405239369770),
        ),
        (
            (0.37659, 0.23673),
            (-0.731786755891, 0.388258266035, 0.560128255633),
        ),
        (
            (0.70959, 0.23673),
            (-0.687440230904, 0.620588324027, 0.377221501265),
        ),
        (
            (0.04359, 0.56973),
            (-0.878663311760, 0.369784238048, 0.302010598918),
        ),
        (
            (0.04359, 0.90273),
            (-0.513678832267, 0.802893189777, 0.302484021215),
        ),
        (
            (0.70959, 0.56973),
            (-0.958706609659, 0.209451080061, 0.192384723035),
        ),
        (
            (0.70959, 0.90273),
            (-0.935522086078, 0.152611577774, 0.318603409884),
        ),
    ];
    for ((x, z), (nx, ny, nz)) in known {
        let hits = crossings(
            |o, d, r| field.intersect(o, d, r),
            DVec3::new(x, 3.0, z),
            -DVec3::Y,
        );
        let point = DVec3::new(x, 3.0 - hits[0], z);
        let normal = field
            .world_normal(point, world_from_local_normal)
            .normalize();
        let expected = DVec3::new(nx, ny, nz);
        assert!(
            (normal - expected).abs().max_element() < 1e-9,
            "at ({x}, {z}): {normal} against {expected}"
        );
    }
}

fn sweep(spline: SweepSpline) -> SphereSweep {
    SphereSweep::new(&SphereSweepSpec {
        spline,
        spheres: vec![
            (DVec3::new(-1.0, 0.0, 0.0), 0.2),
            (DVec3::new(-0.3, 0.6, 0.1), 0.35),
            (DVec3::new(0.4, -0.2, 0.0), 0.25),
            (DVec3::new(1.0, 0.5, -0.3), 0.3),
            (DVec3::new(1.2, 0.9, 0.2), 0.1),
        ],
        tolerance: 1e-6,
    })
    .unwrap()
}

#[test]
fn sphere_sweep_crossings_flip_inside_and_normals_point_out() {
    for spline in [
        SweepSpline::Linear,
        SweepSpline::BSpline,
        SweepSpline::Cubic,
    ] {
        let shape = sweep(spline);
        assert_crossings_flip_inside(
            7,
            1.5,
            1e-6,
            1e-7,
            |o, d, r| shape.intersect(o, d, r),
            |p| shape.inside(p),
        );
        let mut state = 11u64;
        let mut random = || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for _ in 0..200 {
            let origin = DVec3::new(random(), random(), random()) * 3.0;
            let direction = (DVec3::new(random(), random(), random()) * 0.3 - origin).normalize();
            let hits = crossings(|o, d, r| shape.intersect(o, d, r), origin, direction);
            let Some(&first) = hits.iter().find(|&&t| t > 0.0) else {
                continue;
            };
            if shape.inside(origin) {
                continue;
            }
            let point = origin + direction * first;
            let normal = shape.normal(point).normalize();
            assert!(
                !shape.inside(point + normal * 1e-5),
                "{spline:?} at {point}"
            );
            assert!(normal.dot(direction) < 1e-9, "{spline:?} at {point}");
        }
    }
}

#[test]
fn linear_sweep_of_two_equal_spheres_is_a_capsule() {
    let capsule = SphereSweep::new(&SphereSweepSpec {
        spline: SweepSpline::Linear,
        spheres: vec![
            (DVec3::new(-1.0, 0.0, 0.0), 0.5),
            (DVec3::new(1.0, 0.0, 0.0), 0.5),
        ],
        tolerance: 1e-6,
    })
    .unwrap();
    let hits = crossings(
        |o, d, r| capsule.intersect(o, d, r),
        DVec3::new(0.3, 2.0, 0.0),
        -DVec3::Y,
    );
    assert_eq!(hits.len(), 2);
    assert!((hits[0] - 1.5).abs() < 1e-12 && (hits[1] - 2.5).abs() < 1e-12);
    let hits = crossings(
        |o, d, r| capsule.intersect(o, d, r),
        DVec3::new(-3.0, 0.0, 0.0),
        DVec3::X,
    );
    assert_eq!(hits.len(), 2);
    assert!((hits[0] - 1.5).abs() < 1e-12 && (hits[1] - 4.5).abs() < 1e-12);
}
