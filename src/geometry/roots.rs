//! Small fixed-size containers and solvers shared by the shapes.
//!
//! In: polynomial coefficients, ray parameters. Out: [`Roots`] (up to eight ray parameters, each
//! tagged with the surface part it belongs to), sorted real quadratic roots, and the real
//! roots in an interval of polynomials up to degree [`MAX_DEGREE`].
//! Holds: nothing allocates; non-finite parameters are never stored; polynomial roots are
//! isolated between the critical points of the polynomial (found recursively from its
//! derivatives) and then refined inside a sign-changing bracket.

/// The most intersections one primitive shape can have along a line (a degree-7 `poly` has 7).
pub const MAX_ROOTS: usize = 8;

/// Intersections of a ray with one primitive: ray parameters with a surface-part tag each.
///
/// The part tag tells the shape which face or piece was hit (box face, cylinder cap...), so
/// the normal can be computed later without repeating the search.
#[derive(Clone, Copy, Debug)]
pub struct Roots {
    distances: [f64; MAX_ROOTS],
    parts: [u8; MAX_ROOTS],
    len: usize,
}

impl Default for Roots {
    fn default() -> Self {
        Roots::new()
    }
}

impl Roots {
    /// No intersections.
    pub const fn new() -> Roots {
        Roots {
            distances: [0.0; MAX_ROOTS],
            parts: [0; MAX_ROOTS],
            len: 0,
        }
    }

    /// True when no further intersection can be recorded.
    #[inline]
    pub fn is_full(&self) -> bool {
        self.len >= MAX_ROOTS
    }

    /// Records an intersection at ray parameter `distance` on surface part `part`; ignores
    /// non-finite parameters and anything past the capacity.
    #[inline]
    pub fn push(&mut self, distance: f64, part: u8) {
        if distance.is_finite() && self.len < MAX_ROOTS {
            self.distances[self.len] = distance;
            self.parts[self.len] = part;
            self.len += 1;
        }
    }

    /// Records many crossings; when there are more than fit, keeps the nearest ones ahead of
    /// the ray origin (then the nearest behind it). Reorders `crossings`.
    pub fn push_nearest(&mut self, crossings: &mut [(f64, u8)]) {
        if crossings.len() > MAX_ROOTS {
            crossings.sort_by(|a, b| {
                (a.0 < 0.0)
                    .cmp(&(b.0 < 0.0))
                    .then(a.0.abs().total_cmp(&b.0.abs()))
            });
        }
        for &(distance, part) in crossings.iter() {
            self.push(distance, part);
        }
    }

    /// The recorded intersections as (distance, part) pairs, in recording order.
    pub fn iter(&self) -> impl Iterator<Item = (f64, u8)> + '_ {
        self.distances[..self.len]
            .iter()
            .copied()
            .zip(self.parts[..self.len].iter().copied())
    }

    /// The nearest recorded intersection strictly between the two limits.
    #[inline]
    pub fn nearest_within(&self, min_distance: f64, max_distance: f64) -> Option<(f64, u8)> {
        let mut best: Option<(f64, u8)> = None;
        for (distance, part) in self.iter() {
            if distance > min_distance
                && distance < max_distance
                && best.is_none_or(|(nearest, _)| distance < nearest)
            {
                best = Some((distance, part));
            }
        }
        best
    }
}

/// Room for the crossings a shape gathers per line before [`Roots::push_nearest`] keeps the
/// nearest ones (shapes with many pieces: blobs, lathes, extrusions, surfaces of revolution).
pub const CROSSING_BUFFER: usize = 64;

