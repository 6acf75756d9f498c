//! Splines as values: points sorted by parameter and POV-Ray's four interpolations.
//!
//! In: (parameter, point) pairs from the scene language. Out: [`Spline::evaluate`], the point
//! at a parameter. Holds: shared by scene-language calls (`S(t)`) and spline functions
//! (`function { spline { S } }`) on render threads: evaluation is pure, never panics and does
//! not allocate once a natural spline's curvatures are computed (the first time it is
//! evaluated as one).

use std::sync::OnceLock;

/// How a spline interpolates between its points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineKind {
    /// Straight segments.
    Linear,
    /// Each segment follows the parabola through the point before it and its two ends.
    Quadratic,
    /// Catmull-Rom: Hermite segments whose tangents average the neighbouring slopes; only
    /// the second to the next-to-last point are reached.
    Cubic,
    /// The natural cubic spline (zero curvature at both ends) through every point.
    Natural,
}

impl SplineKind {
    /// The kind named by a keyword.
    pub fn from_keyword(word: &str) -> Option<SplineKind> {
        Some(match word {
            "linear_spline" => SplineKind::Linear,
            "quadratic_spline" => SplineKind::Quadratic,
            "cubic_spline" => SplineKind::Cubic,
            "natural_spline" => SplineKind::Natural,
            _ => return None,
        })
    }
}

/// A spline value: its kind and points sorted by parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    /// Interpolation used when a call does not name one.
    pub kind: SplineKind,
    /// (parameter, point) pairs, ascending by parameter; unused components are zero.
    points: Vec<(f64, [f64; 5])>,
    /// Components of the widest point (2 to 5): the size of the vectors the spline returns.
    pub components: u8,
    /// Second derivatives of the natural spline through the points, per point and component;
    /// computed the first time the spline is evaluated as a natural spline.
    curvatures: OnceLock<Vec<[f64; 5]>>,
}

impl Spline {
    /// The (parameter, point) pairs, ascending by parameter.
    pub fn points(&self) -> &[(f64, [f64; 5])] {
        &self.points
    }

    /// A spline of `kind` without points.
    pub fn new(kind: SplineKind) -> Spline {
        Spline {
            kind,
            points: Vec::new(),
            components: 2,
            curvatures: OnceLock::new(),
        }
    }

    /// Whether the spline has no points yet.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Adds a point, replacing the one at the same parameter, except that a point repeating
    /// the last parameter of a spline of two or more points is dropped (POV-Ray 3.7's rule,
    /// measured: `0, A 1, B 1, C` keeps B; `0, A 1, B 2, C 1, D` and `0, A 0, B` replace).
    pub fn insert(&mut self, t: f64, point: [f64; 5], components: u8) {
        if self.points.len() >= 2 && self.points.last().is_some_and(|last| last.0 == t) {
            return;
        }
        self.curvatures = OnceLock::new();
        self.components = self.components.max(components);
        let at = self.points.partition_point(|(p, _)| *p < t);
        match self.points.get_mut(at) {
            Some(existing) if existing.0 == t => existing.1 = point,
            _ => self.points.insert(at, (t, point)),
        }
    }

