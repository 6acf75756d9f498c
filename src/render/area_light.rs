//! Area lights: the array of point lights behind soft shadows, sampled as POV-Ray does.
//!
//! In: a light's [`AreaLight`], the lit point and a function giving the light that reaches
//! the point from one position of the array. Out: the averaged light filter. Holds: no
//! allocation (the subdivision recurses on the stack, at most log₂ of the array size
//! deep, and arrays up to 17×17 remember their lights' values in a table on the stack); jitter is a hash of the lit point and the array cell, so images do not depend on
//! the number of threads.
//!
//! Rules (POV-Ray 3.7 manual, checked against renders):
//! - point light (i, j) of a size1 × size2 array sits at
//!   `centre + (i / (size1 − 1) − ½) axis1 + (j / (size2 − 1) − ½) axis2` (at the centre
//!   along an axis with one light).
//! - the array is sampled by blocks, starting with the whole array: a block spanning more
//!   than one cell along an axis is split into four while the subdivision level is below
//!   `adaptive` (always without `adaptive`), or when its four corners differ by more than
//!   [`ADAPTIVE_THRESHOLD`] in some channel. Along each axis, indices u1..u2 split into
//!   u1..⌊(u1+u2)/2⌋ and ⌈(u1+u2)/2⌉..u2 (an odd span gives disjoint halves, an even one
//!   shares the middle). A block's value is the mean of its quarters, or of its four
//!   corners when not split. (Measured: 5×5 and 9×9 arrays weigh their edges half,
//!   4×4 and 8×8 weigh all lights equally, and 6×6 and 7×7 match only this rule.)
//! - `jitter` moves each point light by up to half a cell along each axis.
//! - `circular` pulls the square array radially onto the ellipse inscribed in the
//!   rectangle (renders match POV-Ray's to a few levels in penumbrae, not exactly).
//! - `orient` turns the array to face the lit point (axes keep their lengths).

use super::antialias::mix64;
use crate::scene::AreaLight;
use glam::DVec3;
use std::ops::{Add, Div};

/// A value averaged over an area light's array: a light filter, or lit colours.
pub trait Sampled: Copy + Add<Output = Self> + Div<f64, Output = Self> {
    /// Whether two samples differ enough to split an adaptive block.
    fn differs_from(&self, other: &Self) -> bool;
}

impl Sampled for DVec3 {
    fn differs_from(&self, other: &Self) -> bool {
        (*self - *other).abs().max_element() > ADAPTIVE_THRESHOLD
    }
}

/// Corners of a block differing by more than this (in any channel) split it.
pub const ADAPTIVE_THRESHOLD: f64 = 0.1;

/// Arrays of up to this many point lights (9×9) remember their values in a small table.
const SMALL_ARRAY_LIGHTS: usize = 81;

/// Arrays of up to this many point lights (17×17) remember each light's value while they
/// are averaged; larger ones compute the corners their blocks share again.
const REMEMBERED_LIGHTS: usize = 289;

/// The array of one area light as seen from one lit point.
#[derive(Clone, Copy, Debug)]
pub struct AreaArray {
    centre: DVec3,
    axis1: DVec3,
    axis2: DVec3,
    size1: u32,
    size2: u32,
    min_level: u32,
    jitter_seed: Option<u64>,
    circular: bool,
}

impl AreaArray {
    /// The array of `area` centred on `centre`, seen from `point`.
    pub fn new(area: &AreaLight, centre: DVec3, point: DVec3) -> AreaArray {
        let (axis1, axis2) = if area.orient {
            oriented_axes(area, centre - point)
        } else {
            (area.axis1, area.axis2)
        };
        AreaArray {
            centre,
            axis1,
            axis2,
            size1: area.size1.max(1),
            size2: area.size2.max(1),
            min_level: area.adaptive.unwrap_or(u32::MAX),
            jitter_seed: area.jitter.then(|| hash_point(point)),
            circular: area.circular,
        }
    }

