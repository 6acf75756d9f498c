//! Radiosity: indirect diffuse light gathered over the hemisphere and cached.
//!
//! In: the scene's [`RadiositySettings`], the eye position, and a way to trace a gathering
//! ray (given by the tracer). Out: the irradiance at a surface point, which the tracer
//! multiplies by pigment, `diffuse` and `brightness` in place of the ambient term.
//! Holds: deterministic results at any thread count — the pretrace fills the cache in a
//! fixed pixel order, each sample's rays traced in parallel a fixed batch at a time, a
//! deeper sample's rays inside such a ray batched in turn (each ray sees the caches as its
//! batch began plus its own deeper samples, which are kept in ray order after the batch);
//! the final render ([`map_rows_storing`]) runs in blocks of rows, each row traced by one
//! thread that sees the cache as it was when the block began plus the samples the row
//! itself gathered, and the rows' new samples join the cache in row order between blocks.
//! Allocation per ray only when a sample is stored (lookups reuse a per-thread buffer).
//!
//! Method (Ward's irradiance cache, as POV-Ray 3.7's manual describes it):
//! - a sample gathers `count` rays over the hemisphere around the normal (halved for each
//!   deeper bounce, as POV-Ray's statistics show), drawn from a fixed cosine-weighted
//!   spherical Fibonacci set of as many directions (or round robin from the larger
//!   `direction_pool`), and stores the mean of the light they see, with the distance of the
//!   nearest surface they hit (first bounce) or the harmonic mean distance of their hits
//!   (deeper bounces);
//! - its reuse radius is `error_bound` times that distance clamped between `minimum_reuse`
//!   and `maximum_reuse` times the sample's distance from the eye (the clamp applies to the
//!   distance, before `error_bound` scales it, as POV-Ray's radiosity files and sample counts
//!   show); a deeper bounce's sample measures that distance along the path the light takes
//!   to the eye (the first hit's distance from the eye plus the gathering rays' lengths),
//!   which probe scenes show POV-Ray doing: its deeper counts do not change with the
//!   camera's distance;
//! - a point reuses the samples whose error `distance / radius + sqrt(1 − N·Nᵢ) / bound` is
//!   below 1 (Ward's test: both terms measured against the error bound) and that do not lie
//!   in front of it, weighted by `1 − error`; the pretrace gathers a new sample wherever
//!   fewer than `nearest_count` are found, with the first bounce's reuse radii lowered by
//!   `low_error_factor` (deeper bounces keep theirs);
//! - each bounce (up to `recursion_limit`) has its own cache, whose samples a spatial index
//!   ([`SampleIndex`]) finds by position; the usable ones are summed in the order they were
//!   stored, so results do not depend on the index's layout.

use super::radiosity_index::SampleIndex;
use crate::accel::counters::{self, Counter};
use crate::scene::RadiositySettings;
use glam::{DVec3, DVec4};
use rayon::prelude::*;
use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::{Arc, RwLock};

/// The golden ratio's fractional part, spacing the Fibonacci set's azimuths.
const GOLDEN_FRACTION: f64 = 0.618_033_988_749_894_9;

/// Weights of red, green and blue in POV-Ray's grey value of a colour.
const GREY_WEIGHTS: DVec3 = DVec3::new(0.297, 0.589, 0.114);

/// One cached irradiance value.
#[derive(Clone, Copy, Debug)]
struct Sample {
    point: DVec3,
    normal: DVec3,
    irradiance: DVec3,
    /// How far the sample may be reused on a flat surface.
    radius: f64,
}

/// The samples of one bounce and the index finding them.
#[derive(Clone, Default)]
struct Cache {
    /// Samples in the order they were gathered (their ids in the index).
    samples: Vec<Sample>,
    index: SampleIndex,
}

/// Working lists of a cache lookup, kept between lookups so they allocate only while growing.
struct LookupBuffers {
    /// Ids of the samples the index finds near the point.
    nearby: Vec<u32>,
    /// Ids of the usable ones, with their weights.
    usable: Vec<(u32, f64)>,
}

impl Cache {
    /// Adds `sample`, to be found by lookups whose radius scale is at most `reach_scale`.
    fn push(&mut self, sample: Sample, reach_scale: f64) {
        // Ids are u32 to keep the index small; a cache cannot grow that large.
        if let Ok(id) = u32::try_from(self.samples.len()) {
            self.index
                .insert(id, sample.point, sample.radius * reach_scale.max(1.0));
            self.samples.push(sample);
        }
    }
}

/// Rows of the final render whose new samples join the cache together; the rows of a block
/// are traced in parallel.
const ROWS_PER_BLOCK: usize = 8;

