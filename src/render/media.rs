//! Participating media along ray segments: absorption, emission and light scattered
//! towards the viewer.
//!
//! In: the media active along a stretch of a ray (those of the objects the ray is inside,
//! plus the scene's atmospheric media outside non-hollow objects), the lights and the
//! world for shadow tests. Out: what the stretch lets through of the light behind it and
//! what it adds. Holds: no allocation; sample positions are fixed or hashed from the ray,
//! so results do not depend on thread count. Shadow rays through media: see
//! [`super::extinction`].
//!
//! Rules measured against POV-Ray 3.7 (16-bit renders of boxes of media seen head-on):
//! - each sample gives a light (emission plus scattered light, both times the density)
//!   and an extinction (absorption plus `extinction` times scattering, times the density);
//!   densities multiply, media add.
//! - method 3 (the default; `intervals` changes nothing): with n the smallest `samples`
//!   (default 10), the segment is cut into N = max(2, ⌊n/2⌋ + 1) pieces of weight L/N.
//!   The pieces' samples lie at spacing L/(N + 1) from the segment's start (so they cover
//!   only N/(N + 1) of it). A piece samples its ends and middle and averages the three;
//!   while either end differs from the middle by more than `aa_threshold` in light and
//!   the depth is below `aa_level` (default 3; the piece is depth 1), it is split in two
//!   halves treated alike and averaged. Piece k adds its light times L/N, dimmed by
//!   `exp(−od)` of the pieces before it only; its extinction times L/N adds to od. The
//!   stretch lets `exp(−od)` through. Exact for constant emission and absorption at
//!   samples 1 to 32, and for step-shaped densities at samples 1, 4 and 10.
//! - methods 1 and 2 (from the manual): `intervals` equal intervals, each sampled `samples`
//!   min times at the middles of equal pieces (method 2 moved by `jitter`, method 1 at a
//!   random place in each piece), then at random places until the confidence test passes
//!   (see [`ConfidenceTest`]) or max samples are taken; the samples, in order along the
//!   ray, share the interval equally, each dimmed by the extinction up to itself (half its
//!   own share). Exact for constant media (measured with samples 2); method 1's random
//!   numbers are POV-Ray's own, so only averages match. `ratio` has no effect.
//! - the first media listed (the first of the container entered first, then the
//!   atmosphere's) sets the method and sampling of all media along a stretch (measured).
//! - a ray that hits nothing crosses atmospheric media over 2·10¹⁰ units.
//! - scattering: for each light with `media_interaction` on that is not `shadowless` (such
//!   lights light no media, measured), its light at the sample (after fading, spotlight
//!   cone and shadows; with `media_attenuation` also dimmed by the atmospheric media on the
//!   way) times the phase function of c = cos(angle between the ray and the direction to
//!   the light): isotropic 1; Mie haze 0.5767 (1 + 9 ((1 + c)/2)⁸); Mie murky
//!   0.4957 (1 + 50 ((1 + c)/2)³²); Rayleigh 0.7994 (1 + c²); Henyey-Greenstein
//!   (1 − g²) / (1 + g² − 2 g c)^1.5. Where several containers' media act at once
//!   (overlapping containers, several media in one interior), all their scattering there
//!   takes the mean of their phase functions, a media without scattering counting as
//!   isotropic; the atmospheric media do the same among themselves (measured, see
//!   [`mean_phase`]).

use super::antialias::mix64;
use super::extinction::{density_at, exp_neg, DEFAULT_MEDIA, MAX_INTERVAL_SAMPLES};
use super::lights::{incoming, SceneLight};
use super::photons::PhotonMap;
use super::shadows::light_filter;
use crate::geometry::World;
use crate::scene::{LightGroup, Media, ScatteringKind};
use glam::DVec3;

/// How far a ray that hits nothing runs through atmospheric media (measured).
pub const UNBOUNDED_MEDIA_LENGTH: f64 = 2e10;

/// At most this many media blocks act together along one stretch of a ray.
pub const MAX_ACTIVE_MEDIA: usize = 16;

