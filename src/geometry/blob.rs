//! Blobs: the surface where a sum of component fields equals a threshold.
//!
//! In: components (spheres, and cylinders with hemispherical caps) with strength, radius and
//! a transform into the blob's space. Out: every crossing of a line (per interval where the
//! same components are active, the field is a quartic in the ray parameter, solved exactly),
//! inside test (field above the threshold), outward normals (against the field gradient),
//! bounds. Holds: at most [`MAX_ROOTS`] crossings are reported: the nearest ahead of the
//! origin, then the nearest behind it (stretches are solved outward from the origin, only until
//! those are found); elements are stored in the order of a per-blob [`Bvh`] over their regions
//! of influence, so a ray or point only visits the elements whose boxes it meets; per-ray work
//! uses per-thread scratch vectors that are reused.

use super::roots::{real_roots_between, Roots, MAX_DEGREE, MAX_ROOTS};
use super::TextureBlend;
use crate::accel::{Aabb, Bvh};
use crate::scene::{Blob as SceneBlob, BlobKind};
use glam::{DAffine3, DVec3};
use std::cell::RefCell;

/// One field element: a distance measured in the component's space, maybe limited to a slab
/// along an axis (cylinder body and caps).
#[derive(Clone, Copy, Debug)]
struct Element {
    /// Blob space to component space.
    component_from_blob: DAffine3,
    /// The point (sphere, cap) or axis start (cylinder body).
    centre: DVec3,
    /// Unit axis for cylinder parts; zero for a sphere.
    axis: DVec3,
    /// Distance measured perpendicular to `axis` (cylinder body) or to `centre` (sphere, cap).
    perpendicular: bool,
    /// Allowed range of `(q - centre) · axis`.
    slab: (f64, f64),
    inverse_radius_squared: f64,
    strength: f64,
    /// The material of the component's texture (see [`Blob::with_materials`]).
    material: u32,
}

impl Element {
    /// The squared distance as `a t² + b t + c` along `q0 + t qd`.
    fn distance_squared(&self, q0: DVec3, qd: DVec3) -> (f64, f64, f64) {
        let offset = q0 - self.centre;
        if self.perpendicular {
            let (oa, da) = (offset.dot(self.axis), qd.dot(self.axis));
            (
                qd.length_squared() - da * da,
                2.0 * (offset.dot(qd) - oa * da),
                offset.length_squared() - oa * oa,
            )
        } else {
            (
                qd.length_squared(),
                2.0 * offset.dot(qd),
                offset.length_squared(),
            )
        }
    }

    /// Where the line `origin + t direction` (blob space) runs through this element's region
    /// of influence, with the field there as a quartic in `t`; `None` when it misses.
    fn interval(&self, origin: DVec3, direction: DVec3) -> Option<Active> {
        let q0 = self.component_from_blob.transform_point3(origin);
        let qd = self.component_from_blob.transform_vector3(direction);
        let (a, b, c) = self.distance_squared(q0, qd);
        let k = self.inverse_radius_squared;
        // Inside the radius: a t² + b t + c < R².
        let (mut start, mut end) = super::roots::solve_quadratic(a, 0.5 * b, c - 1.0 / k)?;
        if a <= 0.0 {
            return None;
        }
        if self.axis != DVec3::ZERO {
            let (oa, da) = ((q0 - self.centre).dot(self.axis), qd.dot(self.axis));
            if da == 0.0 {
                if oa < self.slab.0 || oa > self.slab.1 {
                    return None;
                }
            } else {
                let first = (self.slab.0 - oa) / da;
                let second = (self.slab.1 - oa) / da;
                start = start.max(first.min(second));
                end = end.min(first.max(second));
            }
        }
        if start.partial_cmp(&end) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        let (p2, p1, p0) = (-k * a, -k * b, 1.0 - k * c);
        let s = self.strength;
        let quartic = [
            s * p0 * p0,
            s * 2.0 * p1 * p0,
            s * (p1 * p1 + 2.0 * p2 * p0),
            s * 2.0 * p2 * p1,
            s * p2 * p2,
        ];
        // The falloff peaks where the line passes nearest the centre or axis.
        let peak_falloff = (1.0 - k * (c - b * b / (4.0 * a))).clamp(0.0, 1.0);
        Some(Active {
            start,
            end,
            quartic,
            peak: s.max(0.0) * peak_falloff * peak_falloff,
        })
    }

