//! Small fixed-size containers and solvers shared by the shapes.
//!
//! In: polynomial coefficients, ray parameters. Out: [`Roots`] (up to eight ray parameters, each
//! tagged with the surface part it belongs to) and sorted real quadratic roots.
//! Holds: nothing allocates; non-finite parameters are never stored.

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

#[cfg(test)]
mod tests {
    use super::*;

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
