//! Polynomial surfaces (`poly`, `cubic`, `quartic`) of total degree 2 to 7.
//!
//! In: POV-Ray's coefficient list (terms x^i y^j z^k, i from the order down, then j, then k).
//! Out: every crossing of a line (exact root isolation, so `sturm` changes nothing), inside
//! test (the polynomial is negative inside), gradient normals. Holds: the surface is unbounded;
//! crossings farther than [`MAX_DISTANCE`] along a unit direction are ignored, as POV-Ray does.

use super::roots::{real_roots_between, Roots, MAX_DEGREE};
use glam::DVec3;

/// Crossings farther than this (local units along a unit direction) are not reported.
pub const MAX_DISTANCE: f64 = 1e7;

/// One term `coefficient x^i y^j z^k`.
#[derive(Clone, Copy, Debug)]
struct Term {
    coefficient: f64,
    powers: [usize; 3],
}

/// The zero set of a polynomial in x, y and z.
#[derive(Clone, Debug)]
pub struct PolySurface {
    order: usize,
    /// The non-zero terms.
    terms: Vec<Term>,
}

impl PolySurface {
    /// A surface from POV-Ray's coefficients; `None` for a wrong count, a non-finite
    /// coefficient or a polynomial without x, y or z.
    pub fn new(order: u32, coefficients: &[f64]) -> Option<PolySurface> {
        let order = order as usize;
        if !(1..=MAX_DEGREE).contains(&order) {
            return None;
        }
        let mut terms = Vec::new();
        let mut index = 0;
        for i in (0..=order).rev() {
            for j in (0..=order - i).rev() {
                for k in (0..=order - i - j).rev() {
                    let coefficient = *coefficients.get(index)?;
                    index += 1;
                    if !coefficient.is_finite() {
                        return None;
                    }
                    if coefficient != 0.0 {
                        terms.push(Term {
                            coefficient,
                            powers: [i, j, k],
                        });
                    }
                }
            }
        }
        let constant_only = terms.iter().all(|t| t.powers == [0, 0, 0]);
        (index == coefficients.len() && !constant_only).then_some(PolySurface { order, terms })
    }

    /// The polynomial's value at `point`.
    pub fn value(&self, point: DVec3) -> f64 {
        let powers = self.powers_of(point);
        self.terms
            .iter()
            .map(|t| {
                t.coefficient
                    * powers[0][t.powers[0]]
                    * powers[1][t.powers[1]]
                    * powers[2][t.powers[2]]
            })
            .sum()
    }

    /// x^n, y^n and z^n for n up to the order.
    fn powers_of(&self, point: DVec3) -> [[f64; MAX_DEGREE + 1]; 3] {
        let mut powers = [[1.0; MAX_DEGREE + 1]; 3];
        for axis in 0..3 {
            for n in 1..=self.order {
                powers[axis][n] = powers[axis][n - 1] * point[axis];
            }
        }
        powers
    }

