//! Warps: the `warp { }` blocks of a pattern, which move the evaluation point before the
//! pattern is looked up.
//!
//! In: a point in the frame the warp was written in. Out: the point the pattern is looked
//! up at. Holds: pure, allocation-free; every warp maps finite points to finite points.
//!
//! Measured against POV-Ray 3.7 (a gradient per axis read back through pigment functions):
//! - black hole: with `d = p − centre` and closeness `c = 1 − |d|/radius` inside the radius,
//!   the point moves to `p + d·min(1, strength·c^falloff)` (`inverse`: minus).
//!   With `repeat`, the centre of cell `n = ⌊p/repeat⌋` (0 on axes without repeat) is
//!   `centre + n·repeat`, plus `turbulence` times the cell's three random numbers, which
//!   are crackle's per-cube numbers for the cube with index `n` (bit for bit).
//! - repeat `w·axis`: the copy index `n = ⌊p_axis / w⌋`; the point moves to its place in the
//!   first copy; in odd copies each `flip` axis mirrors there (the repeat axis within the
//!   copy, `w − p`, the others about 0); then `n·offset` is added.
//! - cylindrical: `(u·r^e, y, r)` with `r` the distance from the y axis and
//!   `u = atan2(z, x)/2π` in [0, 1); spherical: `(u·r^e, v·r^e, r)` with
//!   `v = 1 − acos(y/r)/π`; toroidal: `(u·d^e, v·d^e, d)` with `d` the distance from the
//!   major circle and `v = atan2(−y, R − r_xz)/2π`; `orientation` and the planar warp's
//!   normal act through [`orient`] (checked for axes and oblique vectors).

use std::f64::consts::PI;

use glam::DVec3;

use crate::noise::{cube_random_vector, vector_turbulence, NoiseGenerator, TurbulenceShape};

/// One warp.
#[derive(Clone, Debug, PartialEq)]
pub enum Warp {
    /// `warp { turbulence .. octaves .. omega .. lambda .. }`.
    Turbulence {
        /// Turbulence amount per axis.
        amount: DVec3,
        /// Octaves, omega and lambda.
        shape: TurbulenceShape,
    },
    /// `warp { black_hole centre, radius .. }`.
    BlackHole(BlackHole),
    /// `warp { repeat direction offset .. flip .. }`.
    Repeat(Repeat),
    /// `warp { cylindrical | spherical | toroidal .. }`.
    Mapping(Mapping),
    /// `warp { planar [normal, distance] }`.
    Planar {
        /// Normal of the plane the pattern is taken from (unit length).
        normal: DVec3,
        /// Distance of that plane from the origin along the normal.
        distance: f64,
    },
}

/// A black hole warp's settings.
#[derive(Clone, Debug, PartialEq)]
pub struct BlackHole {
    /// Centre (with `repeat`: the offset of the centre inside each cell).
    pub centre: DVec3,
    /// Radius of the affected sphere.
    pub radius: f64,
    /// Power of the closeness (default 2).
    pub falloff: f64,
    /// Scale of the force (default 1).
    pub strength: f64,
    /// Push points away instead of pulling (`inverse`).
    pub inverse: bool,
    /// Cell size of a repeated black hole; 0 on an axis: not repeated on that axis.
    pub repeat: DVec3,
    /// Per-cell random jitter of the centre (only with `repeat`).
    pub jitter: DVec3,
}

impl BlackHole {
    /// A black hole at `centre` with `radius` and POV-Ray's defaults for the rest.
    pub fn new(centre: DVec3, radius: f64) -> BlackHole {
        BlackHole {
            centre,
            radius,
            falloff: 2.0,
            strength: 1.0,
            inverse: false,
            repeat: DVec3::ZERO,
            jitter: DVec3::ZERO,
        }
    }
}

/// A repeat warp's settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Repeat {
    /// Which axis repeats (0, 1 or 2).
    pub axis: usize,
    /// Width of one copy along that axis (non-zero).
    pub width: f64,
    /// Translation added per copy.
    pub offset: DVec3,
    /// Which axes mirror in every other copy.
    pub flip: [bool; 3],
}

/// The kinds of mapping warp.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MappingKind {
    /// Around the y axis.
    Cylindrical,
    /// Around the origin.
    Spherical,
    /// Around a circle in the x-z plane.
    Toroidal,
}