thread_local! {
    /// The samples this thread's work sees besides the shared caches, and where the samples
    /// it gathers go (see [`PrivateSamples`]).
    static PRIVATE: RefCell<PrivateSamples> = const {
        RefCell::new(PrivateSamples { frozen: Vec::new(), own: None })
    };

    /// Where this thread's gathers in progress stand, one entry per bounce (outermost
    /// first): the gathering point and its distance from the eye along the light's path.
    static GATHER_PATH: RefCell<Vec<(DVec3, f64)>> = const { RefCell::new(Vec::new()) };

    /// Where in the direction pool this thread's next pretrace sample starts, while it
    /// traces one ray of a batch ([`Radiosity::gather_in_batches`]); `None` elsewhere (the
    /// shared counter is used).
    static DIRECTION_CURSOR: std::cell::Cell<Option<u32>> = const { std::cell::Cell::new(None) };

    /// The lookup buffers of this thread.
    static LOOKUP_BUFFERS: RefCell<LookupBuffers> = const {
        RefCell::new(LookupBuffers {
            nearby: Vec::new(),
            usable: Vec::new(),
        })
    };
}

/// Samples not yet in the shared caches, as one unit of parallel work sees them: the
/// final render's row being traced, or one ray of a pretrace batch (whose gather may itself
/// run batches: each level's samples stay its own until its batch ends).
#[derive(Default)]
struct PrivateSamples {
    /// Samples of the units this one runs inside, outermost first: read-only while it runs.
    frozen: Vec<Arc<Vec<Cache>>>,
    /// The samples this unit gathered so far, one cache per bounce (grown on demand);
    /// `None` outside any unit (the pretrace's top level stores in the shared caches).
    own: Option<Vec<Cache>>,
}

/// The light seen along one gathering ray and how far away it came from.
#[derive(Clone, Copy, Debug)]
pub struct Gathered {
    /// Light arriving along the ray.
    pub colour: DVec3,
    /// Distance to the surface hit (infinite when the ray escaped).
    pub distance: f64,
}

/// The radiosity state of one render: settings, direction set and caches.
pub struct Radiosity {
    settings: RadiositySettings,
    /// Cosine-weighted unit directions around +z, one set per bounce (deeper bounces
    /// shoot fewer rays).
    directions: Vec<Vec<DVec3>>,
    /// One cache per bounce.
    caches: Vec<RwLock<Cache>>,
    /// The pretrace is running: new samples are stored.
    filling: AtomicBool,
    /// Where in the direction pool the next sample starts (advanced only while filling).
    next_direction: AtomicU32,
    eye: DVec3,
}

impl Radiosity {
    /// The radiosity state for these settings, seen from `eye`.
    pub fn new(settings: &RadiositySettings, eye: DVec3) -> Radiosity {
        let levels = settings.recursion_limit.clamp(1, 20) as usize;
        let directions = (0..levels)
            .map(|depth| direction_set(settings, rays_at_depth(settings.count, depth)))
            .collect();
        Radiosity {
            settings: settings.clone(),
            directions,
            caches: (0..levels).map(|_| RwLock::default()).collect(),
            filling: AtomicBool::new(false),
            next_direction: AtomicU32::new(0),
            eye,
        }
    }

    /// Whether a surface reached at this bounce depth gets indirect light.
    pub fn lights_depth(&self, depth: u32) -> bool {
        (depth as usize) < self.caches.len()
    }

    /// Starts (`true`) or ends the pretrace, during which new samples are stored.
    pub fn set_filling(&self, filling: bool) {
        self.filling.store(filling, Ordering::SeqCst);
    }

    /// Pretrace block sizes in pixels for an image `width` wide: from `pretrace_start` down
    /// to `pretrace_end`, halving each pass.
    pub fn pretrace_steps(&self, width: u32) -> Vec<u32> {
        let width = f64::from(width.max(1));
        let mut steps = Vec::new();
        let mut fraction = self.settings.pretrace_start;
        loop {
            let step = (fraction * width).round().max(1.0) as u32;
            if steps.last() != Some(&step) {
                steps.push(step);
            }
            if fraction <= self.settings.pretrace_end * 1.000_001 || step == 1 {
                break;
            }
            fraction = (fraction / 2.0).max(self.settings.pretrace_end);
        }
        steps
    }

    /// Gathered light scaled for the surface: `brightness`, `gray_threshold`, `max_sample`.
    /// `gather(direction)` traces one ray from the point at the next bounce depth.
    pub fn irradiance(
        &self,
        point: DVec3,
        normal: DVec3,
        depth: u32,
        gather: &(dyn Fn(DVec3) -> Gathered + Sync),
    ) -> DVec3 {
        if self.caches.len() <= depth as usize {
            return DVec3::ZERO;
        }
        let filling = self.filling.load(Ordering::Relaxed);
        let (sum, weight, found) = self.lookup(depth as usize, point, normal, filling);
        let irradiance = if self.reuses(found, filling) {
            sum / weight
        } else {
            counters::add(
                match depth {
                    0 => Counter::RadiositySamplesFirstBounce,
                    1 => Counter::RadiositySamplesSecondBounce,
                    _ => Counter::RadiositySamplesDeeper,
                },
                1,
            );
            let directions = &self.directions[depth as usize];
            let rays = rays_at_depth(self.settings.count, depth as usize);
            let start = if filling {
                DIRECTION_CURSOR.with(|cursor| match cursor.get() {
                    Some(next) => {
                        cursor.set(Some(next.wrapping_add(rays)));
                        next
                    }
                    None => self.next_direction.fetch_add(rays, Ordering::Relaxed),
                })
            } else {
                0
            };
            let path_distance = self.path_distance(point, depth);
            let (irradiance, nearest_distance, harmonic_distance) =
                with_gather_path(depth, point, path_distance, || {
                    if filling {
                        self.gather_in_batches(directions, rays, normal, start, gather)
                    } else {
                        gather_over(directions, rays, normal, start, gather)
                    }
                });
            let distance = if depth == 0 {
                nearest_distance
            } else {
                harmonic_distance
            };
            let radius = self.settings.error_bound
                * distance.clamp(
                    self.settings.minimum_reuse * path_distance,
                    self.settings.maximum_reuse * path_distance,
                );
            if radius.is_finite() && radius > 0.0 && irradiance.is_finite() {
                let sample = Sample {
                    point,
                    normal,
                    irradiance,
                    radius,
                };
                self.store(depth as usize, sample, filling);
            }
            irradiance
        };
        self.adjusted(irradiance)
    }