/// Distinct (light group, atmospheric or not) pairs lit separately at one media sample.
const SCATTERING_CLASSES: usize = 8;

/// The media acting along one stretch of a ray, each with the light group of the object
/// holding it (which lights light it; `None` for atmospheric media and objects outside
/// every group). No allocation: a fixed array.
#[derive(Clone, Copy)]
pub struct ActiveMedia<'a> {
    items: [Option<(&'a Media, Option<LightGroup>)>; MAX_ACTIVE_MEDIA],
    len: usize,
    /// Where the atmospheric media start among the items (the rest are containers').
    atmospheric_from: usize,
}

impl<'a> ActiveMedia<'a> {
    /// No media.
    pub const NONE: ActiveMedia<'static> = ActiveMedia {
        items: [None; MAX_ACTIVE_MEDIA],
        len: 0,
        atmospheric_from: MAX_ACTIVE_MEDIA,
    };

    /// Adds `media`, lit by the lights of `group` (beyond [`MAX_ACTIVE_MEDIA`] the rest
    /// are left out).
    pub fn extend(&mut self, media: &'a [Media], group: Option<LightGroup>) {
        for item in media {
            if self.len < MAX_ACTIVE_MEDIA {
                self.items[self.len] = Some((item, group));
                self.len += 1;
            }
        }
    }

    /// Adds the scene's atmospheric `media` after the containers' (beyond
    /// [`MAX_ACTIVE_MEDIA`] the rest are left out).
    pub fn extend_atmosphere(&mut self, media: &'a [Media]) {
        self.atmospheric_from = self.atmospheric_from.min(self.len);
        self.extend(media, None);
    }

    /// The media whose sampling settings rule the stretch: the first listed (measured:
    /// the first media of the container entered first, before the atmosphere).
    fn ruling(&self) -> &'a Media {
        self.iter().next().unwrap_or(&DEFAULT_MEDIA)
    }

    /// True when no media act.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The media without their light groups.
    fn iter(&self) -> impl Iterator<Item = &'a Media> + '_ {
        self.grouped().map(|(media, _)| media)
    }

    /// The media with their light groups.
    fn grouped(&self) -> impl Iterator<Item = (&'a Media, Option<LightGroup>)> + '_ {
        self.items[..self.len].iter().flatten().copied()
    }
}

/// What one point of media does to a ray.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Sample {
    /// Light sent towards the viewer per unit length (emission plus scattering).
    light: DVec3,
    /// Light taken out per unit length.
    extinction: DVec3,
}

impl Sample {
    fn add(self, other: Sample) -> Sample {
        Sample {
            light: self.light + other.light,
            extinction: self.extinction + other.extinction,
        }
    }

    fn scaled(self, factor: f64) -> Sample {
        Sample {
            light: self.light * factor,
            extinction: self.extinction * factor,
        }
    }
}

/// Integrates media along rays.
pub struct MediaShader<'a> {
    world: &'a World,
    lights: &'a [SceneLight],
    /// Media photons lighting the media, when the scene deposits them.
    photons: Option<&'a PhotonMap>,
}

/// A stretch of a ray: `origin + t · direction` for t in `start..end`.
#[derive(Clone, Copy, Debug)]
pub struct Stretch {
    /// Where the ray starts.
    pub origin: DVec3,
    /// Unit direction.
    pub direction: DVec3,
    /// Distance at which the stretch begins.
    pub start: f64,
    /// Distance at which it ends (infinite for rays that hit nothing).
    pub end: f64,
}

impl<'a> MediaShader<'a> {
    /// A shader lighting media with `lights`, shadowed by `world`.
    pub fn new(world: &'a World, lights: &'a [SceneLight]) -> Self {
        MediaShader {
            world,
            lights,
            photons: None,
        }
    }

    /// The same shader, also lighting scattering media with the media photons of `photons`.
    pub fn with_photons(self, photons: Option<&'a PhotonMap>) -> Self {
        MediaShader {
            photons: photons.filter(|map| map.has_media_photons()),
            ..self
        }
    }