    /// The field at blob-space `point`.
    fn value(&self, point: DVec3) -> f64 {
        self.field(point).0
    }

    /// The field at blob-space `point`, and its gradient.
    fn field(&self, point: DVec3) -> (f64, DVec3) {
        let q = self.component_from_blob.transform_point3(point);
        let offset = q - self.centre;
        let along = offset.dot(self.axis);
        if self.axis != DVec3::ZERO && (along < self.slab.0 || along > self.slab.1) {
            return (0.0, DVec3::ZERO);
        }
        let radial = if self.perpendicular {
            offset - self.axis * along
        } else {
            offset
        };
        let falloff = 1.0 - radial.length_squared() * self.inverse_radius_squared;
        if falloff <= 0.0 {
            return (0.0, DVec3::ZERO);
        }
        let value = self.strength * falloff * falloff;
        let local_gradient =
            radial * (-4.0 * self.strength * falloff * self.inverse_radius_squared);
        let gradient = self.component_from_blob.matrix3.transpose() * local_gradient;
        (value, gradient)
    }
}

/// A prepared blob.
#[derive(Clone, Debug)]
pub struct Blob {
    threshold: f64,
    /// Elements in the order of `tree`'s leaves.
    elements: Vec<Element>,
    /// Hierarchy over the blob-space boxes of the elements' regions of influence.
    tree: Bvh,
    bounds: Aabb,
    /// The elements carry the materials of their components' textures.
    textured: bool,
}

/// An interval of the ray where one element is active, with its field as a quartic
/// (lowest power first).
#[derive(Clone, Copy, Debug)]
struct Active {
    start: f64,
    end: f64,
    quartic: [f64; 5],
    /// An upper bound on the element's field along the interval (zero for a negative
    /// strength).
    peak: f64,
}

/// Where an element's interval starts or ends: ray parameter, interval index, entering.
type Event = (f64, usize, bool);

/// Reusable per-ray storage: the intervals the ray crosses, their sorted ends, and the
/// intervals covering the current stretch of the ray.
#[derive(Default)]
struct Scratch {
    intervals: Vec<Active>,
    events: Vec<Event>,
    covering: Vec<usize>,
}