    /// How far the light gathered at `point` (at bounce `depth`) travels to the eye: the
    /// straight distance for the first bounce; for a deeper one, the distance of the gather
    /// that spawned the ray reaching `point` plus that ray's length.
    fn path_distance(&self, point: DVec3, depth: u32) -> f64 {
        let parent = depth.checked_sub(1).and_then(|parent| {
            GATHER_PATH.with(|path| path.borrow().get(parent as usize).copied())
        });
        match parent {
            Some((origin, distance)) => distance + (point - origin).length(),
            None => (point - self.eye).length(),
        }
    }

    /// `brightness`, `gray_threshold` and `max_sample` applied to gathered light.
    fn adjusted(&self, irradiance: DVec3) -> DVec3 {
        let mut light = irradiance;
        let gray = self.settings.gray_threshold;
        if gray > 0.0 {
            let grey = light.dot(GREY_WEIGHTS);
            light = light * (1.0 - gray) + DVec3::splat(grey * gray);
        }
        let limit = self.settings.max_sample;
        let brightest = light.max_element();
        if limit > 0.0 && brightest > limit {
            light *= limit / brightest;
        }
        light * self.settings.brightness
    }
}

/// Rays gathering one sample at bounce `depth`: POV-Ray halves `count` for each bounce
/// (measured from its statistics: `count 200` shoots 200, 100 and 50 rays at depths 0-2,
/// `count 35` 35, 17 and 8), at least one.
fn rays_at_depth(count: u32, depth: usize) -> u32 {
    count
        .max(1)
        .checked_shr(u32::try_from(depth).unwrap_or(u32::MAX))
        .unwrap_or(0)
        .max(1)
}

/// Runs `gather` with this thread's gather path standing at `point`, `path_distance` from
/// the eye, for bounce `depth` (so that the deeper gathers it starts measure their paths
/// from here), and restores the path afterwards.
fn with_gather_path<T>(
    depth: u32,
    point: DVec3,
    path_distance: f64,
    gather: impl FnOnce() -> T,
) -> T {
    let depth = depth as usize;
    GATHER_PATH.with(|path| {
        let mut path = path.borrow_mut();
        path.truncate(depth);
        // Without the gathers of the outer bounces (not reached from the tracer), deeper
        // gathers measure from the eye instead.
        if path.len() == depth {
            path.push((point, path_distance));
        }
    });
    let result = gather();
    GATHER_PATH.with(|path| path.borrow_mut().truncate(depth));
    result
}

/// The cosine-weighted unit directions around +z that samples gathering `rays` rays draw
/// from: a pool larger than `count` (`count N, POOL`) is used a window of `rays` at a time,
/// so it follows the Halton sequence, every window of which is spread over the hemisphere;
/// otherwise the set is used whole and is the more even spherical Fibonacci set of `rays`.
fn direction_set(settings: &RadiositySettings, rays: u32) -> Vec<DVec3> {
    let windowed = settings.direction_pool > settings.count;
    let pool = if windowed {
        settings.direction_pool
    } else {
        rays.max(1)
    };
    (0..pool)
        .map(|index| {
            let (height, turn) = if windowed {
                (radical_inverse(index + 1, 2), radical_inverse(index + 1, 3))
            } else {
                (
                    (f64::from(index) + 0.5) / f64::from(pool),
                    (f64::from(index) * GOLDEN_FRACTION).fract(),
                )
            };
            let radius = height.sqrt();
            let azimuth = std::f64::consts::TAU * turn;
            DVec3::new(
                radius * azimuth.cos(),
                radius * azimuth.sin(),
                (1.0 - height).max(0.0).sqrt(),
            )
        })
        .collect()
}