/// Real roots of `a x² + 2 half_b x + c = 0`, smaller first, computed without cancellation.
///
/// Returns `None` when there is no real root; a linear equation (`a == 0`) gives its single
/// root twice.
#[inline]
pub fn solve_quadratic(a: f64, half_b: f64, c: f64) -> Option<(f64, f64)> {
    if a == 0.0 {
        if half_b == 0.0 {
            return None;
        }
        let root = -c / (2.0 * half_b);
        return root.is_finite().then_some((root, root));
    }
    let discriminant = half_b * half_b - a * c;
    if discriminant.is_nan() || discriminant < 0.0 {
        return None;
    }
    let q = -(half_b + discriminant.sqrt().copysign(half_b));
    let first = q / a;
    let second = if q == 0.0 { first } else { c / q };
    Some(if first <= second {
        (first, second)
    } else {
        (second, first)
    })
}

/// Highest polynomial degree the root finder accepts (`poly` goes up to 7).
pub const MAX_DEGREE: usize = 7;

/// Value of the polynomial `coefficients` (highest power first) at `x`.
#[inline]
fn evaluate(coefficients: &[f64], x: f64) -> f64 {
    coefficients
        .iter()
        .fold(0.0, |sum, &coefficient| sum * x + coefficient)
}

/// Value and first derivative of the polynomial at `x`.
#[inline]
fn evaluate_with_slope(coefficients: &[f64], x: f64) -> (f64, f64) {
    let mut value = 0.0;
    let mut slope = 0.0;
    for &coefficient in coefficients {
        slope = slope * x + value;
        value = value * x + coefficient;
    }
    (value, slope)
}

/// The root inside `[low, high]`, where the polynomial is monotonic and changes sign, by
/// Newton steps kept inside a shrinking bisection bracket.
fn refine_root(coefficients: &[f64], mut low: f64, mut high: f64, low_value: f64) -> f64 {
    let low_is_negative = low_value < 0.0;
    let mut x = 0.5 * (low + high);
    for _ in 0..100 {
        let (value, slope) = evaluate_with_slope(coefficients, x);
        if value == 0.0 {
            return x;
        }
        if (value < 0.0) == low_is_negative {
            low = x;
        } else {
            high = x;
        }
        let newton = x - value / slope;
        let next = if newton > low && newton < high {
            newton
        } else {
            0.5 * (low + high)
        };
        let tolerance = 4.0 * f64::EPSILON * (x.abs() + 1e-9);
        if (next - x).abs() <= tolerance || high - low <= tolerance {
            return next;
        }
        x = next;
    }
    x
}

/// Whether the polynomial (highest power first, degree at least 1) surely has no root in
/// `[low, high]`: its Bernstein coefficients over the interval all have one sign, by more
/// than their rounding error (the polynomial lies in the convex hull of its Bernstein
/// control points). Most rays that reach a root search meet no surface in its interval;
/// this answers them without bracketing every critical point.
fn surely_no_root(polynomial: &[f64], low: f64, high: f64) -> bool {
    let degree = polynomial.len() - 1;
    // The coefficients of p(low + u), lowest power first, by Taylor shift (repeated
    // synthetic division), and the same computed on absolute values: a bound on rounding.
    let mut shifted = [0.0; MAX_DEGREE + 1];
    let mut magnitude = [0.0; MAX_DEGREE + 1];
    for (power, &coefficient) in polynomial.iter().rev().enumerate() {
        shifted[power] = coefficient;
        magnitude[power] = coefficient.abs();
    }
    if low != 0.0 {
        for first in 0..degree {
            for power in (first..degree).rev() {
                shifted[power] += low * shifted[power + 1];
                magnitude[power] += low.abs() * magnitude[power + 1];
            }
        }
    }
    // The coefficients of p(low + width·t) for t in [0, 1].
    let width = high - low;
    let mut scale = 1.0;
    let mut bound = 0.0;
    for (coefficient, size) in shifted.iter_mut().zip(magnitude).take(degree + 1) {
        *coefficient *= scale;
        bound += size * scale;
        scale *= width;
    }
    if !bound.is_finite() {
        return false;
    }
    // Bernstein coefficient i is the sum over k ≤ i of C(i, k) / C(degree, k) · c_k.
    let margin = 16.0 * (degree + 1) as f64 * f64::EPSILON * bound;
    let mut sign = 0.0;
    for index in 0..=degree {
        let mut bernstein = 0.0;
        let mut ratio = 1.0; // C(index, k) / C(degree, k), from k = 0
        for (power, coefficient) in shifted.iter().enumerate().take(index + 1) {
            bernstein += ratio * coefficient;
            ratio *= (index - power) as f64 / (degree - power) as f64;
        }
        if bernstein.abs() <= margin {
            return false;
        }
        if sign == 0.0 {
            sign = bernstein.signum();
        } else if bernstein.signum() != sign {
            return false;
        }
    }
    true
}

