//! The superellipsoid `(|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1` inside the unit cube.
//!
//! In: the exponents `e` (east-west) and `n` (north-south). Out: crossings of a line, inside
//! test (the function is negative inside), gradient normals, bounds. Holds: when both
//! exponents are at most 2 the function is convex, and its v-th root (v = 2/n) is a norm, so
//! along a line it is convex and nearly linear: Newton steps on that norm from where the line
//! enters the cube walk monotonically onto the entry crossing, and from where it leaves onto
//! the exit crossing, a few steps each. Other exponents (and the rare line where the walk
//! does not settle) split the line inside the cube where x, y or z is zero and where
//! |x| = |y|, sample each piece for sign changes and bisect each change; a tangent touch that
//! never changes the sign is missed there. Whole and half-whole powers multiply instead of
//! calling `powf`; nothing allocates.

use super::roots::Roots;
use crate::accel::Aabb;
use glam::DVec3;

/// Samples per piece of the line when looking for sign changes.
const SAMPLES: usize = 12;
/// Bisection steps per root.
const BISECTIONS: usize = 60;
/// Most Newton steps towards one crossing before the line falls back to sampling.
const NEWTON_STEPS: usize = 48;
/// A Newton walk has settled when its step is below this fraction of the line's length in
/// the cube (the next step would be about its square: far below rounding).
const NEWTON_SETTLED: f64 = 1e-12;

/// `|v|^exponent`, computed by repeated multiplication when the exponent is a whole or
/// half-whole number (as 2/e is for the usual e = 1, 0.5, 0.25, 0.1, 0.05 ...).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Power {
    /// A whole exponent.
    Whole(i32),
    /// A whole exponent plus one half: the whole power times a square root.
    HalfWhole(i32),
    /// Any other exponent.
    General(f64),
}

/// Largest exponent taken by repeated multiplication.
const LARGEST_MULTIPLIED: f64 = 1024.0;

impl Power {
    /// The power for `exponent` (finite and positive).
    fn new(exponent: f64) -> Power {
        let twice = 2.0 * exponent;
        let rounded = twice.round();
        if (1.0..=2.0 * LARGEST_MULTIPLIED).contains(&rounded)
            && (twice - rounded).abs() <= 1e-12 * rounded
        {
            let halves = rounded as i32;
            if halves % 2 == 0 {
                Power::Whole(halves / 2)
            } else {
                Power::HalfWhole(halves / 2)
            }
        } else {
            Power::General(exponent)
        }
    }

    /// `magnitude^exponent` for a magnitude of at least zero.
    #[inline]
    fn of(self, magnitude: f64) -> f64 {
        match self {
            Power::Whole(1) => magnitude,
            Power::Whole(whole) => magnitude.powi(whole),
            Power::HalfWhole(whole) => magnitude.powi(whole) * magnitude.sqrt(),
            Power::General(exponent) => magnitude.powf(exponent),
        }
    }
}

/// How a Newton walk along the line ended.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Walk {
    /// It settled on a crossing at this ray parameter.
    Crossing(f64),
    /// The function stays positive over the rest of the way.
    Clear,
    /// It did not settle (a grazing line) or met a non-finite slope.
    Undecided,
}

/// A superellipsoid in the unit cube.
#[derive(Clone, Copy, Debug)]
pub struct Superellipsoid {
    /// 2 / e: the exponent of |x| and |y|.
    horizontal: f64,
    /// e / n: the exponent of the horizontal sum.
    blend: f64,
    /// 2 / n: the exponent of |z|.
    vertical: f64,
    /// The three exponents as powers.
    horizontal_power: Power,
    blend_power: Power,
    vertical_power: Power,
    /// n / 2, the power that turns the function's value into a norm (Newton walks).
    norm_power: Power,
    /// True when both exponents are at most 2, which makes the function convex.
    convex: bool,
}

impl Superellipsoid {
    /// A superellipsoid; `None` unless both exponents are positive and finite.
    pub fn new(east_west: f64, north_south: f64) -> Option<Superellipsoid> {
        let usable = |v: f64| v > 0.0 && v.is_finite();
        if !(usable(east_west) && usable(north_south)) {
            return None;
        }
        let horizontal = 2.0 / east_west;
        let blend = east_west / north_south;
        let vertical = 2.0 / north_south;
        Some(Superellipsoid {
            horizontal,
            blend,
            vertical,
            horizontal_power: Power::new(horizontal),
            blend_power: Power::new(blend),
            vertical_power: Power::new(vertical),
            norm_power: Power::new(north_south / 2.0),
            convex: (1.0..f64::INFINITY).contains(&horizontal)
                && (1.0..f64::INFINITY).contains(&vertical),
        })
    }