/// Mean light over `rays` of `directions` (cosine-weighted, around +z) turned to the
/// hemisphere around `normal`, starting at `start` in the set and wrapping around, the
/// distance to the nearest surface hit and the harmonic mean distance of the hits (both
/// infinite when every ray escaped). The first bounce's reuse radius follows the nearest
/// distance, as POV-Ray's manual says ("the distance to the closest item hit"): sizing it by
/// the harmonic mean let a sample whose rays mostly see the sky be reused far under an
/// overhang (measured on radiosity2.pov and radiosity3.pov). Deeper bounces' radii follow
/// the harmonic mean, which fits POV-Ray's deeper sample counts (cornell.pov: the nearest
/// distance there gives the same image at 2.7 times the time).
fn gather_over(
    directions: &[DVec3],
    rays: u32,
    normal: DVec3,
    start: u32,
    gather: &dyn Fn(DVec3) -> Gathered,
) -> (DVec3, f64, f64) {
    let frame = normal.any_orthonormal_pair();
    let seen = (0..rays).filter_map(|offset| {
        hemisphere_direction(directions, start, offset, normal, frame).map(gather)
    });
    summarise(seen, rays)
}

/// Direction `offset` of a sample's rays starting at `start` in `directions` (around +z),
/// turned to the hemisphere around `normal` (`frame` is its tangent pair).
fn hemisphere_direction(
    directions: &[DVec3],
    start: u32,
    offset: u32,
    normal: DVec3,
    (tangent, bitangent): (DVec3, DVec3),
) -> Option<DVec3> {
    let pool = directions.len().max(1);
    let local = directions.get((start as usize + offset as usize) % pool)?;
    Some(tangent * local.x + bitangent * local.y + normal * local.z)
}

/// The mean light of the rays of one sample (`rays` of them were shot, `seen` in order),
/// the nearest hit's distance and the harmonic mean distance of the hits.
fn summarise(seen: impl Iterator<Item = Gathered>, rays: u32) -> (DVec3, f64, f64) {
    let mut total = DVec3::ZERO;
    let mut nearest = f64::INFINITY;
    let mut inverse_distances = 0.0;
    for seen in seen {
        if seen.colour.is_finite() {
            total += seen.colour;
        }
        if seen.distance > 0.0 {
            nearest = nearest.min(seen.distance);
            inverse_distances += 1.0 / seen.distance;
        }
    }
    let rays = f64::from(rays.max(1));
    let harmonic = if inverse_distances > 0.0 {
        rays / inverse_distances
    } else {
        f64::INFINITY
    };
    (total / rays, nearest, harmonic)
}

/// `colour(column, row)` for every pixel of a `width` × `height` image, storing the samples
/// the final render gathers: rows are traced in parallel a block of [`ROWS_PER_BLOCK`] at a
/// time, each on one thread with its own list of new samples (which its later pixels reuse);
/// after each block the lists join the cache in row order, so later blocks reuse them and
/// the image does not depend on the number of threads. `progress` hears of each finished row.
pub fn map_rows_storing(
    radiosity: &Radiosity,
    width: u32,
    height: u32,
    progress: Option<&(dyn Fn(u32) + Sync)>,
    colour: impl Fn(u32, u32) -> DVec4 + Sync,
) -> Vec<DVec4> {
    let row_length = width.max(1) as usize;
    let mut colours = vec![DVec4::ZERO; row_length * height as usize];
    for (block, rows) in colours.chunks_mut(row_length * ROWS_PER_BLOCK).enumerate() {
        let gathered: Vec<Vec<Cache>> = rows
            .par_chunks_mut(row_length)
            .enumerate()
            .map(|(offset, line)| {
                let row = (block * ROWS_PER_BLOCK + offset) as u32;
                PRIVATE.with(|private| private.borrow_mut().own = Some(Vec::new()));
                if !super::interrupted() {
                    for (column, slot) in line.iter_mut().enumerate() {
                        *slot = colour(column as u32, row);
                    }
                }
                if let Some(progress) = progress {
                    progress(1);
                }
                PRIVATE
                    .with(|private| private.borrow_mut().own.take())
                    .unwrap_or_default()
            })
            .collect();
        radiosity.keep_new(gathered, true);
    }
    colours
}

impl Radiosity {
    /// The usable samples of bounce `depth` at `point`: the shared cache's and those of the
    /// current unit of work and the units it runs inside (see [`PrivateSamples`]), as the
    /// weighted sum of their irradiance, the sum of the weights and their number. The
    /// pretrace lowers the error bound of the first bounce only: deeper bounces keep their
    /// radii (POV-Ray's deeper counts barely follow `low_error_factor`).
    fn lookup(
        &self,
        depth: usize,
        point: DVec3,
        normal: DVec3,
        filling: bool,
    ) -> (DVec3, f64, u32) {
        let bound_scale = if filling && depth == 0 {
            self.settings.low_error_factor
        } else {
            1.0
        };
        let bound = self.settings.error_bound * bound_scale;
        let Some(cache) = self.caches.get(depth) else {
            return (DVec3::ZERO, 0.0, 0);
        };
        let (mut sum, mut weight, mut found) = {
            let cache = cache.read().unwrap_or_else(|poison| poison.into_inner());
            interpolate(&cache, point, normal, bound, bound_scale)
        };
        PRIVATE.with(|private| {
            let private = private.borrow();
            let layers = private.frozen.iter().map(|layer| layer.as_slice());
            for layer in layers.chain(private.own.as_deref()) {
                if let Some(layer_cache) = layer.get(depth) {
                    let (layer_sum, layer_weight, layer_found) =
                        interpolate(layer_cache, point, normal, bound, bound_scale);
                    sum += layer_sum;
                    weight += layer_weight;
                    found += layer_found;
                }
            }
        });
        (sum, weight, found)
    }