/// A cylindrical, spherical or toroidal warp.
#[derive(Clone, Debug, PartialEq)]
pub struct Mapping {
    /// Which mapping.
    pub kind: MappingKind,
    /// The `orientation` vector, unit length (default +z); see [`orient`].
    pub orientation: DVec3,
    /// `dist_exp`: the mapped u and v are scaled by distance^dist_exp (default 0).
    pub dist_exp: f64,
    /// `major_radius` of the toroidal warp (default 1).
    pub major_radius: f64,
}

impl Mapping {
    /// A mapping warp with POV-Ray's defaults.
    pub fn new(kind: MappingKind) -> Mapping {
        Mapping {
            kind,
            orientation: DVec3::Z,
            dist_exp: 0.0,
            major_radius: 1.0,
        }
    }

    /// Sets the orientation vector (default +z); a zero vector keeps the default.
    pub fn set_orientation(&mut self, orientation: DVec3) {
        if let Some(direction) = orientation.try_normalize() {
            self.orientation = direction;
        }
    }
}

impl Warp {
    /// The point the warp sends `point` to.
    pub fn apply(&self, point: DVec3, generator: NoiseGenerator) -> DVec3 {
        let moved = match self {
            Warp::Turbulence { amount, shape } => {
                point + *amount * vector_turbulence(point, shape, generator)
            }
            Warp::BlackHole(hole) => black_hole(hole, point),
            Warp::Repeat(repeat) => repeat_copy(repeat, point),
            Warp::Mapping(mapping) => map_around(mapping, point),
            Warp::Planar { normal, distance } => planar(*normal, *distance, point),
        };
        if moved.is_finite() {
            moved
        } else {
            point
        }
    }
}

/// The black hole warp.
fn black_hole(hole: &BlackHole, point: DVec3) -> DVec3 {
    let mut centre = hole.centre;
    if hole.repeat != DVec3::ZERO {
        let mut cell = DVec3::ZERO;
        for axis in 0..3 {
            if hole.repeat[axis] > 0.0 {
                cell[axis] = (point[axis] / hole.repeat[axis]).floor();
                centre[axis] += cell[axis] * hole.repeat[axis];
            }
        }
        if hole.jitter != DVec3::ZERO {
            let index = [cell.x as i64, cell.y as i64, cell.z as i64];
            centre += hole.jitter * cube_random_vector(index);
        }
    }
    let offset = point - centre;
    let distance = offset.length();
    if distance.is_nan() || distance >= hole.radius || hole.radius <= 0.0 {
        return point;
    }
    let closeness = 1.0 - distance / hole.radius;
    let force = (closeness.powf(hole.falloff) * hole.strength).min(1.0);
    if hole.inverse {
        point - offset * force
    } else {
        point + offset * force
    }
}

/// The repeat warp.
fn repeat_copy(repeat: &Repeat, point: DVec3) -> DVec3 {
    let axis = repeat.axis;
    let copy = (point[axis] / repeat.width).floor();
    let mut moved = point;
    moved[axis] -= copy * repeat.width;
    // The copy is mirrored first and offset afterwards (measured).
    if copy.rem_euclid(2.0) >= 1.0 {
        for (flip_axis, flips) in repeat.flip.iter().enumerate() {
            if *flips {
                moved[flip_axis] = if flip_axis == axis {
                    repeat.width - moved[flip_axis]
                } else {
                    -moved[flip_axis]
                };
            }
        }
    }
    moved + copy * repeat.offset
}

/// Fraction of a turn of the angle `atan2(y, x)`, in [0, 1).
fn turn_fraction(y: f64, x: f64) -> f64 {
    let turns = y.atan2(x) / (2.0 * PI);
    if turns < 0.0 {
        turns + 1.0
    } else {
        turns
    }
}

/// The cylindrical, spherical and toroidal warps.
fn map_around(mapping: &Mapping, point: DVec3) -> DVec3 {
    orient(map_around_y(mapping, point), mapping.orientation)
}

