//! The aperiodic tilings `tiling 26` (Penrose's kites and darts) and `tiling 27` (Penrose's
//! thick and thin rhombs), each bevelled towards its tiles' edges like the periodic tilings.
//!
//! In: a point (x, z) of the plane and the tiling. Out: the value in [0, 1]. Holds: no
//! tables but the tilings' constants; no allocation, and the work per value grows with the
//! logarithm of the point's distance from the origin.
//!
//! What was measured (probe scenes against POV-Ray 3.7, `pigment { tiling N }` through a
//! black-to-white colour map): both tilings are the Penrose tilings with the full symmetry
//! of a regular pentagon about the origin (values repeat under turns by 72° and under the
//! mirror z → −z), with unit long edges: `tiling 26` has a "sun" of five kites round the
//! origin, their axes along x and every 72° from it; `tiling 27` a star of five thick rhombs,
//! their edges from the origin along x and every 72°. Kites and thick rhombs are type 0 of 2,
//! darts and thin rhombs type 1, and the bevel width is one of each tiling (measured).
//!
//! How a value is found: each tile is two Robinson triangles (a golden triangle with a 36°
//! apex, or a golden gnomon with a 108° apex), and a wheel of ten golden triangles round the
//! origin turns into the tiling when it is split ("deflated") again and again, every split
//! scaling the triangles by 1/φ. A point is followed down from a wheel large enough to hold
//! it, one child triangle per split, to the half-tile it lies in; the tile is that triangle
//! and its mirror image across the side the two halves share.

use glam::DVec2;

/// The golden ratio φ.
pub(super) const PHI: f64 = 1.618_033_988_749_895;

/// How close to the origin POV-Ray's value is 1.
pub(super) const ORIGIN_RADIUS: f64 = 1e-10;

/// The kind of a Robinson triangle.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Half {
    /// A golden triangle: 36° at the apex, 72° at the other two corners.
    Golden,
    /// A golden gnomon: 108° at the apex, 36° at the other two corners.
    Gnomon,
}

/// A Robinson triangle: its kind, its apex and its other two corners, in an order that
/// carries its handedness through the splits.
#[derive(Clone, Copy, Debug)]
struct Triangle {
    half: Half,
    apex: DVec2,
    left: DVec2,
    right: DVec2,
}

impl Triangle {
    const fn new(half: Half, apex: DVec2, left: DVec2, right: DVec2) -> Self {
        Self {
            half,
            apex,
            left,
            right,
        }
    }

    /// How far inside the triangle `point` is: the smallest signed distance to the
    /// triangle's sides, positive inside (either handedness).
    fn insideness(&self, point: DVec2) -> f64 {
        let corners = [self.apex, self.left, self.right];
        let orientation = (self.left - self.apex)
            .perp_dot(self.right - self.apex)
            .signum();
        (0..3)
            .map(|i| {
                let from = corners[i];
                let side = corners[(i + 1) % 3] - from;
                orientation * side.perp_dot(point - from) / side.length()
            })
            .fold(f64::INFINITY, f64::min)
    }
}

/// One of the two Penrose tilings.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Penrose {
    /// `tiling 26`: kites and darts.
    KitesAndDarts,
    /// `tiling 27`: thick and thin rhombs.
    Rhombs,
}

impl Penrose {
    /// The tiling of a tiling number, if it is one of these.
    pub(super) fn from_number(number: u8) -> Option<Self> {
        match number {
            26 => Some(Self::KitesAndDarts),
            27 => Some(Self::Rhombs),
            _ => None,
        }
    }

    /// The width over which a tile's value rises towards its edges (measured: the slope of
    /// the values across edges, the same in both tile types).
    fn bevel(self) -> f64 {
        match self {
            Self::KitesAndDarts => 0.224_215_2,
            Self::Rhombs => 0.291_537_6,
        }
    }

    /// The number of splits modulo 4 after which the wheel of golden triangles has the
    /// tiling's layout round the origin (found by comparing with POV-Ray's values; the
    /// layout repeats every fourth split).
    fn split_phase(self) -> u32 {
        match self {
            Self::KitesAndDarts => 0,
            Self::Rhombs => 3,
        }
    }

