//! Boxes for unbounded quadrics and planes cut down by the other children of an
//! intersection.
//!
//! In: the inside of a plane or quadric leaf as a world-space quadratic inequality
//! `pᵀ A p + 2 bᵀ p + c ≤ 0` (inversion already applied), and a box known to hold the
//! intersection's inside (the other children's boxes overlapped). Out: a smaller box that still
//! holds every point of the box satisfying the inequality. Holds: conservative — a point inside
//! all children is never cut off (results are widened by a hair for rounding); quadrics with
//! cross terms in world space (rotated ones) are left alone.
//!
//! Why: an `intersection { plane { -y, -2.5 } object { Hyperboloid_Y } plane { y, 5.5 } }`
//! has no bounded child, so without this every ray in the scene tests it (POV-Ray's chess2 is
//! built of such pieces). Bounded by the slab the planes make, the hyperboloid's inside is a
//! finite box, as POV-Ray also finds.

use glam::{DAffine3, DMat3, DVec3};

/// The inside of a plane or quadric in world space: `pᵀ A p + 2 bᵀ p + c ≤ 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InsideQuadric {
    /// The symmetric matrix of the square and cross terms.
    squares: DMat3,
    /// Half the linear terms.
    half_linear: DVec3,
    constant: f64,
}

/// Rounding allowance for the boxes found, relative to their size and absolute.
const HAIR_RELATIVE: f64 = 1e-9;
const HAIR_ABSOLUTE: f64 = 1e-9;

impl InsideQuadric {
    /// The inside of a local quadric `A x² + B y² + C z² + D xy + E xz + F yz + G x + H y +
    /// I z + J < 0` (POV-Ray's ten coefficients) placed by `local_from_world`, or of its
    /// outside when `inverted`.
    pub fn from_local(
        coefficients: [f64; 10],
        local_from_world: &DAffine3,
        inverted: bool,
    ) -> Option<InsideQuadric> {
        let [a, b, c, d, e, f, g, h, i, j] = coefficients;
        let squares = DMat3::from_cols(
            DVec3::new(a, d / 2.0, e / 2.0),
            DVec3::new(d / 2.0, b, f / 2.0),
            DVec3::new(e / 2.0, f / 2.0, c),
        );
        let half_linear = DVec3::new(g, h, i) / 2.0;
        // p_local = M p + t.
        let m = local_from_world.matrix3;
        let t = local_from_world.translation;
        let sign = if inverted { -1.0 } else { 1.0 };
        let world = InsideQuadric {
            squares: (m.transpose() * squares * m) * sign,
            half_linear: m.transpose() * (squares * t + half_linear) * sign,
            constant: (t.dot(squares * t) + 2.0 * half_linear.dot(t) + j) * sign,
        };
        let finite = world.squares.is_finite()
            && world.half_linear.is_finite()
            && world.constant.is_finite();
        finite.then_some(world)
    }

    /// The inside of a plane `normal · p < distance` placed by `local_from_world`, or its
    /// outside when `inverted`.
    pub fn from_plane(
        normal: DVec3,
        distance: f64,
        local_from_world: &DAffine3,
        inverted: bool,
    ) -> Option<InsideQuadric> {
        let [x, y, z] = normal.to_array();
        InsideQuadric::from_local(
            [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, x, y, z, -distance],
            local_from_world,
            inverted,
        )
    }

    /// Whether the quadric has no cross terms in world space (only then is it used).
    fn is_axis_aligned(&self) -> bool {
        let m = self.squares;
        let diagonal = m.x_axis.x.abs().max(m.y_axis.y.abs()).max(m.z_axis.z.abs());
        let cross = m.y_axis.x.abs().max(m.z_axis.x.abs()).max(m.z_axis.y.abs());
        cross <= 1e-12 * diagonal.max(f64::MIN_POSITIVE)
    }