/// The cylindrical, spherical and toroidal mappings before the orientation.
fn map_around_y(mapping: &Mapping, p: DVec3) -> DVec3 {
    let u = turn_fraction(p.z, p.x);
    let radial = (p.x * p.x + p.z * p.z).sqrt();
    match mapping.kind {
        MappingKind::Cylindrical => DVec3::new(u * radial.powf(mapping.dist_exp), p.y, radial),
        MappingKind::Spherical => {
            let distance = p.length();
            let v = if distance > 0.0 {
                1.0 - (p.y / distance).clamp(-1.0, 1.0).acos() / PI
            } else {
                0.5
            };
            let scale = distance.powf(mapping.dist_exp);
            DVec3::new(u * scale, v * scale, distance)
        }
        MappingKind::Toroidal => {
            let across = mapping.major_radius - radial;
            let distance = (across * across + p.y * p.y).sqrt();
            let v = turn_fraction(-p.y, across);
            let scale = distance.powf(mapping.dist_exp);
            DVec3::new(u * scale, v * scale, distance)
        }
    }
}

/// The planar warp: the point's x and y and the plane's distance, oriented by the normal.
fn planar(normal: DVec3, distance: f64, point: DVec3) -> DVec3 {
    orient(DVec3::new(point.x, point.y, distance), normal)
}