    /// The implicit function: negative inside, zero on the surface.
    pub fn value(&self, p: DVec3) -> f64 {
        let horizontal = self.horizontal_power.of(p.x.abs()) + self.horizontal_power.of(p.y.abs());
        self.blend_power.of(horizontal) + self.vertical_power.of(p.z.abs()) - 1.0
    }

    /// The function plus one, F(t), at `origin + t direction`, with its slope dF/dt (a
    /// one-sided slope where a term has a kink, which convexity allows).
    #[inline]
    fn value_and_slope(&self, origin: DVec3, direction: DVec3, t: f64) -> (f64, f64) {
        let p = origin + direction * t;
        // d|v|^k / dt = k |v|^k / v · dv/dt, zero at v = 0 (k ≥ 1 where this is used).
        let term = |power: Power, exponent: f64, v: f64, dv: f64| {
            let value = power.of(v.abs());
            let slope = if v == 0.0 {
                0.0
            } else {
                exponent * value / v * dv
            };
            (value, slope)
        };
        let (x, x_slope) = term(self.horizontal_power, self.horizontal, p.x, direction.x);
        let (y, y_slope) = term(self.horizontal_power, self.horizontal, p.y, direction.y);
        let (z, z_slope) = term(self.vertical_power, self.vertical, p.z, direction.z);
        let sum = x + y;
        let blended = self.blend_power.of(sum);
        let blended_slope = if sum == 0.0 {
            0.0
        } else {
            self.blend * blended / sum * (x_slope + y_slope)
        };
        (blended + z, blended_slope + z_slope)
    }

    /// Newton steps on the norm F^(1/v) − 1 from `from` towards `to` (either direction)
    /// along the line; `length` is the length of the line's piece in the cube in ray
    /// parameter. Only for a convex function, on which every step stays outside and the walk
    /// settles on the first crossing it meets.
    fn newton_walk(
        &self,
        origin: DVec3,
        direction: DVec3,
        (from, to): (f64, f64),
        length: f64,
    ) -> Walk {
        let heading = if to >= from { 1.0 } else { -1.0 };
        let mut t = from;
        for _ in 0..NEWTON_STEPS {
            let (value, slope) = self.value_and_slope(origin, direction, t);
            if value < 1.0 {
                // Only rounding brings a walk inside: it is on the crossing.
                return Walk::Crossing(t);
            }
            let norm = self.norm_power.of(value);
            let norm_slope = heading * norm / (self.vertical * value) * slope;
            if !norm_slope.is_finite() {
                return Walk::Undecided;
            }
            if norm_slope >= 0.0 {
                // Convex and not falling: positive all the way on.
                return Walk::Clear;
            }
            let step = (norm - 1.0) / -norm_slope;
            let next = t + heading * step;
            if (next - to) * heading >= 0.0 {
                return Walk::Clear;
            }
            if step <= NEWTON_SETTLED * length {
                return Walk::Crossing(next);
            }
            t = next;
        }
        Walk::Undecided
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let Some((entry, exit)) = cube_span(origin, direction) else {
            return;
        };
        if self.convex && self.newton_crossings(origin, direction, (entry, exit), roots) {
            return;
        }
        self.sampled_crossings(origin, direction, (entry, exit), roots);
    }

    /// The crossings of a convex superellipsoid by Newton walks from both ends of the line's
    /// piece in the cube; false (nothing pushed) when a walk did not settle.
    fn newton_crossings(
        &self,
        origin: DVec3,
        direction: DVec3,
        (entry, exit): (f64, f64),
        roots: &mut Roots,
    ) -> bool {
        let length = exit - entry;
        let first = self.newton_walk(origin, direction, (entry, exit), length);
        let last_end = match first {
            Walk::Undecided => return false,
            Walk::Clear => return true,
            Walk::Crossing(t) => t,
        };
        let last = self.newton_walk(origin, direction, (exit, last_end), length);
        match (first, last) {
            (_, Walk::Undecided) => false,
            (Walk::Crossing(near), Walk::Crossing(far)) => {
                roots.push(near, 0);
                roots.push(far, 0);
                true
            }
            (Walk::Crossing(near), _) => {
                roots.push(near, 0);
                true
            }
            _ => true,
        }
    }