    /// `(min, max)` cut down to the points inside: for each axis in turn, the range the
    /// inequality allows given the other axes' ranges. `None` when no point of the box is
    /// inside. A box with infinite sides is allowed.
    pub fn tighten(&self, (mut min, mut max): (DVec3, DVec3)) -> Option<(DVec3, DVec3)> {
        if !self.is_axis_aligned() {
            return Some((min, max));
        }
        // A square term that is rounding noise (a paraboloid turned 180 degrees keeps a y²
        // of 6e-34 beside its 0.04) counts as none when positive: dropping a positive term
        // only loosens the inequality, where dividing by it lost the bound to cancellation
        // (POV-Ray's arches.pov lost the top of its arches). A negative one is kept: it
        // already cuts nothing.
        let largest = self
            .squares
            .x_axis
            .x
            .abs()
            .max(self.squares.y_axis.y.abs())
            .max(self.squares.z_axis.z.abs());
        let square = [
            self.squares.x_axis.x,
            self.squares.y_axis.y,
            self.squares.z_axis.z,
        ]
        .map(|a| {
            if a > 0.0 && a <= 1e-12 * largest {
                0.0
            } else {
                a
            }
        });
        let half_linear = self.half_linear.to_array();
        for axis in 0..3 {
            // The least the other axes' terms can add.
            let mut least_others = self.constant;
            for other in (0..3).filter(|&other| other != axis) {
                least_others += least_of(square[other], half_linear[other], min[other], max[other]);
            }
            if least_others.is_nan() {
                continue;
            }
            // a x² + 2 b x ≤ room.
            let room = -least_others;
            let (a, b) = (square[axis], half_linear[axis]);
            let (low, high) = if a > 0.0 {
                let centre = -b / a;
                let spread_squared = (room + b * b / a) / a;
                if spread_squared < 0.0 {
                    return None;
                }
                let spread = spread_squared.sqrt();
                (centre - spread, centre + spread)
            } else if a == 0.0 && b > 0.0 {
                (f64::NEG_INFINITY, room / (2.0 * b))
            } else if a == 0.0 && b < 0.0 {
                (room / (2.0 * b), f64::INFINITY)
            } else if a == 0.0 && room < 0.0 {
                return None;
            } else {
                continue;
            };
            if low.is_nan() || high.is_nan() {
                continue;
            }
            let hair = |end: f64| HAIR_RELATIVE * end.abs() + HAIR_ABSOLUTE;
            min[axis] = min[axis].max(low - hair(low));
            max[axis] = max[axis].min(high + hair(high));
            if min[axis] > max[axis] {
                return None;
            }
        }
        Some((min, max))
    }
}