    /// What `active` media along `stretch` do: the light behind is multiplied by the first
    /// value and the second is added.
    pub fn along(&self, active: &ActiveMedia, stretch: Stretch) -> (DVec3, DVec3) {
        let end = if stretch.end == f64::INFINITY {
            stretch.start + UNBOUNDED_MEDIA_LENGTH
        } else {
            stretch.end
        };
        let length = end - stretch.start;
        if active.is_empty() || !(length > 0.0 && length.is_finite()) {
            return (DVec3::ONE, DVec3::ZERO);
        }
        let method = active.ruling().method;
        if method != 3 {
            return self.intervals(active, stretch, length, method == 1);
        }
        // Method 3 samples each stretch between the edges of spotlight and cylinder beams
        // on its own, so that narrow beams are not missed.
        let mut edges = [0.0; MAX_BEAM_EDGES];
        let count = self.beam_edges(
            stretch.origin,
            stretch.direction,
            stretch.start,
            end,
            &mut edges,
        );
        let edges = &mut edges[..count];
        edges.sort_unstable_by(f64::total_cmp);
        let mut keep = DVec3::ONE;
        let mut added = DVec3::ZERO;
        let mut from = stretch.start;
        for &to in edges.iter().chain(std::iter::once(&end)) {
            if to > from {
                let part = Stretch {
                    start: from,
                    end: to,
                    ..stretch
                };
                let (part_keep, part_added) = self.adaptive(active, part, to - from);
                added += keep * part_added;
                keep *= part_keep;
                from = to;
            }
        }
        (keep, added)
    }

    /// Writes into `edges` the distances in `start..end` where the ray crosses the edge of a
    /// spotlight cone or cylinder beam (of lights that light media); returns how many.
    fn beam_edges(
        &self,
        origin: DVec3,
        direction: DVec3,
        start: f64,
        end: f64,
        edges: &mut [f64; MAX_BEAM_EDGES],
    ) -> usize {
        let mut count = 0;
        for light in self.lights {
            if !light.source.media_interaction {
                continue;
            }
            let Some(spot) = &light.source.spotlight else {
                continue;
            };
            let Some(axis) = (spot.point_at - light.source.position).try_normalize() else {
                continue;
            };
            let apex = light.source.position;
            let offset = origin - apex;
            let roots = if spot.cylinder {
                let radius = spot.falloff.max(spot.radius);
                let across_offset = offset - offset.dot(axis) * axis;
                let across_direction = direction - direction.dot(axis) * axis;
                quadratic_roots(
                    across_direction.length_squared(),
                    2.0 * across_offset.dot(across_direction),
                    across_offset.length_squared() - radius * radius,
                )
            } else {
                let cos_edge = spot.falloff.max(spot.radius).to_radians().cos();
                let cos2 = cos_edge * cos_edge;
                let (d_axis, w_axis) = (direction.dot(axis), offset.dot(axis));
                quadratic_roots(
                    d_axis * d_axis - cos2,
                    2.0 * (d_axis * w_axis - cos2 * direction.dot(offset)),
                    w_axis * w_axis - cos2 * offset.length_squared(),
                )
            };
            for t in roots.into_iter().flatten() {
                // Only the forward nappe of a cone is lit.
                let in_front = spot.cylinder || (offset + direction * t).dot(axis) >= 0.0;
                if in_front && t > start && t < end && count < MAX_BEAM_EDGES {
                    edges[count] = t;
                    count += 1;
                }
            }
        }
        count
    }