    /// The tile type of a half-tile: kites and thick rhombs 0, darts and thin rhombs 1.
    fn tile_type(self, half: Half) -> u8 {
        match (self, half) {
            (Self::KitesAndDarts, Half::Golden) | (Self::Rhombs, Half::Gnomon) => 0,
            (Self::KitesAndDarts, Half::Gnomon) | (Self::Rhombs, Half::Golden) => 1,
        }
    }

    /// The triangles one split makes of `triangle` (two or three; `None` pads the list).
    fn split(self, triangle: &Triangle) -> [Option<Triangle>; 3] {
        let Triangle {
            half,
            apex: a,
            left: b,
            right: c,
        } = *triangle;
        let golden = |apex, left, right| Some(Triangle::new(Half::Golden, apex, left, right));
        let gnomon = |apex, left, right| Some(Triangle::new(Half::Gnomon, apex, left, right));
        match (self, half) {
            // A half-kite: its right side is the kite's axis, its left side a long edge.
            (Self::KitesAndDarts, Half::Golden) => {
                let on_axis = a + (c - a) / PHI;
                let on_edge = b + (a - b) / PHI;
                [
                    golden(b, c, on_axis),
                    golden(b, on_edge, on_axis),
                    gnomon(on_edge, on_axis, a),
                ]
            }
            // A half-dart.
            (Self::KitesAndDarts, Half::Gnomon) => {
                let on_base = c + (b - c) / PHI;
                [golden(c, on_base, a), gnomon(on_base, a, b), None]
            }
            // A half thin rhomb: its base is the rhomb's short diagonal.
            (Self::Rhombs, Half::Golden) => {
                let on_side = a + (b - a) / PHI;
                [golden(c, on_side, b), gnomon(on_side, c, a), None]
            }
            // A half thick rhomb: its base is the rhomb's long diagonal.
            (Self::Rhombs, Half::Gnomon) => {
                let on_side = b + (a - b) / PHI;
                let on_base = b + (c - b) / PHI;
                [
                    gnomon(on_base, c, a),
                    gnomon(on_side, on_base, b),
                    golden(on_base, on_side, a),
                ]
            }
        }
    }

    /// The depth of `point` inside the tile whose half is `triangle`, in units of the
    /// bevel: the distance to the nearer of the lines through the triangle's two sides that
    /// are edges of the tile, divided by the bevel width. (The tile's other two edges are
    /// never nearer from this half; and for the dart, which is not convex, POV-Ray measures
    /// to these lines too, not to the edges' ends.)
    fn depth_in_tile(self, triangle: &Triangle, point: DVec2) -> f64 {
        let Triangle {
            apex: a,
            left: b,
            right: c,
            ..
        } = *triangle;
        let edges = match self {
            // Kites and darts: the side from the apex to the right corner is the axis.
            Self::KitesAndDarts => [(a, b), (b, c)],
            // Rhombs: the base is the diagonal.
            Self::Rhombs => [(a, b), (a, c)],
        };
        let distance = edges
            .iter()
            .map(|&(from, to)| line_distance(point, from, to))
            .fold(f64::INFINITY, f64::min);
        distance / self.bevel()
    }

    /// The value at `(x, z)`.
    pub(super) fn value(self, x: f64, z: f64) -> f64 {
        let point = DVec2::new(x, z);
        // POV-Ray gives 1 at the origin itself, though only kites or thick rhombs meet
        // there (measured: 1 up to 1e-10 from it, the values of the tiles from 1.1e-10).
        if point.length() <= ORIGIN_RADIUS {
            return 1.0;
        }
        let Some((mut triangle, splits)) = self.starting_triangle(point) else {
            return 0.0;
        };
        for _ in 0..splits {
            // The child the point is deepest in (the first of equals), which always exists
            // even where rounding puts the point a hair outside every child.
            let mut best = triangle;
            let mut best_insideness = f64::NEG_INFINITY;
            for child in self.split(&triangle).into_iter().flatten() {
                let insideness = child.insideness(point);
                if insideness > best_insideness {
                    best = child;
                    best_insideness = insideness;
                }
            }
            triangle = best;
        }
        let kind = f64::from(self.tile_type(triangle.half));
        let rise = 1.0 - self.depth_in_tile(&triangle, point).clamp(0.0, 1.0);
        // POV-Ray keeps type 0 a millionth below type 1's lowest value (measured: 0.499999
        // on every edge of a kite or thick rhomb).
        const TYPES: f64 = 2.0;
        let value = (kind + rise) / TYPES;
        if kind + 1.0 < TYPES {
            value.min((kind + 1.0) / TYPES - 1e-6)
        } else {
            value
        }
    }

