//! The patterns that need no noise: simple shapes (boxed, cylindrical, onion, radial,
//! spiral1, spiral2, leopard...) and the block patterns (checker, brick, hexagon, square, triangular,
//! cubic).
//!
//! In: a pattern-space point after turbulence and warps. Out: the raw value (before
//! frequency, phase and wave) or the block index. Holds: pure; every formula below was
//! checked against values POV-Ray 3.7 prints through pattern and pigment functions.

use std::f64::consts::PI;

use glam::DVec3;

/// Offset POV-Ray adds to each coordinate before flooring in the checker pattern.
const CHECKER_OFFSET: f64 = 1e-10;

/// Height of one row of the hexagon and triangular patterns' triangles (side 1).
const TRIANGLE_HEIGHT: f64 = 0.866_025_403_784_438_6;

/// Which of two checker blocks (0 or 1) the pattern-space point lies in.
pub fn checker_block(point: DVec3) -> usize {
    let sum = (point.x + CHECKER_OFFSET).floor()
        + (point.y + CHECKER_OFFSET).floor()
        + (point.z + CHECKER_OFFSET).floor();
    // Sums beyond 2^53 are all even; rem_euclid keeps negative sums in 0..2.
    if sum.rem_euclid(2.0) >= 1.0 {
        1
    } else {
        0
    }
}

/// The gradient pattern's raw value: the projection on the unit direction, values above 1
/// wrapped to their fractional part (POV-Ray's wave wrap then handles the rest).
pub fn gradient_raw(point: DVec3, direction: DVec3) -> f64 {
    let length = direction.length();
    if !(length > 0.0 && length.is_finite()) {
        return 0.0;
    }
    let value = point.dot(direction / length);
    if value > 1.0 {
        value % 1.0
    } else {
        value
    }
}

/// `boxed`: 1 at the origin falling to 0 at the faces of the cube [-1, 1]³.
pub fn boxed(point: DVec3) -> f64 {
    1.0 - point.abs().max_element().min(1.0)
}

/// `cylindrical`: 1 on the y axis falling to 0 at radius 1.
pub fn cylindrical(point: DVec3) -> f64 {
    1.0 - (point.x * point.x + point.z * point.z).sqrt().min(1.0)
}

/// `spherical`: 1 at the origin falling to 0 at radius 1.
pub fn spherical(point: DVec3) -> f64 {
    1.0 - point.length().min(1.0)
}

/// `planar`: 1 on the x-z plane falling to 0 at distance 1.
pub fn planar(point: DVec3) -> f64 {
    1.0 - point.y.abs().min(1.0)
}

/// `onion`: concentric unit shells (the distance from the origin).
pub fn onion(point: DVec3) -> f64 {
    point.length() % 1.0
}

/// `leopard`: `((sin x + sin y + sin z) / 3)²`.
pub fn leopard(point: DVec3) -> f64 {
    let mean = (point.x.sin() + point.y.sin() + point.z.sin()) / 3.0;
    mean * mean
}

/// `radial`: the angle around the y axis in turns, 0 at +x, 0.25 at −z.
pub fn radial(point: DVec3) -> f64 {
    let turns = (-point.z).atan2(point.x) / (2.0 * PI);
    if turns < 0.0 {
        turns + 1.0
    } else {
        turns
    }
}

/// `spiral1 arms`: distance from the z axis plus z plus `arms` times the angle around z in
/// turns (measured from −y); `turbulence` is the scalar turbulence POV-Ray adds for the
/// classic `turbulence` modifier.
pub fn spiral1(point: DVec3, arms: f64, turbulence: f64) -> f64 {
    let radius = (point.x * point.x + point.y * point.y).sqrt();
    let turns = point.y.atan2(point.x) / (2.0 * PI) + 0.25;
    point.z + radius + arms * turns + turbulence
}

/// `spiral2 arms`: two spirals twisting in opposite directions, the sum of exact triangle
/// waves of spiral1's value (without turbulence) and of the distance from the z axis.
pub fn spiral2(point: DVec3, arms: f64, turbulence: f64) -> f64 {
    let radius = (point.x * point.x + point.y * point.y).sqrt();
    exact_triangle(spiral1(point, arms, 0.0)) + exact_triangle(radius) + turbulence
}

/// A triangle wave of period 1 rising from 0 at integers to 1 at half-integers.
fn exact_triangle(value: f64) -> f64 {
    let doubled = 2.0 * (value - value.floor());
    if doubled > 1.0 {
        2.0 - doubled
    } else {
        doubled
    }
}

/// `cubic`: which of the six pyramids around the half axes (+x, +y, +z, −x, −y, −z) the
/// point lies in.
pub fn cubic_block(point: DVec3) -> usize {
    let magnitude = point.abs();
    let axis = if magnitude.x >= magnitude.y && magnitude.x >= magnitude.z {
        0
    } else if magnitude.y >= magnitude.z {
        1
    } else {
        2
    };
    if point[axis] < 0.0 {
        axis + 3
    } else {
        axis
    }
}