    /// Number of point lights in the array.
    pub fn count(&self) -> u32 {
        self.size1 * self.size2
    }

    /// Position of point light (i, j).
    pub fn position(&self, i: u32, j: u32) -> DVec3 {
        let mut u = grid_coordinate(i, self.size1);
        let mut v = grid_coordinate(j, self.size2);
        if let Some(seed) = self.jitter_seed {
            let bits = mix64(seed ^ (u64::from(i) << 32 | u64::from(j)));
            let (a, b) = (unit_from(bits), unit_from(bits >> 32));
            if self.size1 > 1 {
                u += (a - 0.5) / f64::from(self.size1 - 1);
            }
            if self.size2 > 1 {
                v += (b - 0.5) / f64::from(self.size2 - 1);
            }
        }
        if self.circular {
            (u, v) = square_to_disc(u, v);
        }
        self.centre + u * self.axis1 + v * self.axis2
    }

    /// The mean of `light_from(position)` over the array, sampled block by block. Blocks
    /// share corners, so in arrays of up to [`REMEMBERED_LIGHTS`] point lights each light's
    /// value is computed once and remembered on the stack (a 9×9 `adaptive 1` array needs 9
    /// shadow rays instead of 16); larger arrays compute a shared corner again.
    pub fn average<T: Sampled>(&self, light_from: &mut impl FnMut(DVec3) -> T) -> T {
        let count = u64::from(self.size1) * u64::from(self.size2);
        if count <= SMALL_ARRAY_LIGHTS as u64 {
            self.average_remembering::<SMALL_ARRAY_LIGHTS, T>(light_from)
        } else if count <= REMEMBERED_LIGHTS as u64 {
            self.average_remembering::<REMEMBERED_LIGHTS, T>(light_from)
        } else {
            let mut value_at = |i: u32, j: u32| light_from(self.position(i, j));
            self.block((0, 0), (self.size1 - 1, self.size2 - 1), 0, &mut value_at)
        }
    }

    /// [`AreaArray::average`] remembering each point light's value in a table of `LIGHTS`
    /// entries (at least the array's size), so no light is computed twice.
    fn average_remembering<const LIGHTS: usize, T: Sampled>(
        &self,
        light_from: &mut impl FnMut(DVec3) -> T,
    ) -> T {
        let mut remembered: [Option<T>; LIGHTS] = [None; LIGHTS];
        let mut value_at = |i: u32, j: u32| {
            let index = j as usize * self.size1 as usize + i as usize;
            *remembered[index].get_or_insert_with(|| light_from(self.position(i, j)))
        };
        self.block((0, 0), (self.size1 - 1, self.size2 - 1), 0, &mut value_at)
    }

    /// The value of the block of point lights from (u1, v1) to (u2, v2).
    fn block<T: Sampled>(
        &self,
        (u1, v1): (u32, u32),
        (u2, v2): (u32, u32),
        level: u32,
        value_at: &mut impl FnMut(u32, u32) -> T,
    ) -> T {
        let splittable = u2 - u1 > 1 || v2 - v1 > 1;
        if !splittable || level >= self.min_level {
            let corners = [(u1, v1), (u2, v1), (u1, v2), (u2, v2)].map(|(i, j)| value_at(i, j));
            if !splittable || !corners_differ(&corners) {
                return (corners[0] + corners[1] + corners[2] + corners[3]) / 4.0;
            }
        }
        // An odd span splits into two disjoint halves, an even one shares its middle.
        let (u_low, u_high) = ((u1 + u2) / 2, (u1 + u2).div_ceil(2));
        let (v_low, v_high) = ((v1 + v2) / 2, (v1 + v2).div_ceil(2));
        let next = level + 1;
        let quarters = [
            self.block((u1, v1), (u_low, v_low), next, value_at),
            self.block((u_high, v1), (u2, v_low), next, value_at),
            self.block((u1, v_high), (u_low, v2), next, value_at),
            self.block((u_high, v_high), (u2, v2), next, value_at),
        ];
        (quarters[0] + quarters[1] + quarters[2] + quarters[3]) / 4.0
    }
}