    /// Method 3 (see the module rules).
    fn adaptive(&self, active: &ActiveMedia, stretch: Stretch, length: f64) -> (DVec3, DVec3) {
        let ruling = active.ruling();
        let (samples, level, threshold, jitter) = (
            ruling.samples.0,
            ruling.aa_level,
            ruling.aa_threshold,
            ruling.jitter,
        );
        let pieces = (samples / 2 + 1).max(2);
        let spacing = length / f64::from(pieces + 1);
        let weight = length / f64::from(pieces);
        let seed = ray_seed(stretch);
        let refine = Refinement {
            active,
            stretch,
            level,
            threshold,
            jitter: jitter * spacing,
            seed,
        };
        let mut depth = DVec3::ZERO;
        let mut added = DVec3::ZERO;
        let mut at = stretch.start;
        let mut at_sample = self.sample(active, stretch, at);
        for piece in 0..pieces {
            let next = refine.jittered(stretch.start + f64::from(piece + 1) * spacing, piece);
            let next_sample = self.sample(active, stretch, next);
            let average = self.piece(&refine, at, next, at_sample, next_sample, 1);
            added += exp_neg(depth) * average.light * weight;
            depth += average.extinction * weight;
            at = next;
            at_sample = next_sample;
        }
        (exp_neg(depth), added)
    }

    /// The average sample over `a..b` whose end samples are given, subdividing while they
    /// differ from the middle (method 3).
    fn piece(
        &self,
        refine: &Refinement,
        a: f64,
        b: f64,
        at_a: Sample,
        at_b: Sample,
        depth: u32,
    ) -> Sample {
        let middle = 0.5 * (a + b);
        let at_middle = self.sample(refine.active, refine.stretch, middle);
        let differs =
            |x: &Sample, y: &Sample| (x.light - y.light).abs().max_element() > refine.threshold;
        if depth < refine.level && (differs(&at_a, &at_middle) || differs(&at_middle, &at_b)) {
            let left = self.piece(refine, a, middle, at_a, at_middle, depth + 1);
            let right = self.piece(refine, middle, b, at_middle, at_b, depth + 1);
            return left.add(right).scaled(0.5);
        }
        at_a.add(at_middle).add(at_b).scaled(1.0 / 3.0)
    }

    /// Methods 1 and 2 (see the module rules): `intervals` equal intervals, each sampled
    /// `samples` min times (method 2 evenly, moved by `jitter`; method 1 at random), then
    /// at random until the confidence test passes or max samples are taken.
    fn intervals(
        &self,
        active: &ActiveMedia,
        stretch: Stretch,
        length: f64,
        random: bool,
    ) -> (DVec3, DVec3) {
        let ruling = active.ruling();
        let intervals = ruling.intervals.max(1);
        let minimum = ruling.samples.0.clamp(1, MAX_INTERVAL_SAMPLES as u32);
        let maximum = ruling.samples.1.clamp(minimum, MAX_INTERVAL_SAMPLES as u32);
        let jitter = if random { 1.0 } else { ruling.jitter };
        let test = ConfidenceTest::new(ruling.confidence, ruling.variance);
        let width = length / f64::from(intervals);
        let seed = ray_seed(stretch);
        let mut taken = [(0.0, Sample::default()); MAX_INTERVAL_SAMPLES];
        let mut depth = DVec3::ZERO;
        let mut added = DVec3::ZERO;
        for interval in 0..intervals {
            let from = stretch.start + f64::from(interval) * width;
            let interval_seed = mix64(seed ^ u64::from(interval));
            let mut spread = Spread::default();
            let mut count = 0;
            while count < maximum as usize {
                let index = count as u64;
                let at = if count < minimum as usize {
                    let offset = (unit_random(interval_seed, index) - 0.5) * jitter;
                    from + (count as f64 + 0.5 + offset) * width / f64::from(minimum)
                } else {
                    from + unit_random(interval_seed, index) * width
                };
                let sample = self.sample(active, stretch, at);
                spread.add(sample.light);
                taken[count] = (at, sample);
                count += 1;
                if count >= minimum as usize && test.passes(&spread) {
                    break;
                }
            }
            let taken = &mut taken[..count];
            taken.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
            let step = width / count as f64;
            for (_, sample) in taken.iter() {
                let half = sample.extinction * (0.5 * step);
                added += exp_neg(depth + half) * sample.light * step;
                depth += sample.extinction * step;
            }
        }
        (exp_neg(depth), added)
    }