/// `square`: unit squares in the x-z plane in a 2×2 arrangement of four blocks.
pub fn square_block(point: DVec3) -> usize {
    let column = point.x.floor().rem_euclid(2.0) >= 1.0;
    let row = point.z.floor().rem_euclid(2.0) >= 1.0;
    match (column, row) {
        (false, false) => 0,
        (false, true) => 1,
        (true, true) => 2,
        (true, false) => 3,
    }
}

/// `hexagon`: hexagons of side 1 in the x-z plane, block 0 centred at the origin, block 1
/// next along +z, the six neighbours of a hexagon alternating between the other two.
pub fn hexagon_block(point: DVec3) -> usize {
    // Hexagon centres form the lattice i·(1.5, √3/2) + j·(0, √3); the hexagon holding a
    // point is the one with the nearest centre.
    let column_width = 1.5;
    let row_height = 2.0 * TRIANGLE_HEIGHT;
    let i_estimate = (point.x / column_width).floor();
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for i in [i_estimate, i_estimate + 1.0] {
        let centre_x = i * column_width;
        let shifted_z = point.z - i * TRIANGLE_HEIGHT;
        let j = (shifted_z / row_height).round();
        let centre_z = i * TRIANGLE_HEIGHT + j * row_height;
        let distance = (point.x - centre_x).powi(2) + (point.z - centre_z).powi(2);
        if distance < best.0 {
            best = (distance, i, j);
        }
    }
    (2.0 * best.1 + best.2).rem_euclid(3.0) as usize % 3
}

/// `triangular`: equilateral triangles of side 1 in the x-z plane, six blocks arranged in
/// hexagons.
pub fn triangular_block(point: DVec3) -> usize {
    let row = (point.z / TRIANGLE_HEIGHT).floor();
    let height_in_row = point.z - row * TRIANGLE_HEIGHT;
    let half_width = 0.5 * (1.0 - height_in_row / TRIANGLE_HEIGHT);
    let odd_row = row.rem_euclid(2.0) >= 1.0;
    // Apex-up triangles sit between integers in even rows, on integers in odd rows.
    let shift = if odd_row { 0.5 } else { 0.0 };
    let up_index = (point.x + shift).floor();
    let up_centre = up_index + 0.5 - shift;
    let slot = |index: f64| index.rem_euclid(3.0) as usize % 3;
    if (point.x - up_centre).abs() < half_width {
        const EVEN_UP: [usize; 3] = [0, 4, 2];
        const ODD_UP: [usize; 3] = [4, 2, 0];
        if odd_row {
            ODD_UP[slot(up_index)]
        } else {
            EVEN_UP[slot(up_index)]
        }
    } else {
        const EVEN_DOWN: [usize; 3] = [1, 3, 5];
        const ODD_DOWN: [usize; 3] = [5, 1, 3];
        let down_index = (point.x + 0.5 - shift).floor();
        if odd_row {
            ODD_DOWN[slot(down_index)]
        } else {
            EVEN_DOWN[slot(down_index)]
        }
    }
}