    /// The triangle of the starting wheel that holds `point`, and how many splits lead from
    /// it to the tiles. The wheel is ten golden triangles with their apexes at the origin,
    /// their sides along every multiple of 36° and mirrored in turn, as long as φ to the
    /// number of splits so the tiles come out with unit long edges;
    /// `None` for a point too far out for any wheel (or not finite).
    fn starting_triangle(self, point: DVec2) -> Option<(Triangle, u32)> {
        // The wheel's inner radius is cos 18° times its outer one; a margin keeps the point
        // clear of its rim.
        let cos_18 = (std::f64::consts::PI / 10.0).cos();
        let needed = point.length() / cos_18 * 1.01 + 1.0;
        if !needed.is_finite() || needed >= f64::MAX / PHI.powi(4) {
            return None;
        }
        let mut splits = self.split_phase();
        while PHI.powi(splits as i32) < needed {
            splits += 4;
        }
        let radius = PHI.powi(splits as i32);
        let angle = point.y.atan2(point.x).rem_euclid(std::f64::consts::TAU);
        let step = std::f64::consts::TAU / 10.0;
        // The sector of the wheel the point's direction falls in (rounding may give 10).
        let sector = ((angle / step) as u32).min(9);
        let corner = |index: u32| DVec2::from_angle(f64::from(index) * step) * radius;
        let (near, far) = (corner(sector), corner(sector + 1));
        let (left, right) = if sector.is_multiple_of(2) {
            (far, near)
        } else {
            (near, far)
        };
        Some((
            Triangle::new(Half::Golden, DVec2::ZERO, left, right),
            splits,
        ))
    }
}

