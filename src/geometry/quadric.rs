//! The general quadric surface, in the object's local space.
//!
//! In: the ten coefficients of A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J
//! (POV-Ray's `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }` order). Out: intersections, inside
//! test (the polynomial is negative inside), gradient normals. Holds: quadrics are unbounded.

use super::roots::{solve_quadratic, Roots};
use glam::DVec3;

/// A quadric surface: the zero set of a second-degree polynomial in x, y, z.
#[derive(Clone, Copy, Debug)]
pub struct Quadric {
    /// A, B, C: the square terms.
    squares: DVec3,
    /// D, E, F: the xy, xz and yz terms.
    mixed: DVec3,
    /// G, H, I: the linear terms.
    linear: DVec3,
    /// J: the constant term.
    constant: f64,
}

impl Quadric {
    /// A quadric from POV-Ray's ten coefficients; `None` when one is not finite or all the
    /// non-constant ones are zero.
    pub fn new(coefficients: [f64; 10]) -> Option<Quadric> {
        let [a, b, c, d, e, f, g, h, i, j] = coefficients;
        let quadric = Quadric {
            squares: DVec3::new(a, b, c),
            mixed: DVec3::new(d, e, f),
            linear: DVec3::new(g, h, i),
            constant: j,
        };
        let finite = coefficients.iter().all(|value| value.is_finite());
        let trivial = coefficients[..9].iter().all(|&value| value == 0.0);
        (finite && !trivial).then_some(quadric)
    }

    /// POV-Ray's ten coefficients `A` to `J`.
    pub fn coefficients(&self) -> [f64; 10] {
        let (s, m, l) = (self.squares, self.mixed, self.linear);
        [s.x, s.y, s.z, m.x, m.y, m.z, l.x, l.y, l.z, self.constant]
    }

    /// The polynomial's value at `point`.
    pub fn value(&self, point: DVec3) -> f64 {
        let p = point;
        self.squares.dot(p * p)
            + self.mixed.dot(DVec3::new(p.x * p.y, p.x * p.z, p.y * p.z))
            + self.linear.dot(p)
            + self.constant
    }

    /// Pushes the crossings of the line `origin + t direction`.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let (o, d) = (origin, direction);
        let a =
            self.squares.dot(d * d) + self.mixed.dot(DVec3::new(d.x * d.y, d.x * d.z, d.y * d.z));
        let half_b = self.squares.dot(o * d)
            + 0.5
                * (self.mixed.dot(DVec3::new(
                    o.x * d.y + o.y * d.x,
                    o.x * d.z + o.z * d.x,
                    o.y * d.z + o.z * d.y,
                )) + self.linear.dot(d));
        let c = self.value(o);
        if let Some((near, far)) = solve_quadratic(a, half_b, c) {
            roots.push(near, 0);
            if far != near {
                roots.push(far, 0);
            }
        }
    }

    /// True when the polynomial is negative at `point`.
    pub fn inside(&self, point: DVec3) -> bool {
        self.value(point) < 0.0
    }

    /// The gradient at `point`, which points outwards (towards positive values).
    pub fn normal(&self, point: DVec3) -> DVec3 {
        let p = point;
        let (d, e, f) = (self.mixed.x, self.mixed.y, self.mixed.z);
        2.0 * self.squares * p
            + DVec3::new(d * p.y + e * p.z, d * p.x + f * p.z, e * p.x + f * p.y)
            + self.linear
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadric_sphere_matches_sphere() {
        // x² + y² + z² - 1 = 0.
        let quadric = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]).unwrap();
        let mut roots = Roots::new();
        quadric.intersect(DVec3::new(0.0, 0.0, -5.0), DVec3::Z, &mut roots);
        assert_eq!(roots.nearest_within(0.0, 100.0), Some((4.0, 0)));
        assert!(quadric.inside(DVec3::ZERO));
        assert_eq!(
            quadric.normal(DVec3::new(0.0, 0.0, -1.0)),
            DVec3::new(0.0, 0.0, -2.0)
        );
    }

    #[test]
    fn quadric_cylinder_along_z_and_paraboloid() {
        // x² + y² - 1 = 0: infinite cylinder along z.
        let cylinder = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]).unwrap();
        let mut roots = Roots::new();
        cylinder.intersect(DVec3::new(0.0, 0.0, -5.0), DVec3::Z, &mut roots);
        assert!(roots.iter().next().is_none());
        // x² + z² - y = 0: a paraboloid; the line x = 1 crosses it once, at y = 1.
        let bowl = Quadric::new([1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0]).unwrap();
        let mut roots = Roots::new();
        bowl.intersect(DVec3::new(1.0, -5.0, 0.0), DVec3::Y, &mut roots);
        assert_eq!(roots.iter().collect::<Vec<_>>(), vec![(6.0, 0)]);
        assert!(Quadric::new([0.0; 10]).is_none());
    }
}