    /// The media's light and extinction at distance `t` along the stretch's ray.
    fn sample(&self, active: &ActiveMedia, stretch: Stretch, t: f64) -> Sample {
        let point = stretch.origin + stretch.direction * t;
        let mut total = Sample::default();
        // Scattering summed per light group (the lights lighting it) and kind of media
        // (containers' or atmospheric); the phase functions of each kind's media, for
        // their mean (see [`mean_phase`]).
        let mut class_total = [DVec3::ZERO; SCATTERING_CLASSES];
        let mut classes: [(Option<LightGroup>, bool); SCATTERING_CLASSES] =
            [(None, false); SCATTERING_CLASSES];
        let mut class_count = 0;
        let mut kinds = [[ScatteringKind::Isotropic; MAX_ACTIVE_MEDIA]; 2];
        let mut kind_counts = [0; 2];
        let mut all_scattering = DVec3::ZERO;
        for (index, (media, group)) in active.grouped().enumerate() {
            let atmospheric = index >= active.atmospheric_from;
            let side = usize::from(atmospheric);
            if kind_counts[side] < MAX_ACTIVE_MEDIA {
                kinds[side][kind_counts[side]] = media
                    .scattering
                    .as_ref()
                    .map_or(ScatteringKind::Isotropic, |s| s.kind);
                kind_counts[side] += 1;
            }
            let density = density_at(media, point);
            if density == DVec3::ZERO {
                continue;
            }
            total.light += media.emission * density;
            total.extinction += media.absorption * density;
            if let Some(scattering) = &media.scattering {
                let amount = scattering.colour * density;
                total.extinction += amount * scattering.extinction;
                all_scattering += amount;
                let class = (group, atmospheric);
                match classes[..class_count]
                    .iter()
                    .position(|known| *known == class)
                {
                    Some(at) => class_total[at] += amount,
                    None if class_count < SCATTERING_CLASSES => {
                        classes[class_count] = class;
                        class_total[class_count] = amount;
                        class_count += 1;
                    }
                    None => {}
                }
            }
        }
        for ((group, atmospheric), amount) in classes[..class_count].iter().zip(&class_total) {
            if *amount != DVec3::ZERO {
                let side = usize::from(*atmospheric);
                let kinds = &kinds[side][..kind_counts[side]];
                total.light += *amount * self.scattered(kinds, *group, point, stretch.direction);
            }
        }
        if let Some(photons) = self.photons {
            if all_scattering != DVec3::ZERO {
                // The containers' phase functions (the atmosphere's where there are none).
                let side = usize::from(kind_counts[0] == 0);
                let kinds = &kinds[side][..kind_counts[side]];
                total.light +=
                    all_scattering * media_photon_light(photons, kinds, point, stretch.direction);
            }
        }
        total
    }

    /// Light from every interacting light source of media in light group `group` scattered
    /// at `point` towards the viewer looking along `direction`, per unit of scattering,
    /// with the mean phase function of `kinds` (the phase functions of all media there).
    /// Light groups rule media as they rule surfaces (measured: a group's light lights the
    /// media inside the group's objects only, the scene's lights reach them only with
    /// `global_lights on`).
    fn scattered(
        &self,
        kinds: &[ScatteringKind],
        group: Option<LightGroup>,
        point: DVec3,
        direction: DVec3,
    ) -> DVec3 {
        let mut total = DVec3::ZERO;
        for light in self.lights {
            // Measured: a `shadowless` light lights no media (scattering media in a box or
            // in the atmosphere stay black under it, while it lights surfaces).
            if !light.source.media_interaction
                || light.source.shadowless
                || !LightGroup::lights(light.source.group, group)
            {
                continue;
            }
            let Some(arriving) = incoming(&light.source, point) else {
                continue;
            };
            let mut colour = arriving.colour;
            if arriving.can_be_shadowed {
                colour *= light_filter(light, self.world, point, &arriving, None);
            }
            if colour == DVec3::ZERO {
                continue;
            }
            total += colour * mean_phase(kinds, direction.dot(arriving.direction));
        }
        total
    }
}