/// POV-Ray's orientation of a mapped point `m` by a unit vector `o` (measured; it is not a
/// rotation): `(m_x(o_y + o_z), m_y(o_x + o_z), o_y·m_y − o_x·m_x) + m_z·(o_x, −o_y, o_z)`.
/// The default `o = +z` leaves `m` unchanged.
fn orient(m: DVec3, o: DVec3) -> DVec3 {
    DVec3::new(m.x * (o.y + o.z), m.y * (o.x + o.z), o.y * m.y - o.x * m.x)
        + m.z * DVec3::new(o.x, -o.y, o.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The probe points POV-Ray's values below were printed at.
    fn probe(i: usize) -> DVec3 {
        let i = i as f64;
        DVec3::new(-0.9 + 0.31 * i, 0.45 - 0.17 * i, 0.3 - 0.11 * i)
    }

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).abs().max_element() < 2e-5
    }

    const GENERATOR: NoiseGenerator = NoiseGenerator::RangeCorrected;

    #[test]
    fn black_hole_pushes_clips_and_inverts_like_povray() {
        let mut hole = BlackHole::new(DVec3::ZERO, 1.0);
        let warp = |hole: &BlackHole, p| Warp::BlackHole(hole.clone()).apply(p, GENERATOR);
        assert!(close(
            warp(&hole, probe(3)),
            DVec3::new(0.05575, -0.11151, -0.05575)
        ));
        hole.inverse = true;
        assert!(close(
            warp(&hole, probe(3)),
            DVec3::new(0.00425, -0.00849, -0.00425)
        ));
        hole.inverse = false;
        hole.strength = 3.0;
        assert!(close(warp(&hole, probe(3)), probe(3) * 2.0));
        assert_eq!(warp(&hole, probe(0)), probe(0));
    }

    #[test]
    fn repeated_black_hole_acts_in_every_cell() {
        // POV-Ray's `black_hole <0.5, 0.5, 0.5>, 0.4 repeat <1, 1, 1>`, values wrapped.
        let mut hole = BlackHole::new(DVec3::splat(0.5), 0.4);
        hole.repeat = DVec3::ONE;
        let moved = black_hole(&hole, probe(5));
        assert!(close(
            moved - moved.floor(),
            DVec3::new(0.65790, 0.60526, 0.76316)
        ));
    }

    #[test]
    fn repeated_black_hole_jitters_each_cell_like_povray() {
        // `black_hole <.45,.45,.45>, .45 strength 1e6 inverse repeat <1,1,R>
        // turbulence <.1,.1,.1>` pulls the cell's points onto its jittered centre; POV-Ray
        // printed the centres' jitter fractions (colour precision) for these cells.
        let mut hole = BlackHole::new(DVec3::splat(0.45), 0.45);
        hole.strength = 1e6;
        hole.inverse = true;
        hole.jitter = DVec3::splat(0.1);
        let cases = [
            (DVec3::ONE, [1, -1, -1], [0.336299, 0.265322, 0.886147]),
            (DVec3::ONE, [2, 1, 0], [0.354116, 0.521504, 0.780446]),
            (
                DVec3::new(1.0, 1.0, 0.0),
                [-1, 1, 0],
                [0.554328, 0.796625, 0.330808],
            ),
        ];
        for (repeat, cell, expected) in cases {
            hole.repeat = repeat;
            let cell = DVec3::new(cell[0] as f64, cell[1] as f64, cell[2] as f64);
            let centre = black_hole(&hole, cell + DVec3::splat(0.5));
            let fraction = (centre - cell - DVec3::splat(0.45)) / 0.1;
            assert!(
                (fraction - DVec3::from_array(expected)).abs().max_element() < 1e-5,
                "{cell}: {fraction}"
            );
        }
    }

    #[test]
    fn repeat_flips_a_copy_before_offsetting_it() {
        // POV-Ray's `repeat x * 0.9 offset <0.2, 0.4, 0> flip <1, 1, 0>` at y = 0.3.
        let repeat = Repeat {
            axis: 0,
            width: 0.9,
            offset: DVec3::new(0.2, 0.4, 0.0),
            flip: [true, true, false],
        };
        let cases = [
            (-2.05, -0.35, -1.5),
            (-1.75, -0.35, -0.5),
            (-0.85, 0.65, -0.7),
            (1.25, 0.75, 0.1),
            (1.85, 0.45, 1.1),
        ];
        for (x, expected_x, expected_y) in cases {
            let moved = repeat_copy(&repeat, DVec3::new(x, 0.3, 0.0));
            assert!(
                close(moved, DVec3::new(expected_x, expected_y, 0.0)),
                "{x}: {moved}"
            );
        }
    }

    #[test]
    fn repeat_offsets_and_flips_copies() {
        let repeat = Repeat {
            axis: 0,
            width: 0.5,
            offset: DVec3::new(0.1, 0.2, 0.3),
            flip: [false; 3],
        };
        let moved = repeat_copy(&repeat, probe(0));
        assert!(close(moved, DVec3::new(-0.1, 0.05, -0.3)));
        let flipping = Repeat {
            offset: DVec3::ZERO,
            flip: [true, true, false],
            ..repeat
        };
        assert!(close(
            repeat_copy(&flipping, probe(2)),
            DVec3::new(0.28, -0.11, 0.08)
        ));
        assert!(close(
            repeat_copy(&flipping, probe(5)),
            DVec3::new(0.35, 0.4, -0.25)
        ));
    }

    #[test]
    fn mapping_warps_match_povray() {
        let cylinder = Mapping::new(MappingKind::Cylindrical);
        assert!(close(
            map_around(&cylinder, probe(0)),
            DVec3::new(0.44879, 0.45, 0.94868)
        ));
        let sphere = Mapping {
            dist_exp: 1.0,
            ..Mapping::new(MappingKind::Spherical)
        };
        assert!(close(
            map_around(&sphere, probe(0)),
            DVec3::new(0.47123, 0.67303, 1.05)
        ));
        let torus = Mapping::new(MappingKind::Toroidal);
        assert!(close(
            map_around(&torus, probe(2)),
            DVec3::new(0.45571, 0.97550, 0.71728)
        ));
        let thin_torus = Mapping {
            dist_exp: 1.0,
            major_radius: 0.5,
            ..Mapping::new(MappingKind::Toroidal)
        };
        assert!(close(
            map_around(&thin_torus, probe(0)),
            DVec3::new(0.28519, 0.39731, 0.63547)
        ));
    }

    #[test]
    fn orientation_along_axes_turns_the_mapped_point() {
        // POV-Ray's `cylindrical orientation x` and `orientation y` at probe point 0.
        let wrap = |v: DVec3| v - v.floor();
        let mut along_x = Mapping::new(MappingKind::Cylindrical);
        along_x.set_orientation(DVec3::X);
        let mapped = wrap(map_around(&along_x, probe(0)));
        assert!(close(mapped, DVec3::new(0.94868, 0.45, 0.55121)));
        let mut along_y = Mapping::new(MappingKind::Cylindrical);
        along_y.set_orientation(DVec3::Y);
        let mapped = wrap(map_around(&along_y, probe(0)));
        assert!(close(mapped, DVec3::new(0.44879, 0.05132, 0.45)));
    }

    #[test]
    fn planar_takes_the_xy_plane_by_default() {
        let moved = planar(DVec3::Z, 0.0, probe(1));
        assert!(close(moved, DVec3::new(-0.59, 0.28, 0.0)));
        let from_y = planar(DVec3::Y, 0.3, probe(1));
        assert!(close(from_y, DVec3::new(-0.59, -0.3, 0.28)));
        // POV-Ray's `planar <1, 2, 3>, 0.25` at probe point 0, wrapped to [0, 1).
        let oblique = planar(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.25, probe(0));
        let wrapped = oblique - oblique.floor();
        assert!(close(wrapped, DVec3::new(0.86415, 0.34744, 0.68152)));
    }
}