    /// The crossings found by sampling each piece of the line between the planes where a
    /// term of the function changes form, and bisecting each sign change.
    fn sampled_crossings(
        &self,
        origin: DVec3,
        direction: DVec3,
        (entry, exit): (f64, f64),
        roots: &mut Roots,
    ) {
        let mut breaks = [0.0; 8];
        let mut count = 0;
        breaks[count] = entry;
        count += 1;
        let mut add = |t: f64| {
            if t > entry && t < exit && t.is_finite() {
                breaks[count] = t;
                count += 1;
            }
        };
        for axis in 0..3 {
            if direction[axis] != 0.0 {
                add(-origin[axis] / direction[axis]);
            }
        }
        if direction.x != direction.y {
            add((origin.y - origin.x) / (direction.x - direction.y));
        }
        if direction.x != -direction.y {
            add(-(origin.x + origin.y) / (direction.x + direction.y));
        }
        breaks[count] = exit;
        count += 1;
        let pieces = &mut breaks[..count];
        pieces.sort_by(f64::total_cmp);
        let at = |t: f64| self.value(origin + direction * t);
        for window in pieces.windows(2) {
            let (start, end) = (window[0], window[1]);
            let step = (end - start) / SAMPLES as f64;
            let mut previous_t = start;
            let mut previous = at(start);
            for sample in 1..=SAMPLES {
                let t = if sample == SAMPLES {
                    end
                } else {
                    start + step * sample as f64
                };
                let value = at(t);
                if (previous < 0.0) != (value < 0.0) {
                    let (mut low, mut high) = (previous_t, t);
                    let low_negative = previous < 0.0;
                    for _ in 0..BISECTIONS {
                        let middle = 0.5 * (low + high);
                        if (at(middle) < 0.0) == low_negative {
                            low = middle;
                        } else {
                            high = middle;
                        }
                    }
                    roots.push(0.5 * (low + high), 0);
                }
                previous_t = t;
                previous = value;
            }
        }
    }

    /// True when the function is negative at `point`.
    pub fn inside(&self, point: DVec3) -> bool {
        self.value(point) < 0.0
    }

    /// The gradient at `point` (outwards).
    pub fn normal(&self, point: DVec3) -> DVec3 {
        let power_slope = |v: f64, exponent: f64| {
            let magnitude = v.abs().max(1e-300);
            exponent * magnitude.powf(exponent - 1.0) * v.signum()
        };
        let horizontal = point.x.abs().powf(self.horizontal) + point.y.abs().powf(self.horizontal);
        let outer = if horizontal > 0.0 {
            self.blend * horizontal.powf(self.blend - 1.0)
        } else {
            0.0
        };
        let gradient = DVec3::new(
            outer * power_slope(point.x, self.horizontal),
            outer * power_slope(point.y, self.horizontal),
            power_slope(point.z, self.vertical),
        );
        if gradient.is_finite() && gradient != DVec3::ZERO {
            gradient
        } else {
            point
        }
    }

    /// The unit cube.
    pub fn bounds(&self) -> Aabb {
        Aabb::from_points([DVec3::splat(-1.0), DVec3::splat(1.0)])
    }
}

