//! The `julia_fractal`: a 3D slice of a 4D Julia set in quaternion or hypercomplex algebra.
//!
//! In: a [`JuliaFractal`](crate::scene::JuliaFractal) (parameter, algebra, function,
//! iterations, precision, slice). Out: crossings of a line, inside test, normals, bounds.
//! Holds: a local point (x, y, z) is the 4D point (x, y, z, w) on the slicing hyperplane; it
//! is inside when none of h₀ … h₍ₙ₋₁₎ of the orbit hₖ₊₁ = f(hₖ) + p leaves the bailout
//! sphere (radius min(1 + |p|, 2) for quaternions, 4 for hypercomplex numbers, as measured
//! with POV-Ray's `inside`). That sphere also bounds the shape. Along a ray the search steps
//! by the distance estimate of escaping points, never less than 1 / precision, and bisects
//! each change between inside and outside down to [`TOLERANCE`]; the hit is the inside end.
//! The normal is the gradient of |hₙ|² by the point, carried forward through the orbit.
//! A ray spends at most [`MAX_SAMPLES`] inside tests; nothing allocates.

use super::julia_algebra::{
    complex_function, complex_mul, from_duplex, quaternion_mul, quaternion_square, to_duplex,
};
use super::roots::Roots;
use crate::accel::Aabb;
use crate::scene::{JuliaAlgebra, JuliaFractal as JuliaSpec, JuliaFunction};
use glam::{DVec2, DVec3, DVec4};

/// Length of ray interval at which bisection stops.
const TOLERANCE: f64 = 1e-7;
/// Most inside tests one ray may spend (a huge precision would otherwise take hours); past it
/// the search gives up on the rest of the ray.
const MAX_SAMPLES: u32 = 1 << 18;

/// A julia fractal in its local space.
#[derive(Clone, Debug)]
pub struct JuliaFractal {
    parameter: DVec4,
    algebra: JuliaAlgebra,
    /// The function of the orbit (POV-Ray 3.7 iterates `hypercomplex cube` as `sqr`:
    /// measured with `inside` and renders).
    function: JuliaFunction,
    max_iteration: u32,
    /// The smallest ray step: 1 / precision.
    step: f64,
    /// w = `slice_offset` − `slice_slope` · (x, y, z) on the slicing hyperplane.
    slice_slope: DVec3,
    slice_offset: f64,
    /// Squared radius of the bailout sphere.
    bailout_squared: f64,
}

/// What one inside test learnt about a point.
struct Sample {
    inside: bool,
    /// How far the ray may step from an outside point without missing the set.
    distance: f64,
}

impl JuliaFractal {
    /// The fractal of a scene description; `None` when a value is not finite or the slice
    /// normal has no fourth component.
    pub fn new(spec: &JuliaSpec) -> Option<JuliaFractal> {
        let normal = spec.slice_normal;
        let usable = spec.parameter.is_finite()
            && normal.is_finite()
            && normal.w != 0.0
            && spec.slice_distance.is_finite()
            && !spec.precision.is_nan();
        if !usable {
            return None;
        }
        let length = normal.length();
        let unit = normal / length;
        let slice_slope = unit.truncate() / unit.w;
        let slice_offset = spec.slice_distance / length / unit.w;
        let bailout_radius = match spec.algebra {
            JuliaAlgebra::Quaternion => (1.0 + spec.parameter.length()).min(2.0),
            JuliaAlgebra::Hypercomplex => 4.0,
        };
        Some(JuliaFractal {
            parameter: spec.parameter,
            algebra: spec.algebra,
            function: match (spec.algebra, spec.function) {
                (JuliaAlgebra::Hypercomplex, JuliaFunction::Cube) => JuliaFunction::Sqr,
                (_, function) => function,
            },
            max_iteration: spec.max_iteration,
            step: 1.0 / spec.precision.max(1.0),
            slice_slope,
            slice_offset,
            bailout_squared: bailout_radius * bailout_radius,
        })
    }

    /// The 4D point of the local point `p`.
    #[inline]
    fn lift(&self, p: DVec3) -> DVec4 {
        p.extend(self.slice_offset - self.slice_slope.dot(p))
    }

    /// True when an orbit point of squared length `norm_squared` has left the bailout sphere
    /// (or overflowed).
    #[inline]
    fn escaped(&self, norm_squared: f64) -> bool {
        norm_squared.is_nan() || norm_squared > self.bailout_squared
    }

    /// One step of the orbit: f(h) + p.
    #[inline]
    fn map(&self, h: DVec4) -> DVec4 {
        let image = match (self.algebra, self.function) {
            (JuliaAlgebra::Quaternion, JuliaFunction::Cube) => {
                quaternion_mul(quaternion_square(h), h)
            }
            (JuliaAlgebra::Quaternion, _) => quaternion_square(h),
            (JuliaAlgebra::Hypercomplex, function) => {
                let (a, b) = to_duplex(h);
                from_duplex(
                    complex_function(function, a).0,
                    complex_function(function, b).0,
                )
            }
        };
        image + self.parameter
    }

    /// True when the orbit of `p` stays in the bailout sphere.
    pub fn inside(&self, p: DVec3) -> bool {
        let mut h = self.lift(p);
        for _ in 0..self.max_iteration {
            if self.escaped(h.length_squared()) {
                return false;
            }
            h = self.map(h);
        }
        true
    }