    /// Keeps a new sample of bounce `depth`: in the current unit's own samples inside one,
    /// else in the shared cache when `shared` (the pretrace, or samples joining the cache
    /// after a block of rows).
    fn store(&self, depth: usize, sample: Sample, shared: bool) {
        // Found wherever some lookup (with its radius scale) could use it.
        let reach_scale = self.settings.low_error_factor;
        let kept = PRIVATE.with(|private| match private.borrow_mut().own.as_mut() {
            Some(own) => {
                // Grown on demand: most rows and rays store nothing.
                if own.len() <= depth {
                    own.resize_with(depth + 1, Cache::default);
                }
                own[depth].push(sample, reach_scale);
                true
            }
            None => false,
        });
        if shared && !kept {
            if let Some(cache) = self.caches.get(depth) {
                let mut cache = cache.write().unwrap_or_else(|poison| poison.into_inner());
                cache.push(sample, reach_scale);
            }
        }
    }

    /// Keeps the samples that parallel units (rows, or rays of a batch) gathered, unit by
    /// unit in order, where this thread stores (see [`Radiosity::store`]). A sample that
    /// the samples kept before it can already answer for at its own point is left out: two
    /// units that gathered at the same place keep one sample, as one after the other would
    /// have.
    fn keep_new(&self, units: Vec<Vec<Cache>>, shared: bool) {
        let filling = self.filling.load(Ordering::Relaxed);
        for unit in units {
            for (depth, unit_cache) in unit.into_iter().enumerate() {
                for sample in unit_cache.samples {
                    let (_, _, found) = self.lookup(depth, sample.point, sample.normal, filling);
                    if !self.reuses(found, filling) {
                        self.store(depth, sample, shared);
                    }
                }
            }
        }
    }

    /// Whether a lookup that found `found` usable samples reuses them rather than gathering.
    fn reuses(&self, found: u32, filling: bool) -> bool {
        let wanted = self.settings.nearest_count.max(1);
        if filling {
            found >= wanted
        } else {
            found > 0 && !(self.settings.always_sample && found < wanted)
        }
    }
}

/// Rays of one pretrace sample traced in parallel together; each ray sees the caches as
/// they were when its batch began plus the deeper samples it gathered itself, and the
/// batch's new samples are kept in ray order after it. A fixed number, so the image does
/// not depend on the number of threads; small, so that a batch's rays (spread over the
/// hemisphere by the direction set's order) seldom gather next to each other.
const RAYS_PER_BATCH: usize = 16;

impl Radiosity {
    /// [`gather_over`] for a sample of the pretrace, its rays traced [`RAYS_PER_BATCH`] at
    /// a time in parallel (the pretrace's pixels follow each other, so this is where its
    /// work spreads over the threads). A ray that gathers a deeper sample batches that
    /// sample's rays in turn, so one expensive ray does not hold its batch back. Each ray
    /// is a unit of its own ([`PrivateSamples`]): the samples of the units it runs inside
    /// are read-only while it runs; what the batch's rays gathered is kept after the batch,
    /// ray by ray; the sum is taken in ray order.
    fn gather_in_batches(
        &self,
        directions: &[DVec3],
        rays: u32,
        normal: DVec3,
        start: u32,
        gather: &(dyn Fn(DVec3) -> Gathered + Sync),
    ) -> (DVec3, f64, f64) {
        let frame = normal.any_orthonormal_pair();
        let path = GATHER_PATH.with(|path| path.borrow().clone());
        // This unit's own samples are read-only to the rays below: they join its frozen
        // layers for the batches and come back afterwards.
        let (outer_frozen, outer_own) = PRIVATE.with(|private| {
            let mut private = private.borrow_mut();
            (private.frozen.clone(), private.own.take())
        });
        let nested = outer_own.is_some();
        let mut frozen = outer_frozen.clone();
        frozen.extend(outer_own.map(Arc::new));
        let offsets: Vec<u32> = (0..rays).collect();
        let mut seen = Vec::with_capacity(offsets.len());
        for batch in offsets.chunks(RAYS_PER_BATCH) {
            let traced: Vec<(Option<Gathered>, Vec<Cache>)> = batch
                .par_iter()
                .map(|&offset| {
                    // This thread may be in the middle of another unit (a thread waiting
                    // for its batch runs others' rays): save its state and restore it.
                    let unit = PrivateSamples {
                        frozen: frozen.clone(),
                        own: Some(Vec::new()),
                    };
                    let outer_unit = PRIVATE.with(|private| private.replace(unit));
                    let outer_path = GATHER_PATH.with(|p| p.replace(path.clone()));
                    // Deeper samples draw their directions from a place of their own.
                    let cursor = start.wrapping_add(offset.wrapping_add(1).wrapping_mul(7919));
                    let outer_cursor = DIRECTION_CURSOR.with(|c| c.replace(Some(cursor)));
                    let gathered =
                        hemisphere_direction(directions, start, offset, normal, frame).map(gather);
                    DIRECTION_CURSOR.with(|c| c.set(outer_cursor));
                    GATHER_PATH.with(|p| p.replace(outer_path));
                    let unit = PRIVATE.with(|private| private.replace(outer_unit));
                    (gathered, unit.own.unwrap_or_default())
                })
                .collect();
            let mut units = Vec::with_capacity(traced.len());
            for (gathered, samples) in traced {
                seen.extend(gathered);
                units.push(samples);
            }
            // Between batches no ray holds the layers: this unit's own samples are taken
            // back out of them to keep the batch's samples among them, then frozen again.
            let own = if nested {
                frozen.pop().map(Arc::unwrap_or_clone)
            } else {
                None
            };
            PRIVATE.with(|private| {
                *private.borrow_mut() = PrivateSamples {
                    frozen: outer_frozen.clone(),
                    own,
                }
            });
            self.keep_new(units, true);
            if nested {
                let own = PRIVATE.with(|private| private.borrow_mut().own.take());
                frozen.extend(own.map(Arc::new));
            }
        }
        PRIVATE.with(|private| {
            let mut private = private.borrow_mut();
            private.frozen = outer_frozen;
            private.own = if nested {
                frozen.pop().map(Arc::unwrap_or_clone)
            } else {
                None
            };
        });
        summarise(seen.into_iter(), rays)
    }
}