/// `brick`: block 0 (mortar) or 1 (brick). Courses are `size.y` high with the mortar in the
/// top `mortar` of each; odd courses shift the bricks half a length along x, even courses
/// half a depth along z; the mortar lies at the far end of each brick along x and z.
///
/// POV-Ray evaluates the pattern 1e-10 further along each axis (measured: at x = -9e-11 it
/// gives brick, at 0.9875 - 9e-11 with `brick_size 1 mortar 0.0125` mortar), so a face lying
/// on a brick boundary, such as a box top at y = 0 under `rotate z*90` (which leaves x at
/// about -1e-16 there), shows bricks rather than speckled mortar.
pub fn brick_block(point: DVec3, size: DVec3, mortar: f64) -> usize {
    let point = point + DVec3::splat(1e-10);
    let course = (point.y / size.y).floor();
    let in_course = point.y - course * size.y;
    let odd = course.rem_euclid(2.0) >= 1.0;
    let x = point.x + if odd { 0.5 * size.x } else { 0.0 };
    let z = point.z + if odd { 0.0 } else { 0.5 * size.z };
    let in_length = x - (x / size.x).floor() * size.x;
    let in_depth = z - (z / size.z).floor() * size.z;
    let is_mortar =
        in_course >= size.y - mortar || in_length >= size.x - mortar || in_depth >= size.z - mortar;
    if is_mortar {
        0
    } else {
        1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::pattern::{Wave, WaveShape};

    /// The points POV-Ray's values below were printed at.
    fn probe(i: usize) -> DVec3 {
        let i = i as f64;
        DVec3::new(-1.3 + 0.77 * i, 0.4 - 0.31 * i, 0.2 + 0.53 * i)
    }

    fn check(name: &str, values: [f64; 6], pattern: impl Fn(DVec3) -> f64) {
        for (i, expected) in values.iter().enumerate() {
            let got = pattern(probe(i));
            assert!(
                (got - expected).abs() < 2e-5,
                "{name} at {:?}: {got} != {expected}",
                probe(i)
            );
        }
    }

    #[test]
    fn shape_patterns_match_povray() {
        let ramp = Wave::new(WaveShape::Ramp);
        let triangle = Wave::new(WaveShape::Triangle);
        check(
            "onion",
            [0.37477, 0.90659, 0.30138, 0.12252, 0.04243, 0.99343],
            |p| ramp.apply(onion(p)),
        );
        check(
            "leopard",
            [0.01566, 0.00701, 0.10488, 0.19283, 0.10364, 0.00051],
            |p| ramp.apply(leopard(p)),
        );
        check(
            "radial",
            [0.52429, 0.65005, 0.77996, 0.83176, 0.85416, 0.86617],
            |p| ramp.apply(radial(p)),
        );
        check("boxed", [0.0, 0.27, 0.0, 0.0, 0.0, 0.0], |p| {
            ramp.apply(boxed(p))
        });
        check(
            "spiral1 3",
            [0.66481, 0.87449, 0.03737, 0.89970, 0.34464, 0.38995],
            |p| triangle.apply(spiral1(p, 3.0, 0.0)),
        );
        check(
            "spiral2 3",
            [0.77007, 0.40127, 0.62299, 0.36195, 0.81612, 0.40915],
            |p| triangle.apply(spiral2(p, 3.0, 0.0)),
        );
        check(
            "spiral2 3 ramp",
            [0.385035, 0.799364, 0.688507, 0.180973, 0.408060, 0.795426],
            |p| ramp.apply(spiral2(p, 3.0, 0.0)),
        );
        check(
            "spiral1 2 ramp",
            [0.965112, 0.714025, 0.849397, 0.276760, 0.647857, 0.012402],
            |p| ramp.apply(spiral1(p, 2.0, 0.0)),
        );
    }

    #[test]
    fn square_tiles_match_povray() {
        // POV-Ray's `tiling 1` through a black-to-white map.
        let ramp = Wave::new(WaveShape::Ramp);
        let square_tiles = |p| crate::texture::pattern::tiling::tiling_value(1, p);
        let value = |x, z| ramp.apply(square_tiles(DVec3::new(x, 0.0, z)));
        assert!((value(-0.5, 0.5) - 0.0).abs() < 1e-9);
        assert!((value(-0.7, 0.5) - 0.4).abs() < 1e-9);
        assert!((value(-0.8, 0.9) - 0.8).abs() < 1e-9);
        assert!((value(-1.0, 0.3) - 1.0).abs() < 1e-9);
        check("tiling 1", [0.6, 0.46, 0.52, 0.98, 0.56, 0.7], |p| {
            ramp.apply(square_tiles(p))
        });
    }

    #[test]
    fn block_patterns_match_povray() {
        check("brick", [1.0, 1.0, 0.0, 1.0, 1.0, 1.0], |p| {
            brick_block(p, DVec3::new(8.0, 3.0, 4.5), 0.5) as f64
        });
        check("hexagon", [2.0, 0.0, 1.0, 0.0, 0.0, 2.0], |p| {
            hexagon_block(p) as f64
        });
        check("square", [0.0, 3.0, 1.0, 2.0, 3.0, 0.0], |p| {
            square_block(p) as f64
        });
        check("triangular", [4.0, 2.0, 4.0, 3.0, 5.0, 3.0], |p| {
            triangular_block(p) as f64
        });
        check("cubic", [3.0, 2.0, 2.0, 2.0, 2.0, 2.0], |p| {
            cubic_block(p) as f64
        });
        check("checker", [0.0, 1.0, 0.0, 1.0, 0.0, 0.0], |p| {
            checker_block(p) as f64
        });
    }

    #[test]
    fn brick_mortar_lines_match_povray() {
        let size = DVec3::new(8.0, 3.0, 4.5);
        // Mortar on top of each course, and at the far end of bricks along x and z.
        assert_eq!(brick_block(DVec3::new(2.1, -0.4, 2.1), size, 0.5), 0);
        assert_eq!(brick_block(DVec3::new(2.1, 2.6, 1.0), size, 0.5), 0);
        assert_eq!(brick_block(DVec3::new(3.7, -1.5, 2.1), size, 0.5), 0);
        assert_eq!(brick_block(DVec3::new(3.3, -1.5, 2.1), size, 0.5), 1);
        assert_eq!(brick_block(DVec3::new(2.1, 1.5, 1.9), size, 0.5), 0);
        assert_eq!(brick_block(DVec3::new(2.1, -1.5, 4.2), size, 0.5), 0);
    }
}