/// The light the media photons around `point` send towards a viewer looking along
/// `direction`, per unit of scattering: each photon's power times the (mean) phase
/// function for the direction it came from, over the volume of the sphere gathered.
fn media_photon_light(
    photons: &PhotonMap,
    kinds: &[ScatteringKind],
    point: DVec3,
    direction: DVec3,
) -> DVec3 {
    let mut sum = DVec3::ZERO;
    let volume = photons.media_photons(point, &mut |travel, power| {
        sum += power * mean_phase(kinds, -direction.dot(travel));
    });
    if volume > 0.0 {
        sum / volume
    } else {
        DVec3::ZERO
    }
}

/// The phase function applied to all the scattering of the containers' media at a point:
/// the mean of the phase functions of every container's media acting there, a media
/// without scattering (or of zero density there) counting as isotropic; likewise for the
/// atmospheric media among themselves. Measured in POV-Ray 3.7 with overlapping boxes and
/// with two media in one interior: Mie haze and isotropic scattering together scatter both
/// with (5.664 + 1) / 2 towards a light ahead, also where the isotropic media's density is
/// 0; an emitting media beside a Mie haze halves the haze's forward peak likewise; an
/// isotropic atmosphere does not change a box's Mie haze, two atmospheric media mix.
fn mean_phase(kinds: &[ScatteringKind], c: f64) -> f64 {
    match kinds {
        [] => 1.0,
        [kind] => phase(*kind, c),
        [first, rest @ ..] if rest.iter().all(|kind| kind == first) => phase(*first, c),
        _ => kinds.iter().map(|kind| phase(*kind, c)).sum::<f64>() / kinds.len() as f64,
    }
}

/// At most this many beam edges split one stretch for method 3.
const MAX_BEAM_EDGES: usize = 256;

/// The real roots of `a t² + b t + c` (none for a degenerate or negative discriminant).
fn quadratic_roots(a: f64, b: f64, c: f64) -> [Option<f64>; 2] {
    let discriminant = b * b - 4.0 * a * c;
    if a.abs() < 1e-12 || discriminant.is_nan() || discriminant < 0.0 {
        return [None, None];
    }
    let root = discriminant.sqrt();
    [Some((-b - root) / (2.0 * a)), Some((-b + root) / (2.0 * a))]
}

/// Running mean and variance of sample lights (Welford's method), per channel.
#[derive(Default)]
struct Spread {
    count: f64,
    mean: DVec3,
    squares: DVec3,
}

impl Spread {
    fn add(&mut self, value: DVec3) {
        self.count += 1.0;
        let delta = value - self.mean;
        self.mean += delta / self.count;
        self.squares += delta * (value - self.mean);
    }
}

/// The test that ends an interval's sampling (methods 1 and 2): with probability
/// `confidence`, the variance of the samples' light is at most `variance`. The upper
/// confidence bound of the variance is (n − 1) s² / χ²(1 − confidence; n − 1), χ² by the
/// Wilson–Hilferty approximation.
struct ConfidenceTest {
    /// The standard normal quantile of 1 − confidence.
    lower_quantile: f64,
    variance: f64,
}

impl ConfidenceTest {
    fn new(confidence: f64, variance: f64) -> Self {
        let confidence = if confidence.is_finite() {
            confidence.clamp(0.0, 0.9999)
        } else {
            0.9
        };
        ConfidenceTest {
            lower_quantile: normal_quantile(1.0 - confidence),
            variance: if variance.is_finite() {
                variance.max(0.0)
            } else {
                1.0 / 128.0
            },
        }
    }

    /// True when the samples so far are close enough (never with fewer than two).
    fn passes(&self, spread: &Spread) -> bool {
        if spread.count < 2.0 {
            return false;
        }
        let freedom = spread.count - 1.0;
        let term = 2.0 / (9.0 * freedom);
        let chi_squared = freedom * (1.0 - term + self.lower_quantile * term.sqrt()).powi(3);
        if chi_squared <= 0.0 {
            return false;
        }
        spread.squares.max_element() / chi_squared <= self.variance
    }
}