/// Position along an axis of light `index` of `size`, from −½ to ½.
fn grid_coordinate(index: u32, size: u32) -> f64 {
    if size > 1 {
        f64::from(index) / f64::from(size - 1) - 0.5
    } else {
        0.0
    }
}

/// Whether any two corner values differ by more than the adaptive threshold.
fn corners_differ<T: Sampled>(corners: &[T; 4]) -> bool {
    corners
        .iter()
        .enumerate()
        .any(|(index, a)| corners[index + 1..].iter().any(|b| a.differs_from(b)))
}

/// Maps the square [−½, ½]² onto the inscribed disc of radius ½ by pulling each point in
/// along its direction from the centre, so that the square of half-size r lands on the
/// circle of radius r (closer to POV-Ray's renders than a concentric mapping).
fn square_to_disc(u: f64, v: f64) -> (f64, f64) {
    let length = (u * u + v * v).sqrt();
    if length == 0.0 {
        return (0.0, 0.0);
    }
    let pull = u.abs().max(v.abs()) / length;
    (u * pull, v * pull)
}

/// The area light's axes turned to be perpendicular to `towards_light` (lengths kept).
fn oriented_axes(area: &AreaLight, towards_light: DVec3) -> (DVec3, DVec3) {
    let Some(facing) = towards_light.try_normalize() else {
        return (area.axis1, area.axis2);
    };
    let helper = if facing.x.abs() < 0.9 {
        DVec3::X
    } else {
        DVec3::Y
    };
    let first = facing.cross(helper).normalize();
    let second = facing.cross(first);
    (first * area.axis1.length(), second * area.axis2.length())
}

/// A number in [0, 1) that depends only on `point` and `salt` (for deterministic
/// randomness such as `crand`).
pub fn point_random(point: DVec3, salt: u64) -> f64 {
    unit_from(mix64(hash_point(point) ^ salt))
}

/// A seed from the bits of a point (the same point always gives the same jitter).
fn hash_point(point: DVec3) -> u64 {
    let mut hash = 0x9e37_79b9_7f4a_7c15u64;
    for coordinate in [point.x, point.y, point.z] {
        hash = mix64(hash ^ coordinate.to_bits());
    }
    hash
}