/// The least value of `a x² + 2 b x` for x in `[low, high]` (either end may be infinite);
/// negative infinity when it has none.
fn least_of(a: f64, b: f64, low: f64, high: f64) -> f64 {
    let value = |x: f64| {
        if x.is_infinite() {
            // The leading term decides the limit.
            if a > 0.0 {
                f64::INFINITY
            } else if a < 0.0 {
                f64::NEG_INFINITY
            } else if b == 0.0 {
                0.0
            } else if (b > 0.0) == (x > 0.0) {
                f64::INFINITY
            } else {
                f64::NEG_INFINITY
            }
        } else {
            (a * x + 2.0 * b) * x
        }
    };
    let mut least = value(low).min(value(high));
    if a > 0.0 {
        let vertex = -b / a;
        if vertex > low && vertex < high {
            least = least.min(value(vertex));
        }
    }
    // Rounding: a little lower is always safe.
    least - HAIR_RELATIVE * least.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    const EVERYWHERE: (DVec3, DVec3) = (DVec3::NEG_INFINITY, DVec3::INFINITY);

    #[test]
    fn a_hyperboloid_between_two_planes_gets_a_finite_box() {
        // x² + z² − y² − 1 < 0 (shapes.inc's Hyperboloid_Y), cut to 2.5 ≤ y ≤ 5.5.
        let hyperboloid = InsideQuadric::from_local(
            [1.0, -1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
            &DAffine3::IDENTITY,
            false,
        )
        .unwrap();
        let below = InsideQuadric::from_plane(DVec3::Y, 5.5, &DAffine3::IDENTITY, false).unwrap();
        let above = InsideQuadric::from_plane(-DVec3::Y, -2.5, &DAffine3::IDENTITY, false).unwrap();
        let mut region = EVERYWHERE;
        for _ in 0..2 {
            for part in [&below, &above, &hyperboloid] {
                region = part.tighten(region).unwrap();
            }
        }
        let reach = (1.0f64 + 5.5 * 5.5).sqrt();
        assert!((region.0.y - 2.5).abs() < 1e-6 && (region.1.y - 5.5).abs() < 1e-6);
        assert!((region.1.x - reach).abs() < 1e-6 && (region.0.z + reach).abs() < 1e-6);
    }

    #[test]
    fn a_paraboloid_turned_upside_down_keeps_its_top() {
        // shapes.inc's Paraboloid_Y (x² + z² − y < 0) scaled <20, 20, 5>, rotated 180 degrees
        // about x and moved to y = 30, as in POV-Ray's arches.pov: its inside reaches up to
        // y = 30 (the rotation leaves a y² term of rounding noise behind).
        let place = DAffine3::from_translation(DVec3::new(0.0, 30.0, -25.0))
            * DAffine3::from_rotation_x(std::f64::consts::PI)
            * DAffine3::from_scale(DVec3::new(20.0, 20.0, 5.0));
        let paraboloid = InsideQuadric::from_local(
            [1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0],
            &place.inverse(),
            false,
        )
        .unwrap();
        let (min, max) = paraboloid.tighten(EVERYWHERE).unwrap();
        let top = DVec3::new(0.0, 29.9, -25.0);
        assert!(top.cmpge(min).all() && top.cmple(max).all(), "{min} {max}");
        assert!((max.y - 30.0).abs() < 1e-6, "{}", max.y);
    }

    #[test]
    fn the_box_holds_every_inside_point() {
        // Random axis-aligned quadrics, scaled and moved, against random boxes: every sampled
        // point inside the box and the quadric stays inside the tightened box.
        let mut state: u64 = 12345;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for _ in 0..300 {
            let coefficients = [
                next(),
                next(),
                next(),
                0.0,
                0.0,
                0.0,
                next(),
                next(),
                next(),
                next(),
            ];
            let place = DAffine3::from_scale_rotation_translation(
                DVec3::new(1.0 + next().abs(), 1.0 + next().abs(), 0.5 + next().abs()),
                glam::DQuat::IDENTITY,
                DVec3::new(next(), next(), next()) * 3.0,
            );
            let inverted = next() > 0.0;
            let quadric =
                InsideQuadric::from_local(coefficients, &place.inverse(), inverted).unwrap();
            let start = (DVec3::splat(-2.0 + next()), DVec3::splat(2.0 + next()));
            let tightened = quadric.tighten(start);
            for _ in 0..400 {
                let point = DVec3::new(next(), next(), next()) * 3.0;
                let in_box = point.cmpge(start.0).all() && point.cmple(start.1).all();
                let local = place.inverse().transform_point3(point);
                let [a, b, c, _, _, _, g, h, i, j] = coefficients;
                let value = a * local.x * local.x
                    + b * local.y * local.y
                    + c * local.z * local.z
                    + g * local.x
                    + h * local.y
                    + i * local.z
                    + j;
                let inside = if inverted { value > 0.0 } else { value < 0.0 };
                if in_box && inside {
                    let (min, max) = tightened.expect("a point is inside, so the box is not empty");
                    assert!(
                        point.cmpge(min).all() && point.cmple(max).all(),
                        "{point} cut off"
                    );
                }
            }
        }
    }
}