/// The radical inverse of `index` in `base`: its digits mirrored about the point.
fn radical_inverse(mut index: u32, base: u32) -> f64 {
    let mut inverse = 0.0;
    let mut scale = 1.0 / f64::from(base);
    while index > 0 {
        inverse += f64::from(index % base) * scale;
        index /= base;
        scale /= f64::from(base);
    }
    inverse
}

/// Fills the caches: traces the pixel at the centre of every block of each pretrace pass,
/// coarse to fine, in row order (`trace_pixel(column, row)`); the rays of each first-bounce
/// sample it gathers run in parallel ([`Radiosity::gather_in_batches`]).
pub fn pretrace(
    radiosity: &Radiosity,
    width: u32,
    height: u32,
    trace_pixel: &dyn Fn(u32, u32) -> DVec4,
) {
    radiosity.set_filling(true);
    for step in radiosity.pretrace_steps(width) {
        let half = step / 2;
        for row in (0..height).step_by(step as usize) {
            for column in (0..width).step_by(step as usize) {
                let _ = trace_pixel((column + half).min(width - 1), (row + half).min(height - 1));
            }
        }
    }
    radiosity.set_filling(false);
}

/// The weighted sum of the cached samples usable at `point` (with unit `normal`), their
/// total weight and how many there are; `bound` is the error bound in force, whose ratio
/// `bound_scale` to `error_bound` shrinks every reuse radius.
fn interpolate(
    cache: &Cache,
    point: DVec3,
    normal: DVec3,
    bound: f64,
    bound_scale: f64,
) -> (DVec3, f64, u32) {
    let weigh = |sample: &Sample| reuse_weight(sample, point, normal, bound, bound_scale);
    LOOKUP_BUFFERS.with(|buffers| match buffers.try_borrow_mut() {
        Ok(mut buffers) => {
            let LookupBuffers { nearby, usable } = &mut *buffers;
            nearby.clear();
            usable.clear();
            cache.index.candidates(point, nearby);
            usable.extend(nearby.iter().filter_map(|&id| {
                let share = weigh(cache.samples.get(id as usize)?)?;
                Some((id, share))
            }));
            // Summed in the order the samples were stored, as a scan of the cache would.
            usable.sort_unstable_by_key(|&(id, _)| id);
            sum_weighted(
                usable
                    .iter()
                    .filter_map(|&(id, share)| Some((cache.samples.get(id as usize)?, share))),
            )
        }
        // Not reached (a lookup never nests in another); the same result, only slower.
        Err(_) => sum_weighted(
            cache
                .samples
                .iter()
                .filter_map(|sample| Some((sample, weigh(sample)?))),
        ),
    })
}

/// How much `sample` counts at `point` (with unit `normal`), if it is usable there:
/// `1 − error`; `bound` is the error bound in force (the normals' term is measured against
/// it) and `bound_scale` its ratio to `error_bound`, which shrinks the reuse radius.
fn reuse_weight(
    sample: &Sample,
    point: DVec3,
    normal: DVec3,
    bound: f64,
    bound_scale: f64,
) -> Option<f64> {
    let offset = point - sample.point;
    let radius = sample.radius * bound_scale;
    let distance_squared = offset.length_squared();
    if distance_squared >= radius * radius {
        return None;
    }
    let facing = normal.dot(sample.normal);
    if facing <= 0.0 {
        return None;
    }
    // A sample in front of the point (e.g. across an inside corner) does not apply.
    if offset.dot(normal + sample.normal) < -0.05 * radius {
        return None;
    }
    // Ward's error `d / R + sqrt(1 − N·Nᵢ)` against the bound: POV-Ray gathers anew on a
    // curved surface as often as this predicts (a lone cylinder: 53 final-pass samples,
    // without the bound on the normals' term a handful).
    let error = distance_squared.sqrt() / radius + (1.0 - facing).max(0.0).sqrt() / bound;
    (error < 1.0).then_some(1.0 - error)
}