thread_local! {
    /// Per-thread scratch, reused from ray to ray.
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// Relative widening of each element's box, so rounding in the box test never drops an
/// element whose interval the exact quadratic would find.
const BOX_PADDING: f64 = 1e-9;

/// Relative margin below the threshold under which a stretch of the ray whose fields cannot
/// sum to more counts as never reaching it (so rounding cannot hide a grazing crossing).
const UNREACHABLE_MARGIN: f64 = 1e-9;

/// Moves the set of intervals covering the ray across `event`: forward (`forward`) enters
/// or leaves its interval as the event says, backward does the opposite.
fn apply(covering: &mut Vec<usize>, (_, index, entering): Event, forward: bool) {
    if entering == forward {
        covering.push(index);
    } else if let Some(slot) = covering.iter().position(|&open| open == index) {
        covering.swap_remove(slot);
    }
}

impl Blob {
    /// A blob from the scene's description; `None` when no component has a usable radius
    /// and transform.
    pub fn new(blob: &SceneBlob) -> Option<Blob> {
        let mut elements = Vec::new();
        let mut element_bounds = Vec::new();
        for (index, component) in blob.components.iter().enumerate() {
            let radius = component.radius;
            let forward = component.transform.outer_from_inner;
            let backward = component.transform.inner_from_outer;
            let usable = radius > 0.0
                && radius.is_finite()
                && component.strength.is_finite()
                && forward.is_finite()
                && backward.is_finite()
                && forward.matrix3.determinant() != 0.0;
            if !usable {
                continue;
            }
            let base = Element {
                component_from_blob: backward,
                centre: DVec3::ZERO,
                axis: DVec3::ZERO,
                perpendicular: false,
                slab: (f64::NEG_INFINITY, f64::INFINITY),
                inverse_radius_squared: 1.0 / (radius * radius),
                strength: component.strength,
                material: index as u32,
            };
            let reach = DVec3::splat(radius);
            // Blob-space box around the balls of influence at `points` (component space).
            let influence = |points: &[DVec3]| {
                let corners = points.iter().flat_map(|&p| [p - reach, p + reach]);
                Aabb::from_points(corners)
                    .transformed(&forward)
                    .padded(BOX_PADDING, 0.0)
            };
            match component.kind {
                BlobKind::Sphere { centre } => {
                    elements.push(Element { centre, ..base });
                    element_bounds.push(influence(&[centre]));
                }
                BlobKind::Cylinder { end1, end2 } => {
                    let Some(axis) = (end2 - end1).try_normalize() else {
                        continue;
                    };
                    let length = (end2 - end1).length();
                    elements.push(Element {
                        centre: end1,
                        axis,
                        perpendicular: true,
                        slab: (0.0, length),
                        ..base
                    });
                    elements.push(Element {
                        centre: end1,
                        axis,
                        slab: (f64::NEG_INFINITY, 0.0),
                        ..base
                    });
                    elements.push(Element {
                        centre: end2,
                        axis,
                        slab: (0.0, f64::INFINITY),
                        ..base
                    });
                    element_bounds.push(influence(&[end1, end2]));
                    element_bounds.push(influence(&[end1]));
                    element_bounds.push(influence(&[end2]));
                }
            }
        }
        let usable = !elements.is_empty()
            && blob.threshold.is_finite()
            && element_bounds.iter().all(Aabb::is_finite);
        if !usable {
            return None;
        }
        let bounds = element_bounds
            .iter()
            .fold(Aabb::EMPTY, |all, element| all.union(element));
        let (tree, order) = Bvh::build(&element_bounds);
        let elements = order
            .iter()
            .map(|&index| elements[index as usize])
            .collect();
        Some(Blob {
            threshold: blob.threshold,
            elements,
            tree,
            bounds,
            textured: false,
        })
    }

    /// The blob with each component's texture shown: `materials[k]` is the material of
    /// component `k` (its own texture, or the blob's for a component without one).
    pub fn with_materials(mut self, materials: &[u32]) -> Blob {
        if materials.is_empty() {
            return self;
        }
        for element in &mut self.elements {
            let index = (element.material as usize).min(materials.len() - 1);
            element.material = materials[index];
        }
        self.textured = true;
        self
    }

    /// True when the components' textures blend on the surface.
    pub fn is_textured(&self) -> bool {
        self.textured
    }

    /// How the components' textures blend at `point` (measured in POV-Ray 3.7: each
    /// component weighs in by the absolute value of its field there, negative components
    /// too, the weights scaled to sum to 1; each texture is shaded on its own and the
    /// colours blended). `None` for a blob without component textures, or a point no
    /// component reaches.
    pub fn texture_blend(&self, point: DVec3) -> Option<TextureBlend> {
        if !self.textured {
            return None;
        }
        let mut parts: Vec<(u32, f64)> = Vec::new();
        self.tree.any_containing(point, |position| {
            let element = &self.elements[position];
            let value = element.value(point).abs();
            if value > 0.0 {
                parts.push((element.material, value));
            }
            false
        });
        TextureBlend::weighted(parts)
    }

    /// The summed field at `point`, and its gradient.
    fn field(&self, point: DVec3) -> (f64, DVec3) {
        let (mut value, mut gradient) = (0.0, DVec3::ZERO);
        self.tree.any_containing(point, |position| {
            let (element_value, element_gradient) = self.elements[position].field(point);
            value += element_value;
            gradient += element_gradient;
            false
        });
        (value, gradient)
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        SCRATCH.with(|scratch| match scratch.try_borrow_mut() {
            Ok(mut scratch) => self.intersect_with(origin, direction, roots, &mut scratch),
            Err(_) => self.intersect_with(origin, direction, roots, &mut Scratch::default()),
        });
    }

    fn intersect_with(
        &self,
        origin: DVec3,
        direction: DVec3,
        roots: &mut Roots,
        scratch: &mut Scratch,
    ) {
        let Scratch {
            intervals,
            events,
            covering,
        } = scratch;
        intervals.clear();
        events.clear();
        covering.clear();
        let inverse_direction = direction.recip();
        self.tree.for_each_on_ray(
            origin,
            inverse_direction,
            f64::NEG_INFINITY,
            f64::INFINITY,
            |position| {
                if let Some(interval) = self.elements[position].interval(origin, direction) {
                    events.push((interval.start, intervals.len(), true));
                    events.push((interval.end, intervals.len(), false));
                    intervals.push(interval);
                }
            },
        );
        // Events at the same parameter may come in any order: a stretch starts only after all
        // of them are applied.
        events.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        // Stretch `pair` runs from event `pair` to event `pair + 1`, covered by the intervals
        // entered and not left by event `pair`. Walk forward from the stretch holding the
        // origin until enough crossings lie ahead, then backward if room is left: the same
        // crossings `Roots::push_nearest` would keep from the whole line.
        let Some(last_pair) = events.len().checked_sub(2) else {
            return;
        };
        let origin_pair = events[..=last_pair]
            .iter()
            .zip(&events[1..])
            .position(|(_, next)| next.0 >= 0.0)
            .unwrap_or(last_pair);
        for &event in &events[..origin_pair] {
            apply(covering, event, true);
        }
        let mut ahead = [0.0; MAX_ROOTS];
        let mut ahead_count = 0;
        let mut behind = [0.0; MAX_ROOTS];
        let mut behind_count = 0;
        let mut found = [0.0; MAX_DEGREE];
        let mut pair = origin_pair;
        while pair <= last_pair && ahead_count < MAX_ROOTS {
            apply(covering, events[pair], true);
            let roots_found = self.stretch_crossings(intervals, covering, events, pair, &mut found);
            for &t in &found[..roots_found] {
                if t >= 0.0 && ahead_count < MAX_ROOTS {
                    ahead[ahead_count] = t;
                    ahead_count += 1;
                } else if t < 0.0 && behind_count < MAX_ROOTS {
                    behind[behind_count] = t;
                    behind_count += 1;
                }
            }
            pair += 1;
        }
        // Crossings behind the origin in its own stretch were found ascending: nearest last.
        behind[..behind_count].reverse();
        if ahead_count + behind_count < MAX_ROOTS && origin_pair > 0 {
            // Undo the events after the origin's stretch, so the covering set is its own.
            for &event in events[origin_pair + 1..pair].iter().rev() {
                apply(covering, event, false);
            }
            for pair in (0..origin_pair).rev() {
                if ahead_count + behind_count >= MAX_ROOTS {
                    break;
                }
                apply(covering, events[pair + 1], false);
                let roots_found =
                    self.stretch_crossings(intervals, covering, events, pair, &mut found);
                for &t in found[..roots_found].iter().rev() {
                    if behind_count < MAX_ROOTS {
                        behind[behind_count] = t;
                        behind_count += 1;
                    }
                }
            }
        }
        let kept_behind = behind_count.min(MAX_ROOTS - ahead_count);
        for &t in ahead[..ahead_count].iter().chain(&behind[..kept_behind]) {
            roots.push(t, 0);
        }
    }

    /// The crossings on stretch `pair` of the sorted `events` (from event `pair` to the next,
    /// field summed over the `covering` intervals), ascending; the stretch's far end counts
    /// only on the last stretch, so a crossing at a shared end is reported once.
    fn stretch_crossings(
        &self,
        intervals: &[Active],
        covering: &[usize],
        events: &[Event],
        pair: usize,
        found: &mut [f64; MAX_DEGREE],
    ) -> usize {
        let (at, next) = (events[pair].0, events[pair + 1].0);
        if next <= at {
            return 0;
        }
        // Each stretch sums its covering fields afresh, so no rounding drifts along the ray.
        // The field there is at most the sum of the covering fields' peaks: stretches that
        // cannot reach the threshold are skipped.
        let mut sum = [0.0; 5];
        let mut ceiling = 0.0;
        for &open in covering {
            let interval = &intervals[open];
            for (total, term) in sum.iter_mut().zip(interval.quartic) {
                *total += term;
            }
            ceiling += interval.peak;
        }
        if ceiling < self.threshold * (1.0 - UNREACHABLE_MARGIN) {
            return 0;
        }
        let coefficients = [sum[4], sum[3], sum[2], sum[1], sum[0] - self.threshold];
        let roots_found = real_roots_between(&coefficients, at, next, found);
        let is_last = pair + 2 == events.len();
        let mut kept = 0;
        for index in 0..roots_found {
            if found[index] < next || is_last {
                found[kept] = found[index];
                kept += 1;
            }
        }
        kept
    }

    /// True when the field at `point` exceeds the threshold.
    pub fn inside(&self, point: DVec3) -> bool {
        self.field(point).0 > self.threshold
    }

    /// Outward normal: against the field's gradient.
    pub fn normal(&self, point: DVec3) -> DVec3 {
        -self.field(point).1
    }

    /// Bounds of the components' spheres of influence.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// True when points far from every component count as inside (threshold not positive).
    pub fn inside_everywhere_far(&self) -> bool {
        self.threshold < 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{math::Transform, scene::BlobComponent};

    fn sphere(centre: DVec3, radius: f64, strength: f64) -> BlobComponent {
        BlobComponent {
            kind: BlobKind::Sphere { centre },
            radius,
            strength,
            transform: Transform::IDENTITY,
            texture: None,
        }
    }

    #[test]
    fn single_sphere_blob_is_a_sphere() {
        // strength 2, threshold 0.5: (1 - r²)² = 0.25 at r² = 0.5.
        let blob = Blob::new(&SceneBlob {
            threshold: 0.5,
            components: vec![sphere(DVec3::ZERO, 1.0, 2.0)],
        })
        .unwrap();
        let mut roots = Roots::new();
        blob.intersect(DVec3::new(-5.0, 0.0, 0.0), DVec3::X, &mut roots);
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        let r = 0.5f64.sqrt();
        assert_eq!(found.len(), 2);
        assert!((found[0] - (5.0 - r)).abs() < 1e-9 && (found[1] - (5.0 + r)).abs() < 1e-9);
        let normal = blob.normal(DVec3::new(-r, 0.0, 0.0)).normalize();
        assert!(normal.abs_diff_eq(-DVec3::X, 1e-9));
        assert!(blob.inside(DVec3::ZERO) && !blob.inside(DVec3::new(0.9, 0.0, 0.0)));
    }

    #[test]
    fn many_crossings_keep_the_nearest_ahead_then_the_nearest_behind() {
        // Twelve separate spheres centred at x = -11, -9, ..., 11: 24 crossings on the x axis.
        let components = (0..12)
            .map(|i| sphere(DVec3::new(2.0 * i as f64 - 11.0, 0.0, 0.0), 0.8, 1.0))
            .collect();
        let blob = Blob::new(&SceneBlob {
            threshold: 0.5,
            components,
        })
        .unwrap();
        // (1 - r²/R²)² = 0.5 at the surface.
        let surface = 0.8 * (1.0 - 0.5f64.sqrt()).sqrt();
        let crossings_from = |x: f64| {
            let mut roots = Roots::new();
            blob.intersect(DVec3::new(x, 0.0, 0.0), DVec3::X, &mut roots);
            let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
            found.sort_by(f64::total_cmp);
            found
        };
        let expected = |origin: f64, centres: &[f64]| {
            let mut all: Vec<f64> = centres
                .iter()
                .flat_map(|c| [c - origin - surface, c - origin + surface])
                .collect();
            all.sort_by(f64::total_cmp);
            all
        };
        let close = |found: &[f64], wanted: &[f64]| {
            found.len() == wanted.len()
                && found.iter().zip(wanted).all(|(f, w)| (f - w).abs() < 1e-9)
        };
        // Eight crossings ahead: nothing behind is kept.
        let found = crossings_from(0.0);
        assert!(
            close(&found, &expected(0.0, &[1.0, 3.0, 5.0, 7.0])),
            "{found:?}"
        );
        // Four ahead, so the four nearest behind fill the rest.
        let found = crossings_from(8.0);
        assert!(
            close(&found, &expected(8.0, &[5.0, 7.0, 9.0, 11.0])),
            "{found:?}"
        );
    }

    #[test]
    fn component_textures_blend_by_the_absolute_field_shares() {
        // Components 0 and 2 show material 7, component 1 (negative) material 9.
        let blob = Blob::new(&SceneBlob {
            threshold: 0.5,
            components: vec![
                sphere(DVec3::new(-0.6, 0.0, 0.0), 1.2, 1.0),
                sphere(DVec3::ZERO, 0.8, -0.3),
                sphere(DVec3::new(0.6, 0.0, 0.0), 1.2, 2.0),
            ],
        })
        .unwrap();
        assert!(!blob.is_textured() && blob.texture_blend(DVec3::ZERO).is_none());
        let blob = blob.with_materials(&[7, 9, 7]);
        let point = DVec3::new(0.1, 0.2, -0.5);
        let field = |centre: DVec3, radius: f64, strength: f64| {
            let falloff = 1.0 - (point - centre).length_squared() / (radius * radius);
            strength * falloff.max(0.0).powi(2)
        };
        let positive = field(DVec3::new(-0.6, 0.0, 0.0), 1.2, 1.0)
            + field(DVec3::new(0.6, 0.0, 0.0), 1.2, 2.0);
        let negative = field(DVec3::ZERO, 0.8, -0.3).abs();
        let parts: Vec<(u32, f64)> = blob.texture_blend(point).unwrap().iter().collect();
        assert_eq!(parts.len(), 2);
        let share = |material: u32| parts.iter().find(|p| p.0 == material).unwrap().1;
        assert!((share(7) - positive / (positive + negative)).abs() < 1e-12);
        assert!((share(9) - negative / (positive + negative)).abs() < 1e-12);
        // Far from every component: nothing to blend.
        assert!(blob.texture_blend(DVec3::splat(5.0)).is_none());
    }

    #[test]
    fn a_blend_keeps_its_heaviest_materials() {
        let blend = TextureBlend::weighted((0..10).map(|m| (m, 1.0 + m as f64))).unwrap();
        let parts: Vec<(u32, f64)> = blend.iter().collect();
        assert_eq!(parts.len(), crate::geometry::BLEND_SLOTS);
        assert!(parts.iter().all(|&(m, _)| m >= 4));
        assert!((parts.iter().map(|p| p.1).sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(TextureBlend::weighted([(1, 0.0), (2, f64::NAN)]).is_none());
    }

    #[test]
    fn blob_crossings_agree_with_inside_test() {
        let mut cylinder = sphere(DVec3::ZERO, 0.8, 1.5);
        cylinder.kind = BlobKind::Cylinder {
            end1: DVec3::new(-1.0, 0.0, 0.0),
            end2: DVec3::new(1.0, 0.5, 0.0),
        };
        let mut squashed = sphere(DVec3::new(0.0, 0.8, 0.0), 1.0, 2.0);
        squashed.transform = Transform::scaling(DVec3::new(1.0, 0.5, 1.0)).unwrap();
        let blob = Blob::new(&SceneBlob {
            threshold: 0.6,
            components: vec![
                cylinder,
                squashed,
                sphere(DVec3::new(0.5, 0.0, 0.0), 0.6, -1.0),
            ],
        })
        .unwrap();
        super::super::test_support::assert_crossings_flip_inside(
            3,
            3.0,
            1e-6,
            1e-7,
            |origin, direction, roots| blob.intersect(origin, direction, roots),
            |point| blob.inside(point),
        );
        let empty = SceneBlob {
            threshold: 1.0,
            components: vec![sphere(DVec3::ZERO, 0.0, 1.0)],
        };
        assert!(Blob::new(&empty).is_none());
    }
}