    /// The point at parameter `t`, interpolated as `kind`.
    pub fn evaluate(&self, t: f64, kind: SplineKind) -> [f64; 5] {
        let points = &self.points;
        let n = points.len();
        let (first, last) = match points.first().zip(points.last()) {
            Some(ends) => ends,
            None => return [0.0; 5],
        };
        // A single point, or a parameter that is not a number, has nothing to interpolate.
        if n == 1 || t.is_nan() {
            return first.1;
        }
        // Too few points for the kind: fall back to straight segments, as POV-Ray does.
        let kind = match kind {
            SplineKind::Quadratic if n < 3 => SplineKind::Linear,
            SplineKind::Cubic if n < 3 => SplineKind::Linear,
            SplineKind::Natural if n < 3 => SplineKind::Linear,
            other => other,
        };
        if kind == SplineKind::Cubic {
            // Only the second to the next-to-last point are on the curve (with three
            // points, just the middle one, whatever `t` is, even NaN).
            let (low, high) = (points[1], points[n - 2]);
            if t <= low.0 || n < 4 {
                return low.1;
            }
            if t >= high.0 {
                return high.1;
            }
        } else {
            if t <= first.0 {
                return first.1;
            }
            if t >= last.0 {
                return last.1;
            }
        }
        // Segment i runs from point i to point i + 1.
        let i = points
            .partition_point(|(p, _)| *p <= t)
            .saturating_sub(1)
            .min(n - 2);
        match kind {
            SplineKind::Linear => {
                let (t0, p0) = points[i];
                let (t1, p1) = points[i + 1];
                let s = (t - t0) / (t1 - t0);
                std::array::from_fn(|c| p0[c] + (p1[c] - p0[c]) * s)
            }
            SplineKind::Quadratic => {
                let start = i.saturating_sub(1);
                quadratic_through(&points[start..start + 3], t)
            }
            SplineKind::Cubic => {
                let start = i.clamp(1, n - 3);
                catmull_rom(&points[start - 1..start + 3], t)
            }
            SplineKind::Natural => {
                let curvatures = self.curvatures.get_or_init(|| natural_curvatures(points));
                natural(points, curvatures, i, t)
            }
        }
    }
}

/// The parabola through three points, at `t` (Lagrange form).
fn quadratic_through(points: &[(f64, [f64; 5])], t: f64) -> [f64; 5] {
    let [(t0, p0), (t1, p1), (t2, p2)] = [points[0], points[1], points[2]];
    let w0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
    let w1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
    let w2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
    std::array::from_fn(|c| w0 * p0[c] + w1 * p1[c] + w2 * p2[c])
}

/// The Hermite segment between the middle two of four points, with each tangent the average
/// of the slopes on either side of its point.
fn catmull_rom(points: &[(f64, [f64; 5])], t: f64) -> [f64; 5] {
    let [(t0, p0), (t1, p1), (t2, p2), (t3, p3)] = [points[0], points[1], points[2], points[3]];
    let h = t2 - t1;
    let s = (t - t1) / h;
    let (s2, s3) = (s * s, s * s * s);
    let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    let h01 = -2.0 * s3 + 3.0 * s2;
    let h10 = s3 - 2.0 * s2 + s;
    let h11 = s3 - s2;
    std::array::from_fn(|c| {
        let slope = (p2[c] - p1[c]) / h;
        let tangent1 = 0.5 * ((p1[c] - p0[c]) / (t1 - t0) + slope) * h;
        let tangent2 = 0.5 * (slope + (p3[c] - p2[c]) / (t3 - t2)) * h;
        h00 * p1[c] + h01 * p2[c] + h10 * tangent1 + h11 * tangent2
    })
}

/// The natural cubic spline through all points, on segment `i`, at `t`, from the
/// curvatures at the points.
fn natural(points: &[(f64, [f64; 5])], curvatures: &[[f64; 5]], i: usize, t: f64) -> [f64; 5] {
    let (t0, p0) = points[i];
    let (t1, p1) = points[i + 1];
    let h = t1 - t0;
    let a = (t1 - t) / h;
    let b = (t - t0) / h;
    std::array::from_fn(|c| {
        let bend = (a * a * a - a) * curvatures[i][c] + (b * b * b - b) * curvatures[i + 1][c];
        a * p0[c] + b * p1[c] + bend * h * h / 6.0
    })
}