/// The sum of the samples' irradiance times their weights, the total weight and the count.
fn sum_weighted<'a>(weighted: impl Iterator<Item = (&'a Sample, f64)>) -> (DVec3, f64, u32) {
    let mut sum = DVec3::ZERO;
    let mut weight = 0.0;
    let mut found = 0;
    for (sample, share) in weighted {
        sum += sample.irradiance * share;
        weight += share;
        found += 1;
    }
    (sum, weight, found)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sky(_direction: DVec3) -> Gathered {
        Gathered {
            colour: DVec3::ONE,
            distance: f64::INFINITY,
        }
    }

    #[test]
    fn directions_are_unit_and_in_the_upper_hemisphere() {
        let radiosity = Radiosity::new(&RadiositySettings::default(), DVec3::ZERO);
        for direction in &radiosity.directions[0] {
            assert!((direction.length() - 1.0).abs() < 1e-12);
            assert!(direction.z > 0.0);
        }
        // Cosine weighting: the mean height of the directions is 2/3.
        let mean = radiosity.directions[0].iter().map(|d| d.z).sum::<f64>() / 35.0;
        assert!((mean - 2.0 / 3.0).abs() < 0.01, "{mean}");
    }

    #[test]
    fn an_open_sky_gives_its_own_colour_and_is_reused() {
        let radiosity = Radiosity::new(&RadiositySettings::default(), DVec3::new(0.0, 0.0, -10.0));
        radiosity.set_filling(true);
        let light = radiosity.irradiance(DVec3::ZERO, DVec3::Y, 0, &sky);
        assert!((light - DVec3::ONE).length() < 1e-12);
        radiosity.set_filling(false);
        let unused = |_: DVec3| -> Gathered { panic!("the cached sample should be reused") };
        let light = radiosity.irradiance(DVec3::new(0.1, 0.0, 0.0), DVec3::Y, 0, &unused);
        assert!((light - DVec3::ONE).length() < 1e-12);
    }

    #[test]
    fn the_final_pass_stores_its_samples_row_by_row() {
        let radiosity = Radiosity::new(&RadiositySettings::default(), DVec3::new(0.0, 0.0, -10.0));
        let rays = AtomicU32::new(0);
        let counting_sky = |direction: DVec3| {
            rays.fetch_add(1, Ordering::Relaxed);
            sky(direction)
        };
        let image = map_rows_storing(&radiosity, 4, 2, None, |column, _row| {
            let point = DVec3::new(f64::from(column) * 0.01, 0.0, 0.0);
            radiosity
                .irradiance(point, DVec3::Y, 0, &counting_sky)
                .extend(0.0)
        });
        assert!(image
            .iter()
            .all(|light| (light.truncate() - DVec3::ONE).length() < 1e-12));
        // Each row of the block gathers one sample that its other pixels reuse.
        assert_eq!(rays.load(Ordering::Relaxed), 2 * 35);
        // After the block, the samples are in the cache for everyone.
        let unused = |_: DVec3| -> Gathered { panic!("the stored sample should be reused") };
        let light = radiosity.irradiance(DVec3::new(0.02, 0.0, 0.0), DVec3::Y, 0, &unused);
        assert!((light - DVec3::ONE).length() < 1e-12);
    }

    #[test]
    fn deeper_bounces_gather_half_as_many_rays_each() {
        let settings = RadiositySettings {
            count: 35,
            direction_pool: 35,
            recursion_limit: 3,
            ..RadiositySettings::default()
        };
        let radiosity = Radiosity::new(&settings, DVec3::new(0.0, 0.0, -10.0));
        radiosity.set_filling(true);
        for (depth, expected) in [(0, 35), (1, 17), (2, 8)] {
            let rays = AtomicU32::new(0);
            let counting_sky = |direction: DVec3| {
                rays.fetch_add(1, Ordering::Relaxed);
                sky(direction)
            };
            // Far apart, so that no sample is reused.
            let point = DVec3::new(1000.0 * f64::from(depth), 0.0, 0.0);
            let light = radiosity.irradiance(point, DVec3::Y, depth, &counting_sky);
            assert!((light - DVec3::ONE).length() < 1e-12);
            assert_eq!(rays.load(Ordering::Relaxed), expected, "depth {depth}");
        }
        // Each bounce's set is cosine-weighted on its own: mean height near 2/3.
        for set in &radiosity.directions {
            let mean = set.iter().map(|d| d.z).sum::<f64>() / set.len() as f64;
            assert!((mean - 2.0 / 3.0).abs() < 0.02, "{mean}");
        }
        assert_eq!(rays_at_depth(1, 5), 1);
        assert_eq!(rays_at_depth(200, 40), 1);
    }

    /// Stores one sample at the origin (normal +y, eye 10 away) whose first ray meets a
    /// surface 1 away and whose other rays escape, then ends the pretrace.
    fn one_sample_beside_a_wall(error_bound: f64) -> Radiosity {
        let settings = RadiositySettings {
            error_bound,
            ..RadiositySettings::default()
        };
        let radiosity = Radiosity::new(&settings, DVec3::new(0.0, 0.0, -10.0));
        let first = AtomicBool::new(true);
        let wall_then_sky = |direction: DVec3| {
            if first.swap(false, Ordering::Relaxed) {
                Gathered {
                    colour: DVec3::ZERO,
                    distance: 1.0,
                }
            } else {
                sky(direction)
            }
        };
        radiosity.set_filling(true);
        radiosity.irradiance(DVec3::ZERO, DVec3::Y, 0, &wall_then_sky);
        radiosity.set_filling(false);
        radiosity
    }

    /// Whether a final-pass lookup at `point` with `normal` gathers anew.
    fn gathers_at(radiosity: &Radiosity, point: DVec3, normal: DVec3) -> bool {
        let gathered = AtomicBool::new(false);
        let noting_sky = |direction: DVec3| {
            gathered.store(true, Ordering::Relaxed);
            sky(direction)
        };
        radiosity.irradiance(point, normal, 0, &noting_sky);
        gathered.load(Ordering::Relaxed)
    }

    #[test]
    fn the_reuse_radius_is_the_bound_times_the_nearest_surface_distance() {
        // Radius 0.5 × 1 (the nearest hit), although most rays saw the open sky.
        let radiosity = one_sample_beside_a_wall(0.5);
        assert!(!gathers_at(
            &radiosity,
            DVec3::new(0.45, 0.0, 0.0),
            DVec3::Y
        ));
        assert!(gathers_at(&radiosity, DVec3::new(0.55, 0.0, 0.0), DVec3::Y));
        // The clamp applies to the distance before the bound scales it: at most
        // `maximum_reuse` (0.2) × 10 = 2 here, so an escaped sample reaches 0.5 × 2 = 1.
        let radiosity = Radiosity::new(
            &RadiositySettings {
                error_bound: 0.5,
                ..RadiositySettings::default()
            },
            DVec3::new(0.0, 0.0, -10.0),
        );
        radiosity.set_filling(true);
        radiosity.irradiance(DVec3::ZERO, DVec3::Y, 0, &sky);
        radiosity.set_filling(false);
        assert!(!gathers_at(
            &radiosity,
            DVec3::new(0.95, 0.0, 0.0),
            DVec3::Y
        ));
        assert!(gathers_at(&radiosity, DVec3::new(1.05, 0.0, 0.0), DVec3::Y));
    }

    #[test]
    fn the_normals_term_is_measured_against_the_bound() {
        let tilted = |degrees: f64| {
            let angle = degrees.to_radians();
            DVec3::new(angle.sin(), angle.cos(), 0.0)
        };
        // sqrt(1 − cos 10°) / 0.3 ≈ 0.41: reused; sqrt(1 − cos 30°) / 0.3 ≈ 1.22: not.
        let radiosity = one_sample_beside_a_wall(0.3);
        assert!(!gathers_at(&radiosity, DVec3::ZERO, tilted(10.0)));
        assert!(gathers_at(&radiosity, DVec3::ZERO, tilted(30.0)));
    }

    #[test]
    fn deeper_bounces_measure_reuse_along_the_light_path() {
        let settings = RadiositySettings {
            recursion_limit: 2,
            error_bound: 0.5,
            maximum_reuse: 0.2,
            nearest_count: 1,
            ..RadiositySettings::default()
        };
        let radiosity = Radiosity::new(&settings, DVec3::ZERO);
        radiosity.set_filling(true);
        let first = DVec3::new(0.0, 0.0, 10.0);
        let deeper = DVec3::new(0.0, 4.0, 7.0);
        // The first bounce's rays reach `deeper` (5 from `first`), which gathers the sky.
        let bounce = |_direction: DVec3| {
            let colour = radiosity.irradiance(deeper, DVec3::Y, 1, &sky);
            Gathered {
                colour,
                distance: 5.0,
            }
        };
        radiosity.irradiance(first, -DVec3::Z, 0, &bounce);
        let radius_at = |depth: usize| {
            let cache = radiosity.caches[depth].read().unwrap();
            assert_eq!(cache.samples.len(), 1, "depth {depth}");
            cache.samples[0].radius
        };
        // First bounce: the harmonic distance (5) clamped to 0.2 × the eye distance (10),
        // then scaled by error_bound.
        assert!((radius_at(0) - 0.5 * 2.0).abs() < 1e-12);
        // Deeper: the sky is infinitely far, so the distance is clamped to 0.2 × the light's
        // path to the eye (10 + 5), not its straight distance (8.06), then scaled.
        assert!((radius_at(1) - 0.5 * 0.2 * 15.0).abs() < 1e-12);
    }

    #[test]
    fn pretrace_steps_halve_from_start_to_end() {
        let radiosity = Radiosity::new(&RadiositySettings::default(), DVec3::ZERO);
        assert_eq!(radiosity.pretrace_steps(160), vec![13, 6]);
    }
}