/// The part `(entry, exit)` of the line `origin + t direction` inside the cube [-1, 1]³.
fn cube_span(origin: DVec3, direction: DVec3) -> Option<(f64, f64)> {
    let mut entry = f64::NEG_INFINITY;
    let mut exit = f64::INFINITY;
    for axis in 0..3 {
        if direction[axis] == 0.0 {
            if origin[axis].abs() > 1.0 {
                return None;
            }
            continue;
        }
        let first = (-1.0 - origin[axis]) / direction[axis];
        let second = (1.0 - origin[axis]) / direction[axis];
        entry = entry.max(first.min(second));
        exit = exit.min(first.max(second));
    }
    (entry.is_finite() && exit.is_finite() && entry < exit).then_some((entry, exit))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_superellipsoid_is_a_sphere() {
        let shape = Superellipsoid::new(1.0, 1.0).unwrap();
        let mut roots = Roots::new();
        shape.intersect(DVec3::new(-5.0, 0.1, 0.2), DVec3::X, &mut roots);
        let expected = (1.0f64 - 0.01 - 0.04).sqrt();
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        assert_eq!(found.len(), 2);
        assert!((found[0] - (5.0 - expected)).abs() < 1e-9);
        assert!((found[1] - (5.0 + expected)).abs() < 1e-9);
        let n = shape.normal(DVec3::new(0.0, 0.0, 1.0)).normalize();
        assert!(n.abs_diff_eq(DVec3::Z, 1e-9));
        assert!(Superellipsoid::new(0.0, 1.0).is_none());
        assert!(Superellipsoid::new(1.0, f64::NAN).is_none());
    }

    #[test]
    fn boxy_superellipsoid_crossings_agree_with_inside_test() {
        let shape = Superellipsoid::new(0.25, 0.5).unwrap();
        super::super::test_support::assert_crossings_flip_inside(
            11,
            3.0,
            1e-6,
            1e-7,
            |origin, direction, roots| shape.intersect(origin, direction, roots),
            |point| shape.inside(point),
        );
    }

    /// A repeatable stream of numbers in [-1, 1).
    fn numbers(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        }
    }

    #[test]
    fn powers_multiply_for_whole_and_half_whole_exponents() {
        assert_eq!(Power::new(40.0), Power::Whole(40));
        assert_eq!(Power::new(2.0 / 0.05), Power::Whole(40));
        assert_eq!(Power::new(2.5), Power::HalfWhole(2));
        assert_eq!(Power::new(0.5), Power::HalfWhole(0));
        assert_eq!(Power::new(2.0 / 0.3), Power::General(2.0 / 0.3));
        assert_eq!(Power::new(1e6), Power::General(1e6));
        for exponent in [0.5, 1.0, 2.5, 4.0, 40.0, 2.0 / 0.3, 333.0] {
            let power = Power::new(exponent);
            for magnitude in [0.0, 1e-9, 0.3, 0.97, 1.0, 1.02] {
                let expected = f64::powf(magnitude, exponent);
                let found = power.of(magnitude);
                assert!(
                    (found - expected).abs() <= 1e-13 * expected.max(1e-300),
                    "{magnitude}^{exponent}: {found} vs {expected}"
                );
            }
        }
    }

    /// The crossings the Newton walks (`None` when they did not settle) and the sampling
    /// find, sorted.
    fn both_ways(shape: &Superellipsoid, origin: DVec3, direction: DVec3) -> Option<[Vec<f64>; 2]> {
        let (entry, exit) = cube_span(origin, direction).unwrap_or((0.0, 0.0));
        let mut newton = Roots::new();
        if !shape.newton_crossings(origin, direction, (entry, exit), &mut newton) {
            return None;
        }
        let mut sampled = Roots::new();
        if entry < exit {
            shape.sampled_crossings(origin, direction, (entry, exit), &mut sampled);
        }
        Some([newton, sampled].map(|roots| {
            let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
            found.sort_by(f64::total_cmp);
            found
        }))
    }

    #[test]
    fn newton_walks_find_what_sampling_finds() {
        let mut random = numbers(7);
        let (mut rays, mut undecided) = (0, 0);
        for (east_west, north_south) in [
            (1.0, 1.0),
            (0.05, 0.05),
            (0.25, 0.5),
            (2.0, 2.0),
            (1.5, 0.3),
            (0.3, 1.9),
        ] {
            let shape = Superellipsoid::new(east_west, north_south).unwrap();
            assert!(shape.convex);
            for _ in 0..4000 {
                let origin = DVec3::new(random(), random(), random()) * 3.0;
                let direction = DVec3::new(random(), random(), random());
                let Some([newton, sampled]) = both_ways(&shape, origin, direction) else {
                    undecided += 1;
                    continue;
                };
                let (entry, exit) = cube_span(origin, direction).unwrap_or((0.0, 0.0));
                let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
                for t in &sampled {
                    assert!(
                        newton.iter().any(|&n| close(n, *t)),
                        "{east_west} {north_south} {origin} {direction}: {newton:?} vs {sampled:?}"
                    );
                }
                for t in &newton {
                    // Sampling misses a crossing where rounding puts the cube's face inside
                    // a boxy superellipsoid that hugs it, and a pair of crossings closer
                    // than its sample spacing.
                    let missed_face = close(*t, entry) || close(*t, exit);
                    let missed_pair =
                        sampled.is_empty() && newton.len() == 2 && newton[1] - newton[0] < 0.1;
                    assert!(
                        sampled.iter().any(|&s| close(s, *t)) || missed_face || missed_pair,
                        "{east_west} {north_south} {origin} {direction}: {newton:?} vs {sampled:?}"
                    );
                }
                rays += usize::from(!sampled.is_empty());
            }
        }
        assert!(rays > 2500, "{rays}");
        // Only grazing lines leave the walks undecided.
        assert!(undecided < 10, "{undecided}");
    }

    #[test]
    fn stretched_exponents_still_sample() {
        assert!(!Superellipsoid::new(2.5, 1.0).unwrap().convex);
        assert!(!Superellipsoid::new(1.0, 3.0).unwrap().convex);
        assert!(!Superellipsoid::new(1e-320, 1.0).unwrap().convex);
    }
}