/// A number in [0, 1) from the low 32 bits.
fn unit_from(bits: u64) -> f64 {
    f64::from(bits as u32) / 4_294_967_296.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(size1: u32, size2: u32) -> AreaLight {
        AreaLight {
            axis1: DVec3::new(4.0, 0.0, 0.0),
            axis2: DVec3::new(0.0, 0.0, 2.0),
            size1,
            size2,
            adaptive: None,
            jitter: false,
            circular: false,
            orient: false,
            area_illumination: false,
        }
    }

    #[test]
    fn grid_positions_span_the_axes() {
        let array = AreaArray::new(&area(3, 2), DVec3::Y, DVec3::ZERO);
        assert_eq!(array.position(0, 0), DVec3::new(-2.0, 1.0, -1.0));
        assert_eq!(array.position(1, 0), DVec3::new(0.0, 1.0, -1.0));
        assert_eq!(array.position(2, 1), DVec3::new(2.0, 1.0, 1.0));
        let line = AreaArray::new(&area(1, 1), DVec3::Y, DVec3::ZERO);
        assert_eq!(line.position(0, 0), DVec3::Y);
    }

    #[test]
    fn full_sampling_tests_every_light_of_a_power_of_two_plus_one_grid() {
        let array = AreaArray::new(&area(5, 5), DVec3::ZERO, DVec3::new(0.0, -5.0, 0.0));
        let mut tested = 0;
        // Light only from the positive x half (and the middle column).
        let value = array.average(&mut |p: DVec3| {
            tested += 1;
            DVec3::splat(if p.x >= 0.0 { 1.0 } else { 0.0 })
        });
        assert!(tested >= 25);
        // Blocks' corners: columns 0..2 give 0,0,1 per block pair → 0.25 and 1 → mean 0.625.
        assert!((value.x - 0.625).abs() < 1e-12, "{value}");
    }

    #[test]
    fn odd_spans_split_into_disjoint_halves() {
        // A 4×1 array weighs its lights equally, as POV-Ray does.
        let array = AreaArray::new(&area(4, 1), DVec3::ZERO, DVec3::new(0.0, -5.0, 0.0));
        let value = array.average(&mut |p: DVec3| DVec3::splat(if p.x < -1.0 { 1.0 } else { 0.0 }));
        assert!((value.x - 0.25).abs() < 1e-12, "{value}");
    }

    /// How many point lights an `adaptive` array of `size` × `size` tests for a uniformly
    /// lit point, and the average it finds.
    fn tests_for_uniform_light(size: u32, adaptive: u32) -> (usize, DVec3) {
        let mut light = area(size, size);
        light.adaptive = Some(adaptive);
        let array = AreaArray::new(&light, DVec3::ZERO, DVec3::new(0.0, -5.0, 0.0));
        let mut tested = 0;
        let value = array.average(&mut |_| {
            tested += 1;
            DVec3::ONE
        });
        (tested, value)
    }

    #[test]
    fn adaptive_zero_stops_at_uniform_corners() {
        let (tested, value) = tests_for_uniform_light(9, 0);
        assert_eq!(tested, 4);
        assert_eq!(value, DVec3::ONE);
    }

    #[test]
    fn shared_corners_are_computed_once() {
        // adaptive 1 splits a 9×9 array into four blocks sharing a 3×3 grid of corners.
        let (tested, value) = tests_for_uniform_light(9, 1);
        assert_eq!(tested, 9);
        assert_eq!(value, DVec3::ONE);
        // Past the remembered size every block computes its own corners.
        let (tested, _) = tests_for_uniform_light(19, 1);
        assert_eq!(tested, 16);
    }

    #[test]
    fn jitter_is_deterministic_and_stays_in_its_cell() {
        let mut light = area(5, 5);
        light.jitter = true;
        let point = DVec3::new(0.3, -2.0, 0.7);
        let first = AreaArray::new(&light, DVec3::ZERO, point);
        let again = AreaArray::new(&light, DVec3::ZERO, point);
        for i in 0..5 {
            for j in 0..5 {
                let p = first.position(i, j);
                assert_eq!(p, again.position(i, j));
                let plain = AreaArray::new(&area(5, 5), DVec3::ZERO, point).position(i, j);
                assert!((p.x - plain.x).abs() <= 0.5 + 1e-12);
                assert!((p.z - plain.z).abs() <= 0.25 + 1e-12);
            }
        }
    }

    #[test]
    fn circular_arrays_fit_in_the_ellipse() {
        let mut light = area(5, 5);
        light.circular = true;
        let array = AreaArray::new(&light, DVec3::ZERO, DVec3::new(0.0, -5.0, 0.0));
        for i in 0..5 {
            for j in 0..5 {
                let p = array.position(i, j);
                let r = (p.x / 2.0).powi(2) + (p.z / 1.0).powi(2);
                assert!(r <= 1.0 + 1e-12, "{p}");
            }
        }
        assert!((array.position(4, 2) - DVec3::new(2.0, 0.0, 0.0)).length() < 1e-12);
    }

    #[test]
    fn oriented_arrays_face_the_point() {
        let mut light = area(3, 3);
        light.orient = true;
        light.axis2 = DVec3::new(0.0, 0.0, 4.0);
        let point = DVec3::new(5.0, 0.0, 0.0);
        let array = AreaArray::new(&light, DVec3::ZERO, point);
        for (i, j) in [(0, 0), (2, 0), (0, 2), (2, 2)] {
            let p = array.position(i, j);
            assert!(p.x.abs() < 1e-12, "{p}");
            assert!((p.length() - 8f64.sqrt()).abs() < 1e-12);
        }
    }
}