    /// The inside test with a distance estimate for escaping points: |h| ln |h| / (2 |h'|)
    /// with the derivative h' carried along the orbit, for `sqr` and `cube`; the smallest
    /// step for the other functions, whose orbits the estimate does not describe.
    fn sample(&self, p: DVec3) -> Sample {
        let mut h = self.lift(p);
        // |h'| for quaternions; h' itself (in duplex form) for hypercomplex numbers.
        let mut slope = 1.0;
        let mut duplex_slope = (DVec2::X, DVec2::X);
        let estimates = matches!(self.function, JuliaFunction::Sqr | JuliaFunction::Cube);
        for _ in 0..self.max_iteration {
            let norm_squared = h.length_squared();
            if self.escaped(norm_squared) {
                let distance = if estimates {
                    let derivative = match self.algebra {
                        JuliaAlgebra::Quaternion => slope,
                        JuliaAlgebra::Hypercomplex => {
                            from_duplex(duplex_slope.0, duplex_slope.1).length()
                        }
                    };
                    let norm = norm_squared.sqrt();
                    0.5 * norm * norm.ln() / derivative
                } else {
                    0.0
                };
                return Sample {
                    inside: false,
                    distance,
                };
            }
            if estimates {
                let degree = if self.function == JuliaFunction::Cube {
                    3.0
                } else {
                    2.0
                };
                match self.algebra {
                    JuliaAlgebra::Quaternion => {
                        slope *= degree * norm_squared.sqrt().powf(degree - 1.0)
                    }
                    JuliaAlgebra::Hypercomplex => {
                        let (a, b) = to_duplex(h);
                        let derivative_a = complex_function(self.function, a).1;
                        let derivative_b = complex_function(self.function, b).1;
                        duplex_slope = (
                            complex_mul(derivative_a, duplex_slope.0),
                            complex_mul(derivative_b, duplex_slope.1),
                        );
                    }
                }
            }
            h = self.map(h);
        }
        Sample {
            inside: true,
            distance: 0.0,
        }
    }

    /// Pushes the crossings of the line `origin + t direction`, nearest first.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let length = direction.length();
        if !(length > 0.0 && length.is_finite()) {
            return;
        }
        let direction = direction / length;
        // The part of the line inside the bailout sphere.
        let half_b = origin.dot(direction);
        let discriminant = half_b * half_b - (origin.length_squared() - self.bailout_squared);
        if discriminant.is_nan() || discriminant <= 0.0 {
            return;
        }
        let root = discriminant.sqrt();
        let mut depth = -half_b - root;
        let depth_max = -half_b + root;
        if depth_max < TOLERANCE {
            return;
        }
        depth = depth.max(TOLERANCE);
        let sample_at = |depth: f64| self.sample(origin + direction * depth);
        let mut samples = 1;
        let mut current = sample_at(depth);
        // A ray starting inside looks for the way out from just past its start.
        if current.inside {
            depth += 2.0 * TOLERANCE;
            if depth > depth_max {
                return;
            }
            current = sample_at(depth);
        }
        while depth < depth_max {
            // Step until the next sample lies on the other side of the surface.
            let mut step;
            let next = loop {
                if samples >= MAX_SAMPLES {
                    return;
                }
                step = current.distance.max(self.step);
                if depth + step > depth_max {
                    return;
                }
                let next = sample_at(depth + step);
                samples += 1;
                if next.inside != current.inside {
                    break next;
                }
                depth += step;
                current = next;
            };
            // Bisect between `depth` (on the current side) and `depth + step`.
            let stride = step;
            let mut near = depth;
            while step > TOLERANCE {
                step *= 0.5;
                if self.inside(origin + direction * (near + step)) == current.inside {
                    near += step;
                }
            }
            let hit = if current.inside { near } else { near + step };
            roots.push(hit / length, 0);
            depth += stride;
            current = next;
        }
    }

    /// The gradient of |hₙ|² by the point (outwards), carried through the orbit of `p`; the
    /// orbit stops where it leaves the bailout sphere.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let mut h = self.lift(p);
        // ∂h/∂x, ∂h/∂y, ∂h/∂z, including the slope of w along the slice.
        let mut partials = [
            DVec4::new(1.0, 0.0, 0.0, -self.slice_slope.x),
            DVec4::new(0.0, 1.0, 0.0, -self.slice_slope.y),
            DVec4::new(0.0, 0.0, 1.0, -self.slice_slope.z),
        ];
        for _ in 0..self.max_iteration {
            if self.escaped(h.length_squared()) {
                break;
            }
            match (self.algebra, self.function) {
                (JuliaAlgebra::Quaternion, JuliaFunction::Cube) => {
                    let square = quaternion_square(h);
                    for partial in &mut partials {
                        // d(h³) = dh h² + h dh h + h² dh.
                        *partial = quaternion_mul(*partial, square)
                            + quaternion_mul(quaternion_mul(h, *partial), h)
                            + quaternion_mul(square, *partial);
                    }
                }
                (JuliaAlgebra::Quaternion, _) => {
                    for partial in &mut partials {
                        // d(h²) = h dh + dh h.
                        *partial = quaternion_mul(h, *partial) + quaternion_mul(*partial, h);
                    }
                }
                (JuliaAlgebra::Hypercomplex, function) => {
                    let (a, b) = to_duplex(h);
                    let derivative_a = complex_function(function, a).1;
                    let derivative_b = complex_function(function, b).1;
                    for partial in &mut partials {
                        let (da, db) = to_duplex(*partial);
                        *partial = from_duplex(
                            complex_mul(derivative_a, da),
                            complex_mul(derivative_b, db),
                        );
                    }
                }
            }
            h = self.map(h);
        }
        let gradient = DVec3::new(h.dot(partials[0]), h.dot(partials[1]), h.dot(partials[2]));
        if gradient.is_finite() && gradient != DVec3::ZERO {
            gradient
        } else {
            p
        }
    }

    /// The bailout sphere's box.
    pub fn bounds(&self) -> Aabb {
        let radius = self.bailout_squared.sqrt();
        Aabb::from_points([DVec3::splat(-radius), DVec3::splat(radius)])
    }
}