    /// Pushes every crossing of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let speed = direction.length();
        if !(speed > 0.0 && speed.is_finite() && origin.is_finite()) {
            return;
        }
        let unit = direction / speed;
        // (o + t d)^n as polynomials in t, lowest power first, for each axis.
        let mut axis_powers = [[[0.0; MAX_DEGREE + 1]; MAX_DEGREE + 1]; 3];
        for axis in 0..3 {
            axis_powers[axis][0][0] = 1.0;
            for n in 1..=self.order {
                for power in 0..=n {
                    let keep = axis_powers[axis][n - 1][power] * origin[axis];
                    let raise = if power > 0 {
                        axis_powers[axis][n - 1][power - 1] * unit[axis]
                    } else {
                        0.0
                    };
                    axis_powers[axis][n][power] = keep + raise;
                }
            }
        }
        let mut along = [0.0; MAX_DEGREE + 1];
        for term in &self.terms {
            let [i, j, k] = term.powers;
            let (px, py, pz) = (&axis_powers[0][i], &axis_powers[1][j], &axis_powers[2][k]);
            for a in 0..=i {
                if px[a] == 0.0 {
                    continue;
                }
                for b in 0..=j {
                    let xy = px[a] * py[b];
                    if xy == 0.0 {
                        continue;
                    }
                    for c in 0..=k {
                        along[a + b + c] += term.coefficient * xy * pz[c];
                    }
                }
            }
        }
        // Highest power first for the root finder.
        let mut coefficients = [0.0; MAX_DEGREE + 1];
        for (slot, value) in coefficients[..=self.order]
            .iter_mut()
            .zip(along[..=self.order].iter().rev())
        {
            *slot = *value;
        }
        let mut found = [0.0; MAX_DEGREE];
        let count = real_roots_between(
            &coefficients[..=self.order],
            -MAX_DISTANCE,
            MAX_DISTANCE,
            &mut found,
        );
        for &root in &found[..count] {
            roots.push(root / speed, 0);
        }
    }

    /// True when the polynomial is negative at `point`.
    pub fn inside(&self, point: DVec3) -> bool {
        self.value(point) < 0.0
    }

    /// The gradient at `point` (points towards positive values: outwards).
    pub fn normal(&self, point: DVec3) -> DVec3 {
        let powers = self.powers_of(point);
        let mut gradient = DVec3::ZERO;
        for term in &self.terms {
            for axis in 0..3 {
                let n = term.powers[axis];
                if n == 0 {
                    continue;
                }
                let mut product = term.coefficient * n as f64;
                for (other, axis_powers) in powers.iter().enumerate() {
                    let power = if other == axis {
                        n - 1
                    } else {
                        term.powers[other]
                    };
                    product *= axis_powers[power];
                }
                gradient[axis] += product;
            }
        }
        gradient
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Coefficients of a torus (major 2, minor 0.5) around Y as a quartic:
    /// (x²+y²+z²+R²-r²)² - 4R²(x²+z²).
    fn torus_quartic() -> Vec<f64> {
        let (major, minor) = (2.0_f64, 0.5_f64);
        let k = major * major - minor * minor;
        let mut c = vec![0.0; 35];
        let mut set = |powers: [usize; 3], value: f64| {
            let mut index = 0;
            for i in (0..=4usize).rev() {
                for j in (0..=4 - i).rev() {
                    for k in (0..=4 - i - j).rev() {
                        if [i, j, k] == powers {
                            c[index] += value;
                        }
                        index += 1;
                    }
                }
            }
        };
        set([4, 0, 0], 1.0);
        set([0, 4, 0], 1.0);
        set([0, 0, 4], 1.0);
        set([2, 2, 0], 2.0);
        set([2, 0, 2], 2.0);
        set([0, 2, 2], 2.0);
        set([2, 0, 0], 2.0 * k - 4.0 * major * major);
        set([0, 2, 0], 2.0 * k);
        set([0, 0, 2], 2.0 * k - 4.0 * major * major);
        set([0, 0, 0], k * k);
        c
    }

    #[test]
    fn quartic_torus_crossings() {
        let torus = PolySurface::new(4, &torus_quartic()).unwrap();
        let mut roots = Roots::new();
        torus.intersect(DVec3::new(-5.0, 0.0, 0.0), DVec3::X * 2.0, &mut roots);
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        let expected = [1.25, 1.75, 3.25, 3.75];
        assert_eq!(found.len(), 4);
        for (got, want) in found.iter().zip(expected) {
            assert!((got - want).abs() < 1e-9, "{got} vs {want}");
        }
        assert!(torus.inside(DVec3::new(2.0, 0.0, 0.0)));
        assert!(!torus.inside(DVec3::ZERO));
        let normal = torus.normal(DVec3::new(2.5, 0.0, 0.0)).normalize();
        assert!(normal.abs_diff_eq(DVec3::X, 1e-12));
    }

    #[test]
    fn crossings_agree_with_inside_test() {
        let torus = PolySurface::new(4, &torus_quartic()).unwrap();
        super::super::test_support::assert_crossings_flip_inside(
            12345,
            4.0,
            0.0,
            1e-6,
            |origin, direction, roots| torus.intersect(origin, direction, roots),
            |point| torus.inside(point),
        );
    }

    #[test]
    fn degenerate_polys_are_rejected() {
        assert!(PolySurface::new(4, &[0.0; 35]).is_none());
        assert!(PolySurface::new(3, &[1.0; 35]).is_none());
        assert!(PolySurface::new(9, &[1.0; 220]).is_none());
        let mut nan = vec![0.0; 20];
        nan[0] = f64::NAN;
        assert!(PolySurface::new(3, &nan).is_none());
    }
}