/// The quantile of the standard normal distribution at probability `p` in (0, 1)
/// (Acklam's rational approximation, relative error below 1.2·10⁻⁹).
fn normal_quantile(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969683028665376e1,
        2.209460984245205e2,
        -2.759285104469687e2,
        1.38357751867269e2,
        -3.066479806614716e1,
        2.506628277459239,
    ];
    const B: [f64; 5] = [
        -5.447609879822406e1,
        1.615858368580409e2,
        -1.556989798598866e2,
        6.680131188771972e1,
        -1.328068155288572e1,
    ];
    const C: [f64; 6] = [
        -7.784894002430293e-3,
        -3.223964580411365e-1,
        -2.400758277161838,
        -2.549732539343734,
        4.374664141464968,
        2.938163982698783,
    ];
    const D: [f64; 4] = [
        7.784695709041462e-3,
        3.224671290700398e-1,
        2.445134137142996,
        3.754408661907416,
    ];
    let p = p.clamp(1e-12, 1.0 - 1e-12);
    let tail = |q: f64| {
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    };
    if p < 0.02425 {
        tail((-2.0 * p.ln()).sqrt())
    } else if p > 1.0 - 0.02425 {
        -tail((-2.0 * (1.0 - p).ln()).sqrt())
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

/// What method 3's subdivision needs to know.
struct Refinement<'r, 'a> {
    active: &'r ActiveMedia<'a>,
    stretch: Stretch,
    level: u32,
    threshold: f64,
    /// Largest offset of a piece boundary (`jitter` times the spacing).
    jitter: f64,
    seed: u64,
}

impl Refinement<'_, '_> {
    /// The end of piece `index` at `t`, moved by the hashed jitter.
    fn jittered(&self, t: f64, index: u32) -> f64 {
        if self.jitter > 0.0 {
            t + (unit_random(self.seed, u64::from(index)) - 0.5) * self.jitter
        } else {
            t
        }
    }
}

/// The phase function for the cosine `c` between the ray and the direction to the light.
fn phase(kind: ScatteringKind, c: f64) -> f64 {
    let forward = 0.5 * (1.0 + c);
    match kind {
        ScatteringKind::Isotropic => 1.0,
        ScatteringKind::MieHazy => 0.5767 * (1.0 + 9.0 * forward.powi(8)),
        ScatteringKind::MieMurky => 0.4957 * (1.0 + 50.0 * forward.powi(32)),
        ScatteringKind::Rayleigh => 0.7994 * (1.0 + c * c),
        ScatteringKind::HenyeyGreenstein(g) => {
            let denominator = (1.0 + g * g - 2.0 * g * c).max(1e-12);
            (1.0 - g * g) / denominator.powf(1.5)
        }
    }
}

/// A hash of the stretch's ray, for jitter.
fn ray_seed(stretch: Stretch) -> u64 {
    let mut seed = 0u64;
    for value in [
        stretch.origin.x,
        stretch.origin.y,
        stretch.origin.z,
        stretch.direction.x,
        stretch.direction.y,
        stretch.direction.z,
    ] {
        seed = mix64(seed ^ value.to_bits());
    }
    seed
}

/// A number in 0..1 from `seed` and `index`.
fn unit_random(seed: u64, index: u64) -> f64 {
    (mix64(seed ^ mix64(index)) >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shader_free_along(media: &[Media], length: f64) -> (DVec3, DVec3) {
        let world = World::build_from_objects(Vec::new());
        let shader = MediaShader::new(&world, &[]);
        let mut active = ActiveMedia::NONE;
        active.extend(media, None);
        shader.along(
            &active,
            Stretch {
                origin: DVec3::ZERO,
                direction: DVec3::Z,
                start: 0.0,
                end: length,
            },
        )
    }

    #[test]
    fn constant_emission_and_absorption_match_povray() {
        // POV-Ray 3.7: emission 0.25, absorption 0.5 over 2 units on black: 0.34313
        // (default samples), 0.40163 (samples 1), 0.32544 (samples 32).
        let mut media = Media {
            emission: DVec3::splat(0.25),
            absorption: DVec3::splat(0.5),
            samples: (10, 10),
            ..Media::default()
        };
        let (keep, add) = shader_free_along(std::slice::from_ref(&media), 2.0);
        assert!((keep.x - (-1f64).exp()).abs() < 1e-12);
        assert!((add.x - 0.34313).abs() < 1e-5);
        media.samples = (1, 1);
        let (_, add) = shader_free_along(std::slice::from_ref(&media), 2.0);
        assert!((add.x - 0.40163).abs() < 1e-5);
        media.samples = (32, 32);
        let (_, add) = shader_free_along(std::slice::from_ref(&media), 2.0);
        assert!((add.x - 0.32544).abs() < 1e-5);
        // Method 2, samples 2: 0.31279.
        media.method = 2;
        media.samples = (2, 2);
        let (_, add) = shader_free_along(std::slice::from_ref(&media), 2.0);
        assert!((add.x - 0.31279).abs() < 1e-5);
    }

    #[test]
    fn normal_quantiles_and_the_confidence_test() {
        assert!((normal_quantile(0.1) + 1.281_551_565_5).abs() < 1e-8);
        assert!((normal_quantile(0.5)).abs() < 1e-12);
        assert!((normal_quantile(0.99) - 2.326_347_874).abs() < 1e-8);
        let test = ConfidenceTest::new(0.9, 1.0 / 128.0);
        let mut steady = Spread::default();
        let mut noisy = Spread::default();
        for index in 0..10 {
            steady.add(DVec3::splat(0.5));
            noisy.add(DVec3::splat(if index % 2 == 0 { 0.0 } else { 1.0 }));
        }
        assert!(test.passes(&steady));
        assert!(!test.passes(&noisy));
    }

    #[test]
    fn adaptive_methods_are_exact_on_constant_media() {
        // Constant media pass the confidence test at the minimum count, so methods 1 and 2
        // with samples 2, 50 give what samples 2 give.
        for method in [1, 2] {
            let media = Media {
                method,
                emission: DVec3::splat(0.25),
                absorption: DVec3::splat(0.5),
                samples: (2, 50),
                ..Media::default()
            };
            let (keep, add) = shader_free_along(std::slice::from_ref(&media), 2.0);
            assert!((keep.x - (-1f64).exp()).abs() < 1e-12);
            assert!((add.x - 0.31279).abs() < 1e-5, "method {method}: {}", add.x);
        }
    }

    #[test]
    fn mixed_media_share_the_mean_phase_function() {
        // POV-Ray 3.7: Mie haze beside isotropic scattering, looking into the light,
        // scatters with (5.664 + 1) / 2; alike media keep their own phase function.
        let c = 0.995;
        let haze = phase(ScatteringKind::MieHazy, c);
        let mixed = mean_phase(&[ScatteringKind::MieHazy, ScatteringKind::Isotropic], c);
        assert!((mixed - (haze + 1.0) / 2.0).abs() < 1e-12);
        assert!((mean_phase(&[ScatteringKind::MieHazy; 3], c) - haze).abs() < 1e-12);
        assert_eq!(mean_phase(&[], c), 1.0);
    }

    #[test]
    fn henyey_greenstein_reduces_to_isotropic() {
        for c in [-1.0, -0.3, 0.0, 0.7, 1.0] {
            assert!((phase(ScatteringKind::HenyeyGreenstein(0.0), c) - 1.0).abs() < 1e-12);
        }
        // POV-Ray: eccentricity 0.5 straight towards the light gives 6.
        assert!((phase(ScatteringKind::HenyeyGreenstein(0.5), 1.0) - 6.0).abs() < 1e-12);
    }

    #[test]
    fn empty_or_degenerate_stretches_change_nothing() {
        let media = [Media {
            emission: DVec3::ONE,
            ..Media::default()
        }];
        assert_eq!(shader_free_along(&media, 0.0), (DVec3::ONE, DVec3::ZERO));
        assert_eq!(
            shader_free_along(&media, f64::NAN),
            (DVec3::ONE, DVec3::ZERO)
        );
        assert_eq!(shader_free_along(&[], 3.0), (DVec3::ONE, DVec3::ZERO));
    }
}