/// Second derivatives of every component at each point of the natural spline (zero at both
/// ends), from the tridiagonal system solved by elimination.
fn natural_curvatures(points: &[(f64, [f64; 5])]) -> Vec<[f64; 5]> {
    let n = points.len();
    let mut curvature = vec![[0.0; 5]; n];
    let mut upper = vec![0.0; n];
    for k in 1..n.saturating_sub(1) {
        let (tp, pp) = points[k - 1];
        let (tk, pk) = points[k];
        let (tn, pn) = points[k + 1];
        let sigma = (tk - tp) / (tn - tp);
        let pivot = sigma * upper[k - 1] + 2.0;
        upper[k] = (sigma - 1.0) / pivot;
        for c in 0..5 {
            let rhs = (pn[c] - pk[c]) / (tn - tk) - (pk[c] - pp[c]) / (tk - tp);
            curvature[k][c] = (6.0 * rhs / (tn - tp) - sigma * curvature[k - 1][c]) / pivot;
        }
    }
    for k in (0..n.saturating_sub(1)).rev() {
        let next = curvature[k + 1];
        for (value, below) in curvature[k].iter_mut().zip(next) {
            *value += upper[k] * below;
        }
    }
    curvature
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spline(points: &[(f64, f64)]) -> Spline {
        let mut spline = Spline::new(SplineKind::Linear);
        for &(t, value) in points {
            spline.insert(t, [value, value, 0.0, 0.0, 0.0], 2);
        }
        spline
    }

    /// Values POV-Ray 3.7 prints for splines with a repeated parameter.
    #[test]
    fn repeated_parameters_follow_povray() {
        let at = |s: &Spline, t: f64| s.evaluate(t, SplineKind::Linear)[0];
        // Repeating the last parameter keeps the older point.
        let kept = spline(&[(0.0, 0.0), (1.0, 1.0), (1.0, 5.0), (2.0, 2.0)]);
        assert_eq!(
            (at(&kept, 0.5), at(&kept, 1.0), at(&kept, 1.5)),
            (0.5, 1.0, 1.5)
        );
        // Repeating an inner or the first parameter replaces the point.
        let inner = spline(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (1.0, 5.0)]);
        assert_eq!(
            (at(&inner, 0.5), at(&inner, 1.0), at(&inner, 1.5)),
            (2.5, 5.0, 3.5)
        );
        let first = spline(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (0.0, 9.0)]);
        assert_eq!(at(&first, 0.0), 9.0);
        // A single point is always replaced.
        let single = spline(&[(0.0, 0.0), (0.0, 9.0), (0.0, 8.0)]);
        assert_eq!(at(&single, 0.0), 8.0);
    }

    /// A cubic spline of three points is its middle point, also when its parameters are not
    /// numbers (meshmaker.inc's BuildSpline gives three points parameters -inf, NaN, NaN).
    #[test]
    fn three_point_cubic_spline_is_its_middle_point() {
        let three = spline(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]);
        for t in [-1.0, 0.5, 1.5, 3.0] {
            assert_eq!(three.evaluate(t, SplineKind::Cubic)[0], 1.0);
        }
        let broken = spline(&[(f64::NEG_INFINITY, 0.0), (f64::NAN, 1.0), (f64::NAN, 2.0)]);
        for t in [-1.0, 0.5, 3.0] {
            let value = broken.evaluate(t, SplineKind::Cubic)[0];
            assert!((0.0..=2.0).contains(&value), "{value} at {t}");
        }
    }

    #[test]
    fn natural_spline_curvatures_are_computed_once_and_reset_by_insert() {
        let mut natural = Spline::new(SplineKind::Natural);
        for (t, value) in [(0.0, 0.0), (1.0, 2.0), (2.0, 4.0), (3.0, 1.0)] {
            natural.insert(t, [value; 5], 3);
        }
        let before = natural.evaluate(1.5, SplineKind::Natural);
        natural.insert(4.0, [0.0; 5], 3);
        let after = natural.evaluate(1.5, SplineKind::Natural);
        assert_ne!(before, after);
        let mut fresh = Spline::new(SplineKind::Natural);
        for (t, value) in [(0.0, 0.0), (1.0, 2.0), (2.0, 4.0), (3.0, 1.0), (4.0, 0.0)] {
            fresh.insert(t, [value; 5], 3);
        }
        assert_eq!(after, fresh.evaluate(1.5, SplineKind::Natural));
    }
}