/// The distance from `point` to the line through `from` and `to`.
fn line_distance(point: DVec2, from: DVec2, to: DVec2) -> f64 {
    let along = to - from;
    along.perp_dot(point - from).abs() / along.length()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// POV-Ray 3.7's values of `tiling 26` through a black-to-white colour map at random
    /// points, near the origin and far from it.
    const KITES_AND_DARTS_SAMPLES: &[(f64, f64, f64)] = &[
        (-2.1140068220020516, -4.189809912905977, 0.214488089085),
        (1.8112136764782445, -5.130764559989487, 0.194326922297),
        (0.43058405168027036, -1.611732997048973, 0.302548855543),
        (-5.304012902703518, 0.08922879827304264, 0.417386859655),
        (-5.550052098696181, -0.7962517960513695, 0.382788270712),
        (-5.161734917104573, -4.91144383987362, 0.474117189646),
        (-64.5726558652388, -60.61270060783622, 0.226525589824),
        (-237.87774377380543, 80.57373941142544, 0.467168956995),
        (-262.65130702878747, -259.5914304941851, 0.207786738873),
        (396.6693596971768, -5.498844683972948, 0.346716195345),
        (229.00652378993595, 840.9285468801452, 0.153567016125),
        (-488.33955978723685, -977.3855899579622, 0.247736632824),
        (-57340.68417207616, 79996.74735996508, 0.443492203951),
        (96098.63026118628, 95471.70446791887, 0.000000000000),
        (7391.320134324691, 58157.426017924794, 0.281385421753),
        (-61178.679532514434, -54548.13538218628, 0.000000000000),
        (37406.80707109126, -35583.55014979426, 0.447355270386),
        (-28930.581741829737, 23953.267185125776, 0.988524198532),
    ];

    /// POV-Ray 3.7's values of `tiling 27` at the same points.
    const RHOMBS_SAMPLES: &[(f64, f64, f64)] = &[
        (-2.1140068220020516, -4.189809912905977, 0.223758056760),
        (1.8112136764782445, -5.130764559989487, 0.485272049904),
        (0.43058405168027036, -1.611732997048973, 0.425406098366),
        (-5.304012902703518, 0.08922879827304264, 0.936464011669),
        (-5.550052098696181, -0.7962517960513695, 0.926058828831),
        (-5.161734917104573, -4.91144383987362, 0.382772028446),
        (-64.5726558652388, -60.61270060783622, 0.143806934357),
        (-237.87774377380543, 80.57373941142544, 0.788400053978),
        (-262.65130702878747, -259.5914304941851, 0.169852286577),
        (396.6693596971768, -5.498844683972948, 0.822707593441),
        (229.00652378993595, 840.9285468801452, 0.947800934315),
        (-488.33955978723685, -977.3855899579622, 0.305989742279),
        (-57340.68417207616, 79996.74735996508, 0.000000000000),
        (96098.63026118628, 95471.70446791887, 0.857858359814),
        (7391.320134324691, 58157.426017924794, 0.664387285709),
        (-61178.679532514434, -54548.13538218628, 0.062775328755),
        (37406.80707109126, -35583.55014979426, 0.131245791912),
        (-28930.581741829737, 23953.267185125776, 0.491174191236),
    ];

    /// Compares with POV-Ray's values (single precision colours, so to 1e-6).
    fn check(tiling: Penrose, samples: &[(f64, f64, f64)]) {
        for &(x, z, expected) in samples {
            let value = tiling.value(x, z);
            assert!(
                (value - expected).abs() < 1e-6,
                "{tiling:?} at ({x}, {z}): {value} against {expected}"
            );
        }
    }

    #[test]
    fn kites_and_darts_match_povray() {
        check(Penrose::KitesAndDarts, KITES_AND_DARTS_SAMPLES);
    }

    #[test]
    fn rhombs_match_povray() {
        check(Penrose::Rhombs, RHOMBS_SAMPLES);
    }

    #[test]
    fn both_have_the_symmetry_of_a_pentagon_about_the_origin() {
        for tiling in [Penrose::KitesAndDarts, Penrose::Rhombs] {
            let point = DVec2::new(3.7, -1.3);
            let value = tiling.value(point.x, point.y);
            for turn in 1..5 {
                let turned =
                    DVec2::from_angle(f64::from(turn) * 0.4 * std::f64::consts::PI).rotate(point);
                assert!((tiling.value(turned.x, turned.y) - value).abs() < 1e-9);
            }
            assert!((tiling.value(point.x, -point.y) - value).abs() < 1e-9);
        }
    }

    #[test]
    fn edges_of_type_0_stay_a_millionth_below_type_1() {
        // On the thick rhombs' shared edge along x, and on a kite's long edge.
        check(Penrose::Rhombs, &[(0.6, 0.0, 0.499999)]);
        let along_36 = DVec2::from_angle(0.2 * std::f64::consts::PI) * 0.6;
        check(
            Penrose::KitesAndDarts,
            &[(along_36.x, along_36.y, 0.499999)],
        );
        // Type 1 reaches 1 on its edges: a thin rhomb's corner at (φ, 0).
        check(Penrose::Rhombs, &[(1.617_999, 0.0, 0.999_942_958)]);
    }

    #[test]
    fn the_origin_gives_1() {
        for tiling in [Penrose::KitesAndDarts, Penrose::Rhombs] {
            check(
                tiling,
                &[
                    (0.0, 0.0, 1.0),
                    (0.0, -1e-10, 1.0),
                    (1.1e-10, 0.0, 0.499999),
                ],
            );
        }
    }

    #[test]
    fn huge_and_non_finite_points_give_a_value() {
        for tiling in [Penrose::KitesAndDarts, Penrose::Rhombs] {
            assert_eq!(tiling.value(f64::NAN, 0.0), 0.0);
            assert_eq!(tiling.value(0.0, f64::INFINITY), 0.0);
            let value = tiling.value(1e300, -1e300);
            assert!((0.0..=1.0).contains(&value));
            assert_eq!(tiling.value(f64::MAX, f64::MAX), 0.0);
        }
    }
}
