//! The patterns that depend on the surface rather than on the point alone: `slope` (the
//! surface normal against a direction, optionally blended with an altitude gradient) and
//! `aoi` (the angle between the ray and the surface).
//!
//! In: a pattern-space point and the [`SurfaceContext`] (point, normal and ray direction in
//! world space) of the hit being shaded. Out: the raw pattern value. Holds: pure,
//! allocation-free; without a surface (zero normal) the value is that of a normal
//! perpendicular to everything, 0.5.
//!
//! Measured against POV-Ray 3.7 renders: the slope direction, `point_at` and the ray and
//! normal of `aoi` live in world space — the pattern's transformations and turbulence do
//! not turn or move them; only the altitude part uses the pattern-space point. Values
//! outside [0, 1] (a `Lo_slope, Hi_slope` range narrower than the slopes met) are not
//! clamped: the wave wraps them like any pattern value.

use glam::{DVec2, DVec3};

/// What a surface-dependent pattern knows of the hit being shaded, in world space. Zero
/// vectors mean "unknown" (a pattern evaluated away from any surface, such as in media).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SurfaceContext {
    /// The hit point.
    pub point: DVec3,
    /// The unit normal facing the incoming ray (before any `normal { }` perturbation).
    pub normal: DVec3,
    /// The unit direction of the ray that hit the surface.
    pub ray_direction: DVec3,
    /// The hit's uv coordinates, when its shape has them and a material there uses them:
    /// uv-mapped pigments nested in other pigments are looked up there.
    pub uv: Option<DVec2>,
}

/// `slope { .. }`'s settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slope {
    /// The unit direction the normal is compared with (for `point_at`, unused).
    pub direction: DVec3,
    /// The weight of the slope part: the length of the direction as written.
    pub slope_weight: f64,
    /// The slope values mapped to 0 and 1.
    pub slope_range: (f64, f64),
    /// `point_at`: the point the normal is compared with the direction to.
    pub point_at: Option<DVec3>,
    /// `altitude`: the unit gradient direction, its weight (length as written) and the
    /// heights mapped to 0 and 1.
    pub altitude: Option<Altitude>,
}

/// The altitude part of a `slope` pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Altitude {
    /// Unit direction of the gradient.
    pub direction: DVec3,
    /// Its weight: the length of the direction as written.
    pub weight: f64,
    /// The heights along `direction` mapped to 0 and 1.
    pub range: (f64, f64),
}

impl Slope {
    /// `slope { direction }` with the full range 0 to 1 and no altitude.
    pub fn new(direction: DVec3) -> Slope {
        let length = direction.length();
        Slope {
            direction: direction.try_normalize().unwrap_or(DVec3::Y),
            slope_weight: length,
            slope_range: (0.0, 1.0),
            point_at: None,
            altitude: None,
        }
    }

    /// The raw value at pattern-space `point` on `surface`.
    pub fn value(&self, point: DVec3, surface: &SurfaceContext) -> f64 {
        let towards = match self.point_at {
            Some(target) => (target - surface.point)
                .try_normalize()
                .unwrap_or(DVec3::ZERO),
            None => self.direction,
        };
        let slope = angle_of_incidence(surface.normal, -towards);
        let slope = stretch(slope, self.slope_range);
        match self.altitude {
            None => slope,
            Some(altitude) => {
                let height = stretch(point.dot(altitude.direction), altitude.range);
                let total = self.slope_weight + altitude.weight;
                if total > 0.0 {
                    (self.slope_weight * slope + altitude.weight * height) / total
                } else {
                    slope
                }
            }
        }
    }
}

/// `value` with `range.0` mapped to 0 and `range.1` to 1 (unchanged for an empty range).
fn stretch(value: f64, (low, high): (f64, f64)) -> f64 {
    let span = high - low;
    if span != 0.0 && span.is_finite() {
        (value - low) / span
    } else {
        value
    }
}

/// `aoi`: 0.5 where the ray grazes the surface, 1 where it meets it head on: one minus the
/// angle between the normal and the reversed ray, over π. (The slope is the same measure of
/// the angle between the normal and the slope direction, measured.)
pub fn angle_of_incidence(normal: DVec3, ray_direction: DVec3) -> f64 {
    let cosine = normal.dot(-ray_direction).clamp(-1.0, 1.0);
    1.0 - cosine.acos() / std::f64::consts::PI
}

#[cfg(test)]
mod tests {
    use super::*;

    fn on(normal: DVec3) -> SurfaceContext {
        SurfaceContext {
            point: DVec3::ZERO,
            normal,
            ray_direction: DVec3::Z,
            uv: None,
        }
    }

    #[test]
    fn slope_measures_the_angle() {
        // POV-Ray: `slope { -y*3, 0, 0.5 }` on a sphere where the normal is 0.974 up gives
        // 0.145 (measured from a render): 1 - angle/pi, stretched over the range.
        let mut slope = Slope::new(DVec3::new(0.0, -3.0, 0.0));
        slope.slope_range = (0.0, 0.5);
        let normal = DVec3::new(0.0, 0.974, -(1.0f64 - 0.974 * 0.974).sqrt());
        assert!((slope.value(DVec3::ZERO, &on(normal)) - 0.145).abs() < 2e-3);
        assert_eq!(Slope::new(DVec3::Y).value(DVec3::ZERO, &on(DVec3::Y)), 1.0);
        // Without a surface: a normal perpendicular to everything.
        let unknown = SurfaceContext::default();
        assert_eq!(Slope::new(DVec3::Y).value(DVec3::ZERO, &unknown), 0.5);
    }

    #[test]
    fn altitude_blends_by_the_written_lengths() {
        let mut slope = Slope::new(DVec3::Y);
        slope.altitude = Some(Altitude {
            direction: DVec3::Y,
            weight: 3.0,
            range: (0.0, 2.0),
        });
        let value = slope.value(DVec3::new(0.0, 1.0, 0.0), &on(DVec3::Y));
        assert!((value - (1.0 + 3.0 * 0.5) / 4.0).abs() < 1e-12);
    }

    #[test]
    fn aoi_is_one_head_on_and_half_grazing() {
        assert_eq!(angle_of_incidence(-DVec3::Z, DVec3::Z), 1.0);
        assert!((angle_of_incidence(DVec3::Y, DVec3::Z) - 0.5).abs() < 1e-12);
    }
}