/// Writes the real roots of the polynomial `coefficients` (highest power first, degree at most
/// seven) that lie in `[low, high]` into `out`, ascending, and returns how many there are.
///
/// Every interval between consecutive critical points is monotonic, so it holds a root
/// exactly when the polynomial changes sign across it.
pub fn real_roots_between(
    coefficients: &[f64],
    low: f64,
    high: f64,
    out: &mut [f64; MAX_DEGREE],
) -> usize {
    let first_nonzero = coefficients
        .iter()
        .position(|&c| c != 0.0)
        .unwrap_or(coefficients.len());
    let polynomial = &coefficients[first_nonzero..];
    if polynomial.len() < 2
        || polynomial.len() > MAX_DEGREE + 1
        || low.is_nan()
        || high.is_nan()
        || low > high
    {
        return 0;
    }
    let degree = polynomial.len() - 1;
    if degree >= 3 && surely_no_root(polynomial, low, high) {
        return 0;
    }
    bracketed_roots(polynomial, low, high, out)
}

/// [`real_roots_between`] for a polynomial whose leading coefficient is not zero, of degree
/// 1 to [`MAX_DEGREE`], on a valid interval: each interval between consecutive critical
/// points that changes sign holds one root.
fn bracketed_roots(polynomial: &[f64], low: f64, high: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let degree = polynomial.len() - 1;
    if degree == 1 {
        let root = -polynomial[1] / polynomial[0];
        if root >= low && root <= high {
            out[0] = root;
            return 1;
        }
        return 0;
    }
    let mut derivative = [0.0; MAX_DEGREE];
    for (power_index, coefficient) in polynomial[..degree].iter().enumerate() {
        derivative[power_index] = coefficient * (degree - power_index) as f64;
    }
    let mut critical = [0.0; MAX_DEGREE];
    let critical_count = real_roots_between(&derivative[..degree], low, high, &mut critical);
    let mut count = 0;
    let mut push = |root: f64, count: &mut usize| {
        if *count < MAX_DEGREE && (*count == 0 || out[*count - 1] != root) {
            out[*count] = root;
            *count += 1;
        }
    };
    let mut previous = low;
    let mut previous_value = evaluate(polynomial, low);
    if previous_value == 0.0 {
        push(low, &mut count);
    }
    for &point in critical[..critical_count]
        .iter()
        .chain(std::iter::once(&high))
    {
        let value = evaluate(polynomial, point);
        if value == 0.0 {
            push(point, &mut count);
        } else if previous_value != 0.0 && (previous_value < 0.0) != (value < 0.0) {
            push(
                refine_root(polynomial, previous, point, previous_value),
                &mut count,
            );
        }
        previous = point;
        previous_value = value;
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots_of(coefficients: &[f64], low: f64, high: f64) -> Vec<f64> {
        let mut out = [0.0; MAX_DEGREE];
        let count = real_roots_between(coefficients, low, high, &mut out);
        out[..count].to_vec()
    }

    #[test]
    fn no_root_is_skipped_by_the_bernstein_test() {
        // Random polynomials of degrees 3 to 7 built from roots near the interval (some
        // double, some just outside it): wherever the test says "no root", the full
        // search finds none. A fixed generator keeps the cases the same on every run.
        let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut skipped, mut with_roots) = (0, 0);
        for case in 0..20_000 {
            let degree = 3 + case % 5;
            let mut polynomial = vec![1.0 + 4.0 * next()];
            for _ in 0..degree {
                let root = if next() < 0.2 {
                    1.0 + 1e-9 * next()
                } else {
                    3.0 * next() - 1.0
                };
                // Multiply by (x - root).
                let mut product = polynomial.clone();
                product.push(0.0);
                for index in 1..product.len() {
                    product[index] -= root * polynomial[index - 1];
                }
                polynomial = product;
            }
            if next() < 0.3 {
                // Lift it off the axis so that some cases have no real roots at all.
                *polynomial.last_mut().unwrap() += 0.1 * next();
            }
            let low = next() - 0.5;
            let high = low + 2.0 * next();
            let mut out = [0.0; MAX_DEGREE];
            let found = bracketed_roots(&polynomial, low, high, &mut out);
            if surely_no_root(&polynomial, low, high) {
                skipped += 1;
                assert_eq!(
                    found,
                    0,
                    "{polynomial:?} on [{low}, {high}]: {:?}",
                    &out[..found]
                );
            }
            with_roots += usize::from(found > 0);
        }
        assert!(
            skipped > 1_000 && with_roots > 1_000,
            "{skipped} {with_roots}"
        );
    }

    #[test]
    fn polynomial_roots() {
        // (x - 1)(x - 2)(x - 3)(x - 4) = x⁴ - 10x³ + 35x² - 50x + 24.
        let found = roots_of(&[1.0, -10.0, 35.0, -50.0, 24.0], -10.0, 10.0);
        assert_eq!(found.len(), 4);
        for (root, expected) in found.iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((root - expected).abs() < 1e-12, "{found:?}");
        }
        assert_eq!(
            roots_of(&[1.0, -10.0, 35.0, -50.0, 24.0], 1.5, 2.5).len(),
            1
        );
        assert!(roots_of(&[1.0, 0.0, 1.0], -10.0, 10.0).is_empty());
        assert_eq!(roots_of(&[0.0, 0.0, 2.0, -1.0], -10.0, 10.0), vec![0.5]);
        assert!(roots_of(&[f64::NAN, 1.0, 1.0], -1.0, 1.0).len() <= 2);
        // Close roots: (x - 1)(x - 1.000001).
        let close = roots_of(&[1.0, -2.000001, 1.000001], 0.0, 2.0);
        assert_eq!(close.len(), 2);
    }

    #[test]
    fn quadratic_roots() {
        assert_eq!(solve_quadratic(1.0, 0.0, -4.0), Some((-2.0, 2.0)));
        assert_eq!(solve_quadratic(1.0, 0.0, 4.0), None);
        assert_eq!(solve_quadratic(0.0, 1.0, -4.0), Some((2.0, 2.0)));
        assert_eq!(solve_quadratic(0.0, 0.0, 1.0), None);
        let (small, large) = solve_quadratic(1.0, -1e8, 1.0).unwrap();
        assert!((small - 0.5e-8).abs() < 1e-20);
        assert!((large - 2e8).abs() < 1e-6);
        assert_eq!(solve_quadratic(f64::NAN, 1.0, 1.0), None);
    }

    #[test]
    fn roots_keep_nearest_in_range() {
        let mut roots = Roots::new();
        roots.push(3.0, 1);
        roots.push(f64::NAN, 2);
        roots.push(1.0, 3);
        roots.push(-1.0, 4);
        assert_eq!(roots.iter().count(), 3);
        assert_eq!(roots.nearest_within(0.0, 10.0), Some((1.0, 3)));
        assert_eq!(roots.nearest_within(1.0, 10.0), Some((3.0, 1)));
        assert_eq!(roots.nearest_within(1.0, 3.0), None);
    }
}
