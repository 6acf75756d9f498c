//! Photon mapping: caustics from light reflected and refracted by photon targets.
//!
//! In: the scene's [`PhotonSettings`], its lights and the [`World`] (materials carry each
//! object's `photons` flags). Out: a [`PhotonMap`] built once before rendering, and
//! [`PhotonMap::irradiance`], the caustic light arriving at a surface point. Holds: shooting
//! runs in a fixed order (light by light, target by target, ring by ring) with jitter drawn
//! from a hash of the photon's place in that order, so the map is the same on any number of
//! threads; gathering allocates nothing (each thread reuses one buffer).
//!
//! Rules, from POV-Ray 3.7's manual and renders of a glass sphere over a plane:
//! - photons leave each light that shoots them (`photons { refraction | reflection }` of the
//!   light, both on by default) towards each target's bounding sphere, on a spiral of rings
//!   around the direction to its centre: ring i at angle i·dθ from it, dθ = spacing ·
//!   target multiplier / distance to the centre, about 2π sin θ / dθ photons per ring, each
//!   direction jittered by `jitter` times the spacing. Rings stop at the bounding sphere's
//!   edge, or earlier when a whole ring misses the target after one photon has hit it and the
//!   spiral is beyond `autostop` of the way out (measured: a sphere of radius 1 at distance
//!   5.745 and spacing 0.02 gets 8311 photons, the sphere's own cone plus one ring, not the
//!   24,000 of its bounding box's sphere).
//! - `parallel` and cylinder lights shoot parallel rays along their direction instead, from
//!   the plane through the light perpendicular to it, on the same rings laid out across the
//!   target's bounding disc `spacing` apart (measured: a sphere of radius 0.6 at spacing
//!   0.02 gets 3118 photons, its disc plus one ring); each carries the light's colour times
//!   spacing², the area it stands for.
//! - a photon from a point carries the light's colour (spotlit as the light arrives at its
//!   first hit) times (spacing · multiplier)², the area it stands for where it meets the
//!   target; the light's `fade_distance`/`fade_power` fade it by the length of its whole
//!   path where it is stored (measured through a glass pane: the caustic fades as the
//!   floor's direct light does, not as the light at the pane).
//! - an object reflects (refracts) a light's photons with its `reflection on`
//!   (`refraction on`), or without its own item when the light's block says `reflection
//!   on` (`refraction on`) itself (measured).
//! - at a surface whose object reflects photons it goes on mirrored, times the finish's
//!   reflection; where the object refracts photons it goes on bent by Snell's law, times
//!   `filter · pigment + transmit`, less what the surface reflects when its finish has
//!   `conserve_energy` (as for camera rays; measured); total internal reflection sends it
//!   all back. Photons cross `no_shadow` objects unchanged, and `pass_through` ones on
//!   their way from the light (after their first bounce they meet those as any object; a
//!   part's own `pass_through` is dropped in a CSG target). After one bounce a
//!   photon is stored where it meets an object that collects photons. Bounces end at
//!   `max_trace_level` or when the photon's largest component falls below `adc_bailout` of
//!   its start.
//! - shadows: a target that refracts photons blocks the shadow rays of lights that shoot
//!   refracted photons (its caustic stands for the light through it; measured: no other
//!   combination changes the shadow). A `no_image` target is neither shot at nor blocks.
//! - media photons (`media MAX_STEPS, FACTOR`): after its first bounce a photon crossing
//!   scattering media (of the hollow objects it is in, by the same stack of interiors
//!   camera rays carry, and of the atmosphere) deposits photons along its path, spacing ·
//!   FACTOR apart (at most MAX_STEPS per stretch between surfaces), each carrying its power
//!   times the length it stands for, dimmed by the media's extinction on the way; media
//!   samples of camera rays add scattering times the phase-weighted power of the nearest
//!   `gather` max within the media radius (`radius`'s third value, else 15 media spacings)
//!   over the sphere's volume.
//! - gathering: the photons within the gather radius (estimated as 5 spacings, POV-Ray's
//!   recommended ratio, or `radius`, times its multiplier), the nearest `gather` max of them;
//!   with fewer than `gather` min the radius is doubled once and the wider estimate kept
//!   unless it raises the density by more than `expand_thresholds`' fraction with at least
//!   its minimum found. Each photon lights the point like a light from the direction it came
//!   from, `cos^brilliance` divided by the `cos` by which photons arriving aslant already
//!   lie sparser (measured: a caustic through a pane of index 1 lights a floor as the light
//!   does at any angle and brilliance); their sum is divided by the area of the disc
//!   searched, times diffuse and pigment.

use super::antialias::unit_hash;
use super::extinction::{density_at, exp_neg};
use super::interiors::{interiors_around, InteriorStack};
use super::lights::{fade_factor, incoming};
use super::optics::{
    interior_fade, mirror, reflection_colour, refract, sanitise_ior, SURFACE_EPSILON,
};
use super::surface::surface_pigment;
use crate::geometry::{Ray, World};
use crate::scene::{LightSource, Media, PhotonDensity, PhotonSettings, Scene};
use crate::texture::pigment::hit_surface;
use glam::DVec3;
use std::cell::{Cell, RefCell};
use std::f64::consts::{PI, TAU};

/// POV-Ray's recommended ratio of gather radius to photon spacing.
const RADIUS_PER_SPACING: f64 = 5.0;

/// The automatic gather radius of media photons, in media photon spacings (spacing times
/// the `media` factor). Measured against POV-Ray's beams in media (reference
/// `media_photons_mirror`): 5 spacings gives 13% of pixels off, 10 gives 5.9%, beyond 12.5
/// the nearest `gather` max photons set the radius and nothing changes (5.7%).
const MEDIA_RADIUS_PER_SPACING: f64 = 15.0;

/// At most this many media act on one stretch of a photon's path.
const MAX_DEPOSIT_MEDIA: usize = 16;

/// At most this many photon rays are traced in all (shots from lights and every bounce
/// of every branch), whatever the spacing and trace level ask for.
const TRACE_LIMIT: u64 = 20_000_000;

/// At most this many photons are stored.
const STORED_LIMIT: usize = 5_000_000;

/// The smallest cosine a gathered photon's weight uses (about 89.94° from the normal).
const GRAZING_COSINE: f64 = 1e-3;

/// Salt of the jitter random numbers.
const JITTER_SALT: u64 = 0x51a7_c0de_9e37_79b9;

/// One stored photon.
#[derive(Clone, Copy, Debug)]
struct Photon {
    /// Where it landed.
    position: DVec3,
    /// The unit direction it travelled.
    direction: DVec3,
    /// The light it carries.
    power: DVec3,
}

/// A target to shoot at: its bounding sphere and its material.
#[derive(Clone, Copy, Debug)]
struct Target {
    centre: DVec3,
    radius: f64,
    spacing_multiplier: f64,
    material: u32,
}

/// The stored photons in a kd-tree, and how to gather them.
pub struct PhotonMap {
    /// Photons in kd-tree order: the median of each range is the node splitting it.
    photons: Vec<Photon>,
    /// The axis (0, 1, 2) each node splits, by index.
    axes: Vec<u8>,
    /// The search radius of a gather.
    radius: f64,
    gather_min: usize,
    gather_max: usize,
    expand_increase: f64,
    expand_min: usize,
    /// Photons shot in all.
    shot: u64,
    /// The photons deposited in scattering media, when the scene asks for them.
    media: Option<MediaPhotons>,
}

/// Photons deposited along photons' paths through scattering media, in a kd-tree.
struct MediaPhotons {
    photons: Vec<Photon>,
    axes: Vec<u8>,
    /// The search radius of a gather.
    radius: f64,
}

/// How photons deposit media photons on their way (the global `media` item).
#[derive(Clone, Copy)]
struct MediaDeposit<'a> {
    /// At most this many photons per stretch of a path.
    max_steps: u32,
    /// Their distance along the path, in spacings.
    factor: f64,
    /// The scene's atmospheric media.
    atmosphere: &'a [Media],
}

thread_local! {
    /// The photons found by one gather (index, squared distance), reused by every gather
    /// on the thread.
    static FOUND: RefCell<Vec<(u32, f64)>> = const { RefCell::new(Vec::new()) };
}

impl PhotonMap {
    /// Shoots the scene's photons and stores them; `None` when the scene has no photons
    /// block.
    pub fn build(scene: &Scene, world: &World) -> Option<PhotonMap> {
        let settings = scene.settings.photons.as_ref()?;
        let targets = targets(world);
        let spacing = match settings.density {
            PhotonDensity::Spacing(spacing) => spacing,
            PhotonDensity::Count(count) => spacing_for_count(scene, &targets, count),
        };
        let max_level = settings
            .max_trace_level
            .unwrap_or(scene.settings.max_trace_level)
            .clamp(1, 256);
        let bailout = settings.adc_bailout.unwrap_or(scene.settings.adc_bailout);
        let shooter = Shooter {
            world,
            max_level,
            bailout: if bailout.is_nan() { 0.0 } else { bailout },
            budget: Budget::new(TRACE_LIMIT, STORED_LIMIT),
            media: (settings.media_steps > 0).then_some(MediaDeposit {
                max_steps: settings.media_steps,
                factor: settings.media_factor,
                atmosphere: &scene.atmosphere.media,
            }),
            media_photons: RefCell::new(Vec::new()),
        };
        let mut photons = Vec::new();
        let mut shot = 0u64;
        for (light_index, light) in scene.lights.iter().enumerate() {
            if !(light.photons.refraction || light.photons.reflection) {
                continue;
            }
            for (target_index, target) in targets.iter().enumerate() {
                let seed = (light_index as u64) << 32 | target_index as u64;
                shot += shooter.shoot_at(
                    light,
                    target,
                    spacing * target.spacing_multiplier,
                    settings,
                    seed,
                    &mut photons,
                );
            }
        }
        if let Some(limit) = shooter.budget.limit_hit.get() {
            eprintln!(
                "durer: warning: photon shooting reached the limit of {limit} \
                 ({TRACE_LIMIT} rays, {STORED_LIMIT} photons); the caustics are incomplete \
                 (use a larger `spacing` or a smaller `count`)"
            );
        }
        let radius = if settings.radius > 0.0 {
            settings.radius
        } else {
            RADIUS_PER_SPACING * spacing
        } * settings.radius_multiplier;
        let axes = build_tree(&mut photons);
        let media = shooter.media.map(|deposit| {
            let mut photons = shooter.media_photons.take();
            let axes = build_tree(&mut photons);
            let radius = if settings.media_radius > 0.0 {
                settings.media_radius
            } else {
                MEDIA_RADIUS_PER_SPACING * spacing * deposit.factor
            } * settings.media_radius_multiplier;
            MediaPhotons {
                photons,
                axes,
                radius,
            }
        });
        Some(PhotonMap {
            photons,
            axes,
            radius,
            gather_min: settings.gather_min as usize,
            gather_max: settings.gather_max.max(1) as usize,
            expand_increase: settings.expand_increase,
            expand_min: settings.expand_min as usize,
            shot,
            media,
        })
    }

    /// Number of photons stored.
    pub fn stored(&self) -> usize {
        self.photons.len()
    }

    /// Number of photons shot.
    pub fn shot(&self) -> u64 {
        self.shot
    }

    /// Number of media photons stored.
    pub fn media_stored(&self) -> usize {
        self.media.as_ref().map_or(0, |media| media.photons.len())
    }

    /// True when the map holds media photons.
    pub fn has_media_photons(&self) -> bool {
        self.media_stored() > 0
    }

    /// The media photons gathered around `point`: calls `each` with every photon's unit
    /// direction of travel and power (its light times the length of path it stands for),
    /// and returns the volume of the sphere searched (0 when none were found); the light
    /// scattered towards a viewer per unit of scattering is the phase-weighted sum of the
    /// powers over that volume.
    pub fn media_photons(&self, point: DVec3, each: &mut impl FnMut(DVec3, DVec3)) -> f64 {
        let Some(media) = &self.media else {
            return 0.0;
        };
        if media.photons.is_empty() || !point.is_finite() {
            return 0.0;
        }
        FOUND.with(|found| {
            let mut found = found.borrow_mut();
            let (count, reach) = nearest_in(
                &media.photons,
                &media.axes,
                self.gather_max,
                point,
                media.radius,
                &mut found,
            );
            if count == 0 {
                return 0.0;
            }
            for &(index, _) in found.iter() {
                let photon = &media.photons[index as usize];
                each(photon.direction, photon.power);
            }
            4.0 / 3.0 * PI * reach * reach * reach
        })
    }

    /// The caustic light arriving at `point` (unit `normal` facing the viewer) on a finish
    /// of this `brilliance`, from the photons gathered around it over the area searched;
    /// the surface sends on its diffuse · pigment times this.
    pub fn irradiance(&self, point: DVec3, normal: DVec3, brilliance: f64) -> DVec3 {
        if self.photons.is_empty() || !point.is_finite() {
            return DVec3::ZERO;
        }
        FOUND.with(|found| {
            let mut found = found.borrow_mut();
            let light = |found: &[(u32, f64)]| -> DVec3 {
                found
                    .iter()
                    .map(|&(index, _)| {
                        let photon = &self.photons[index as usize];
                        let cosine = -photon.direction.dot(normal);
                        if cosine > 0.0 {
                            photon.power * photon_weight(cosine, brilliance)
                        } else {
                            DVec3::ZERO
                        }
                    })
                    .sum()
            };
            let (count, reach) = self.nearest(point, self.radius, &mut found);
            if count == 0 {
                return DVec3::ZERO;
            }
            let mut estimate = light(&found) / (PI * reach * reach);
            if count < self.gather_min {
                let (wider_count, wider_reach) = self.nearest(point, 2.0 * self.radius, &mut found);
                let wider = light(&found) / (PI * wider_reach * wider_reach);
                let increase = wider.max_element() / estimate.max_element().max(1e-300) - 1.0;
                if increase <= self.expand_increase || wider_count < self.expand_min {
                    estimate = wider;
                }
            }
            estimate
        })
    }

    /// Fills `found` with the nearest `gather_max` photons within `radius` of `point`;
    /// returns how many and the radius of the disc they stand for (the farthest one's
    /// distance when `gather_max` were found, else `radius`).
    fn nearest(&self, point: DVec3, radius: f64, found: &mut Vec<(u32, f64)>) -> (usize, f64) {
        nearest_in(
            &self.photons,
            &self.axes,
            self.gather_max,
            point,
            radius,
            found,
        )
    }
}

/// Fills `found` with the nearest `gather_max` of the kd-tree's `photons` (split along
/// `axes`) within `radius` of `point`; returns how many and the radius they stand for (the
/// farthest one's distance when `gather_max` were found, else `radius`).
fn nearest_in(
    photons: &[Photon],
    axes: &[u8],
    gather_max: usize,
    point: DVec3,
    radius: f64,
    found: &mut Vec<(u32, f64)>,
) -> (usize, f64) {
    found.clear();
    let mut radius2 = radius * radius;
    let tree = Tree {
        photons,
        axes,
        gather_max,
    };
    tree.collect(point, &mut radius2, 0, photons.len(), found);
    if found.len() >= gather_max {
        return (found.len(), radius2.sqrt().max(1e-12));
    }
    (found.len(), radius)
}

/// A kd-tree of photons searched for the nearest ones.
struct Tree<'a> {
    photons: &'a [Photon],
    axes: &'a [u8],
    gather_max: usize,
}

impl Tree<'_> {
    /// Adds the photons of the range `start..end` within `sqrt(radius2)` of `point` to
    /// `found`, which holds at most `gather_max`: once full it is a max-heap on distance
    /// and `radius2` shrinks to its farthest photon.
    fn collect(
        &self,
        point: DVec3,
        radius2: &mut f64,
        start: usize,
        end: usize,
        found: &mut Vec<(u32, f64)>,
    ) {
        if start >= end {
            return;
        }
        let middle = (start + end) / 2;
        let photon = &self.photons[middle];
        let distance2 = photon.position.distance_squared(point);
        if distance2 <= *radius2 {
            let candidate = (middle as u32, distance2);
            if found.len() < self.gather_max {
                found.push(candidate);
                if found.len() == self.gather_max {
                    make_max_heap(found);
                    *radius2 = found[0].1;
                }
            } else if distance2 < found[0].1 {
                found[0] = candidate;
                sift_down(found, 0);
                *radius2 = found[0].1;
            }
        }
        let axis = usize::from(self.axes[middle]);
        let offset = point[axis] - photon.position[axis];
        let (near, far) = if offset <= 0.0 {
            ((start, middle), (middle + 1, end))
        } else {
            ((middle + 1, end), (start, middle))
        };
        self.collect(point, radius2, near.0, near.1, found);
        if offset * offset <= *radius2 {
            self.collect(point, radius2, far.0, far.1, found);
        }
    }
}

/// Orders `found` as a max-heap on distance (the farthest first).
fn make_max_heap(found: &mut [(u32, f64)]) {
    for index in (0..found.len() / 2).rev() {
        sift_down(found, index);
    }
}

/// Moves the entry at `index` down the max-heap `found` to its place.
fn sift_down(found: &mut [(u32, f64)], mut index: usize) {
    loop {
        let (left, right) = (2 * index + 1, 2 * index + 2);
        let mut largest = index;
        if left < found.len() && found[left].1 > found[largest].1 {
            largest = left;
        }
        if right < found.len() && found[right].1 > found[largest].1 {
            largest = right;
        }
        if largest == index {
            return;
        }
        found.swap(index, largest);
        index = largest;
    }
}

/// How much a photon arriving at `cosine` to the normal adds: `cosine^(brilliance - 1)`.
/// Photons arriving aslant already lie sparser by `cosine`, so this makes a caustic light a
/// surface as the light itself would, `cosine^brilliance` (measured: POV-Ray's photons
/// through a pane of index 1 light a floor like the light at any angle and brilliance).
/// Exactly 1 for the common brilliance 1; the cosine is kept above [`GRAZING_COSINE`] so a
/// grazing photon cannot blow up.
fn photon_weight(cosine: f64, brilliance: f64) -> f64 {
    if brilliance == 1.0 {
        1.0
    } else {
        cosine.max(GRAZING_COSINE).powf(brilliance - 1.0)
    }
}

/// Orders `photons` as a balanced kd-tree (each range's median splits it along the axis
/// where the range is widest) and returns each node's axis.
fn build_tree(photons: &mut [Photon]) -> Vec<u8> {
    let mut axes = vec![0u8; photons.len()];
    // Ranges still to split, kept on an explicit stack.
    let mut pending = vec![(0usize, photons.len())];
    while let Some((start, end)) = pending.pop() {
        if end - start < 2 {
            continue;
        }
        let range = &mut photons[start..end];
        let (low, high) = range.iter().fold(
            (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
            |(low, high), p| (low.min(p.position), high.max(p.position)),
        );
        let extent = high - low;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let middle = range.len() / 2;
        range.select_nth_unstable_by(middle, |a, b| a.position[axis].total_cmp(&b.position[axis]));
        axes[start + middle] = axis as u8;
        pending.push((start, start + middle));
        pending.push((start + middle + 1, end));
    }
    axes
}

/// The bounding spheres of the world's photon targets, in the world's order.
fn targets(world: &World) -> Vec<Target> {
    world
        .photon_targets()
        .filter_map(|(bounds, material)| {
            let target = world.materials.get(material as usize)?;
            // Measured: a `no_image` target gets no photons (and casts no shadow).
            if target.no_image {
                return None;
            }
            let multiplier = target.photons.target()?;
            let centre = (bounds.min + bounds.max) / 2.0;
            let radius = (bounds.max - bounds.min).length() / 2.0;
            (centre.is_finite() && radius.is_finite()).then_some(Target {
                centre,
                radius,
                spacing_multiplier: multiplier,
                material,
            })
        })
        .collect()
}

/// The spacing that shoots about `count` photons at the targets from all lights.
fn spacing_for_count(scene: &Scene, targets: &[Target], count: u32) -> f64 {
    // Photons at spacing 1: the cone's solid angle over the square of the angular spacing
    // (for a parallel beam, the target's disc over the square of the spacing).
    let mut at_unit_spacing = 0.0;
    for light in scene
        .lights
        .iter()
        .filter(|l| l.photons.refraction || l.photons.reflection)
    {
        for target in targets {
            if let Some(Beam::Parallel { .. }) = Beam::towards(light, target) {
                // A parallel beam: the target's disc over the square of the spacing.
                at_unit_spacing += PI * (target.radius / target.spacing_multiplier).powi(2);
                continue;
            }
            let distance = target.centre.distance(light.position);
            let solid_angle = if distance <= target.radius {
                2.0 * TAU
            } else {
                TAU * (1.0 - (1.0 - (target.radius / distance).powi(2)).sqrt())
            };
            let per_radian = distance / target.spacing_multiplier;
            at_unit_spacing += solid_angle * per_radian * per_radian;
        }
    }
    let spacing = (at_unit_spacing / f64::from(count.max(1))).sqrt();
    if spacing > 0.0 && spacing.is_finite() {
        spacing
    } else {
        1.0
    }
}

/// What photon shooting needs of the scene.
struct Shooter<'a> {
    world: &'a World,
    max_level: u32,
    bailout: f64,
    /// The rays and stored photons the whole build may still use.
    budget: Budget,
    /// Whether and how photons deposit media photons.
    media: Option<MediaDeposit<'a>>,
    /// The media photons deposited so far.
    media_photons: RefCell<Vec<Photon>>,
}

/// The limits of one photon build, shared by every light and target.
struct Budget {
    /// Photon rays that may still be traced.
    traces_left: Cell<u64>,
    /// Most photons stored.
    stored_limit: usize,
    /// The limit that stopped shooting, described for the warning.
    limit_hit: Cell<Option<&'static str>>,
}

impl Budget {
    fn new(trace_limit: u64, stored_limit: usize) -> Budget {
        Budget {
            traces_left: Cell::new(trace_limit),
            stored_limit,
            limit_hit: Cell::new(None),
        }
    }

    /// Takes one ray from the budget; false (noting it) when none is left.
    fn take_trace(&self) -> bool {
        match self.traces_left.get().checked_sub(1) {
            Some(left) => {
                self.traces_left.set(left);
                true
            }
            None => {
                self.limit_hit.set(Some("photon rays traced"));
                false
            }
        }
    }

    /// True while rays are left to trace.
    fn has_traces(&self) -> bool {
        self.traces_left.get() > 0
    }

    /// Stores `photon` unless the map is full (noting it).
    fn store(&self, photon: Photon, photons: &mut Vec<Photon>) {
        if photons.len() < self.stored_limit {
            photons.push(photon);
        } else {
            self.limit_hit.set(Some("photons stored"));
        }
    }
}

impl Shooter<'_> {
    /// Shoots the photons of `light` at `target` with this spacing at the target; stores
    /// them in `photons` and returns how many were shot.
    fn shoot_at(
        &self,
        light: &LightSource,
        target: &Target,
        spacing: f64,
        settings: &PhotonSettings,
        seed: u64,
        photons: &mut Vec<Photon>,
    ) -> u64 {
        let Some(beam) = Beam::towards(light, target) else {
            return 0;
        };
        // Rings are `step` apart (an angle for a cone, a length for a parallel beam) out to
        // `max_extent`; each photon stands for `step²` (a solid angle or an area).
        let (step, max_extent, relative_step) = match beam {
            Beam::Cone { distance, .. } => {
                let step = spacing / distance;
                let max_angle = if distance <= target.radius {
                    PI
                } else {
                    (target.radius / distance).asin()
                };
                (step, max_angle, step)
            }
            Beam::Parallel { .. } => (spacing, target.radius, spacing / target.radius),
        };
        // A spacing below f64's resolution of directions or positions (or not a number)
        // shoots nothing.
        if !(relative_step >= f64::EPSILON && relative_step.is_finite()) {
            return 0;
        }
        let axis = beam.axis();
        let (across, up) = axis.any_orthonormal_pair();
        // What the light is inside: photons enter and leave objects from there.
        let around_light = if self.media.is_some() {
            interiors_around(self.world, light.position)
        } else {
            InteriorStack::OUTSIDE
        };
        let energy = step * step;
        let mut shot = 0u64;
        let mut any_hit = false;
        let mut ring = 0u64;
        loop {
            let extent = ring as f64 * step;
            if extent > max_extent + 0.5 * step || !self.budget.has_traces() {
                break;
            }
            let circumference = match beam {
                Beam::Cone { .. } => TAU * extent.sin(),
                Beam::Parallel { .. } => TAU * extent,
            };
            let count = if ring == 0 {
                1
            } else {
                ((circumference / step).round() as u64).max(1)
            };
            let mut ring_hit = false;
            for index in 0..count {
                let key = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ (ring << 24 | index);
                let (jitter_radial, jitter_phi) = jitter_pair(key);
                let radial = extent + settings.jitter * step * jitter_radial;
                let phi = (index as f64 + settings.jitter * jitter_phi) * TAU / count as f64;
                let outwards = across * phi.cos() + up * phi.sin();
                let ray = match beam {
                    Beam::Cone { .. } => {
                        let theta = radial.clamp(0.0, PI);
                        Ray {
                            origin: light.position,
                            direction: (axis * theta.cos() + outwards * theta.sin())
                                .normalize_or(axis),
                        }
                    }
                    Beam::Parallel { start, .. } => Ray {
                        origin: start + outwards * radial.max(0.0),
                        direction: axis,
                    },
                };
                if !self.budget.has_traces() {
                    break;
                }
                shot += 1;
                let spreads = matches!(beam, Beam::Cone { .. });
                let start = Start {
                    energy,
                    spreads,
                    inside: around_light,
                    media_step: spacing,
                };
                if self.shoot(light, ray, start, target.material, photons) {
                    ring_hit = true;
                }
            }
            any_hit |= ring_hit;
            if !ring_hit && any_hit && extent >= settings.autostop * max_extent {
                break;
            }
            ring += 1;
        }
        shot
    }

    /// Follows one photon leaving `light` along `ray` as `start` describes; true when its
    /// first surface is the target's.
    fn shoot(
        &self,
        light: &LightSource,
        ray: Ray,
        start: Start,
        target_material: u32,
        photons: &mut Vec<Photon>,
    ) -> bool {
        let Start {
            energy,
            spreads,
            inside,
            media_step,
        } = start;
        if !self.budget.take_trace() {
            return false;
        }
        crate::accel::counters::add(crate::accel::counters::Counter::PhotonRays, 1);
        let Some(hit) = self.next_hit(&ray, 1) else {
            return false;
        };
        let hit_target = hit.material == target_material;
        let Some(arriving) = incoming(light, hit.point) else {
            return hit_target;
        };
        // The light's distance fade is applied where the photon lands, by its whole path
        // (measured), so the fade `incoming` gave the light arriving here (by the distance
        // from the light's position, also for parallel beams) is taken out again.
        let first_fade = fade_factor(light, light.position.distance(hit.point));
        let colour = arriving.colour / first_fade * energy;
        if !(first_fade > 0.0 && colour.is_finite()) {
            return hit_target;
        }
        let mut first = Bounce {
            ray,
            colour,
            level: 1,
            travelled: 0.0,
            spreads,
            inside,
            media_step,
        };
        self.follow(light, &mut first, colour.max_element(), photons);
        hit_target
    }

    /// The nearest surface along `ray`, a photon's path at trace `level`, that the photon
    /// does not cross unchanged: it crosses `no_shadow` objects always, `pass_through`
    /// ones only on its way from the light (level 1); after its first bounce it meets
    /// those like any other (POV-Ray's manual: "once a photon hits the target object, it
    /// will ignore the pass_through flag"; both measured).
    fn next_hit(&self, ray: &Ray, level: u32) -> Option<crate::geometry::SurfaceHit> {
        let materials = &self.world.materials;
        self.world
            .first_hit_skipping(ray, SURFACE_EPSILON, f64::INFINITY, &|id: u32| {
                materials
                    .get(id as usize)
                    .is_some_and(|m| m.no_shadow || (level == 1 && m.photons.pass_through()))
            })
    }

    /// Follows a photon through its bounces (each bounce recursing once per branch),
    /// storing it where it lands after at least one.
    fn follow(
        &self,
        light: &LightSource,
        photon: &mut Bounce,
        start: f64,
        photons: &mut Vec<Photon>,
    ) {
        if !self.budget.take_trace() {
            return;
        }
        let Some(hit) = self.next_hit(&photon.ray, photon.level) else {
            return;
        };
        let Some(material) = self.world.materials.get(hit.material as usize) else {
            return;
        };
        let direction = photon.ray.direction;
        let flags = material.photons;
        if let Some(deposit) = self.media {
            self.deposit_in_media(light, photon, hit.distance, deposit);
        }
        photon.travelled += hit.distance;
        // Light fades on its way through the object the photon is in.
        if let Some(kept) = photon
            .inside
            .materials_innermost_first()
            .next()
            .and_then(|id| self.world.materials.get(id as usize))
            .and_then(|inside| interior_fade(&inside.interior, hit.distance))
        {
            photon.colour *= kept;
        }
        if photon.level > 1 && flags.collect() {
            self.budget.store(
                Photon {
                    position: hit.point,
                    direction,
                    power: fade_factor(light, photon.travelled)
                        * if photon.spreads {
                            // Its solid angle times the square of its path: the area it
                            // covers.
                            photon.colour * photon.travelled * photon.travelled
                        } else {
                            photon.colour
                        },
                },
                photons,
            );
        }
        if photon.level >= self.max_level {
            return;
        }
        let reflects = flags.reflects_for(&light.photons);
        let refracts = flags.refracts_for(&light.photons);
        if !reflects && !refracts {
            return;
        }
        let texture = material.texture_facing(direction, hit.normal);
        let surface = hit_surface(hit.point, direction, hit.normal);
        let pigment = surface_pigment(texture, &hit, &surface);
        let normal = surface.normal;
        // Entering or leaving by the objects the photon is known to be in, as camera rays
        // decide (see `trace`): a bubble cut out of glass is entered from the glass.
        let entering = !photon.inside.contains(hit.material);
        let ior = sanitise_ior(material.interior.ior);
        let (ratio, beyond) = if entering {
            (
                photon.inside.ior() / ior,
                photon.inside.entered(hit.material, ior),
            )
        } else {
            let beyond = photon.inside.left(hit.material);
            (ior / beyond.ior(), beyond)
        };
        let cos_incidence = -direction.dot(normal);
        // A photon never gains light at a bounce.
        let reflectance =
            reflection_colour(&texture.finish, cos_incidence, ratio, pigment.rgb_vec())
                .clamp(DVec3::ZERO, DVec3::ONE);
        let mut reflection = if reflects { reflectance } else { DVec3::ZERO };
        if refracts {
            let mut pass = super::optics::transmission(pigment).clamp(DVec3::ZERO, DVec3::ONE);
            if texture.finish.conserve_energy {
                // What the surface reflects does not pass (as for camera rays).
                pass *= DVec3::ONE - reflectance;
            }
            if pass.max_element() > 0.0 {
                match refract(direction, normal, ratio) {
                    Some(bent) => self.branch(
                        light,
                        photon,
                        Ray {
                            origin: hit.point,
                            direction: bent,
                        },
                        pass,
                        beyond,
                        start,
                        photons,
                    ),
                    // Total internal reflection: all of it goes back.
                    None => reflection = pass + reflection,
                }
            }
        }
        if reflection.max_element() > 0.0 {
            if let Some(mirrored) = mirror(direction, normal).try_normalize() {
                let ray = Ray {
                    origin: hit.point,
                    direction: mirrored,
                };
                self.branch(
                    light,
                    photon,
                    ray,
                    reflection,
                    photon.inside,
                    start,
                    photons,
                );
            }
        }
    }

    /// Deposits media photons along the first `length` of the photon's path, in the
    /// scattering media of the objects it is in (when all of them are hollow) and of the
    /// atmosphere, and dims the photon by the media's extinction there. Photons straight
    /// from the light deposit none (the media's own lighting stands for them, as surface
    /// photons are stored only after a bounce). They lie `media_step` times the `media`
    /// factor apart, at most `max_steps` over the stretch (then evenly spread), each
    /// carrying the photon's power times the length it stands for.
    fn deposit_in_media(
        &self,
        light: &LightSource,
        photon: &mut Bounce,
        length: f64,
        deposit: MediaDeposit,
    ) {
        if photon.level < 2 || !(length > 0.0 && length.is_finite()) {
            return;
        }
        let mut media: [Option<&Media>; MAX_DEPOSIT_MEDIA] = [None; MAX_DEPOSIT_MEDIA];
        let mut count = 0;
        for id in photon.inside.materials_outermost_first() {
            let Some(material) = self.world.materials.get(id as usize) else {
                continue;
            };
            // Media stay out of non-hollow objects (as for camera rays).
            if !material.hollow {
                return;
            }
            for item in &material.interior.media {
                if count < MAX_DEPOSIT_MEDIA {
                    media[count] = Some(item);
                    count += 1;
                }
            }
        }
        for item in deposit.atmosphere {
            if count < MAX_DEPOSIT_MEDIA {
                media[count] = Some(item);
                count += 1;
            }
        }
        let media = &media[..count];
        let scatters = |item: &&Media| {
            item.scattering
                .as_ref()
                .is_some_and(|s| s.colour != DVec3::ZERO)
        };
        if !media.iter().flatten().any(scatters) {
            return;
        }
        let wanted = photon.media_step * deposit.factor;
        if !(wanted > 0.0 && wanted.is_finite()) {
            return;
        }
        let steps = (length / wanted)
            .ceil()
            .clamp(1.0, f64::from(deposit.max_steps.max(1)));
        let step = length / steps;
        let mut depth = DVec3::ZERO;
        let mut stored = self.media_photons.borrow_mut();
        for index in 0..steps as u32 {
            let t = (f64::from(index) + 0.5) * step;
            let point = photon.ray.origin + photon.ray.direction * t;
            let mut extinction = DVec3::ZERO;
            let mut scattering = DVec3::ZERO;
            for item in media.iter().flatten() {
                let density = density_at(item, point);
                extinction += item.absorption * density;
                if let Some(s) = &item.scattering {
                    scattering += s.colour * density;
                    extinction += s.colour * s.extinction * density;
                }
            }
            if scattering != DVec3::ZERO {
                let travelled = photon.travelled + t;
                let spread = if photon.spreads {
                    travelled * travelled
                } else {
                    1.0
                };
                let power = photon.colour
                    * exp_neg(depth + extinction * (0.5 * step))
                    * (fade_factor(light, travelled) * spread * step);
                if power.is_finite() && power.max_element() > 0.0 {
                    self.budget.store(
                        Photon {
                            position: point,
                            direction: photon.ray.direction,
                            power,
                        },
                        &mut stored,
                    );
                }
            }
            depth += extinction * step;
        }
        photon.colour *= exp_neg(depth);
    }

    /// Sends the photon on along `ray` with its colour times `filter`, inside the objects
    /// of `inside`, unless it is too weak.
    #[allow(clippy::too_many_arguments)]
    fn branch(
        &self,
        light: &LightSource,
        photon: &Bounce,
        ray: Ray,
        filter: DVec3,
        inside: InteriorStack,
        start: f64,
        photons: &mut Vec<Photon>,
    ) {
        let colour = photon.colour * filter;
        let strength = colour.max_element();
        if strength.is_nan() || strength <= 0.0 || strength < self.bailout * start {
            return;
        }
        let mut next = Bounce {
            ray,
            colour,
            level: photon.level + 1,
            travelled: photon.travelled,
            spreads: photon.spreads,
            inside,
            media_step: photon.media_step,
        };
        self.follow(light, &mut next, start, photons);
    }
}

/// A photon on its way.
struct Bounce {
    ray: Ray,
    colour: DVec3,
    /// 1 for photons straight from the light, one more per bounce.
    level: u32,
    /// The length of the photon's path so far.
    travelled: f64,
    /// Whether the photon left a point (its colour is per solid angle and the area it
    /// covers grows with the square of its path) rather than a parallel beam (its colour
    /// is per area).
    spreads: bool,
    /// The objects the photon is in (the innermost one's interior fades the photon; their
    /// media, with the atmosphere's, take media photons).
    inside: InteriorStack,
    /// The photon spacing at its target (media photons lie this times the `media` factor
    /// apart along its path).
    media_step: f64,
}

/// How a photon leaves its light.
#[derive(Clone, Copy)]
struct Start {
    /// The solid angle of a photon that `spreads` from a point, else the area of one in a
    /// parallel beam.
    energy: f64,
    spreads: bool,
    /// The objects around the light.
    inside: InteriorStack,
    /// The spacing at the target.
    media_step: f64,
}

/// How a light's photons leave it towards one target.
#[derive(Clone, Copy, Debug)]
enum Beam {
    /// From the light's position, on cones around the unit `axis` towards the target's
    /// centre, `distance` away.
    Cone { axis: DVec3, distance: f64 },
    /// Parallel to the unit `axis` (a `parallel` or cylinder light), from the plane through
    /// the light perpendicular to it, on circles around `start`, the point of that plane
    /// in line with the target's centre.
    Parallel { axis: DVec3, start: DVec3 },
}

impl Beam {
    /// How `light` shoots at `target`; `None` when it has no direction to shoot in.
    fn towards(light: &LightSource, target: &Target) -> Option<Beam> {
        // Parallel and cylinder lights send their light along their axis (as in `incoming`).
        let cylinder_aim = light
            .spotlight
            .filter(|spot| spot.cylinder)
            .map(|spot| spot.point_at);
        match light.parallel.or(cylinder_aim) {
            Some(point_at) => {
                let axis = (point_at - light.position).try_normalize()?;
                let start = target.centre - axis * (target.centre - light.position).dot(axis);
                start.is_finite().then_some(Beam::Parallel { axis, start })
            }
            None => {
                let to_target = target.centre - light.position;
                let distance = to_target.length();
                let axis = to_target.try_normalize()?;
                Some(Beam::Cone { axis, distance })
            }
        }
    }

    /// The direction photons leave in at the beam's centre.
    fn axis(&self) -> DVec3 {
        match *self {
            Beam::Cone { axis, .. } | Beam::Parallel { axis, .. } => axis,
        }
    }
}

/// Two pseudo-random numbers in [-0.5, 0.5) from `key` (two steps of SplitMix64).
fn jitter_pair(key: u64) -> (f64, f64) {
    let state = key ^ JITTER_SALT;
    (
        unit_hash(state) - 0.5,
        unit_hash(state.wrapping_add(0x9e37_79b9_7f4a_7c15)) - 0.5,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn photon_at(x: f64, y: f64, z: f64) -> Photon {
        Photon {
            position: DVec3::new(x, y, z),
            direction: DVec3::NEG_Y,
            power: DVec3::ONE,
        }
    }

    /// A map over `photons` with radius 1 that gathers at most `gather_max` of them.
    fn test_map(mut photons: Vec<Photon>, gather_max: usize) -> PhotonMap {
        let axes = build_tree(&mut photons);
        PhotonMap {
            photons,
            axes,
            radius: 1.0,
            gather_min: 1,
            gather_max,
            expand_increase: 0.2,
            expand_min: 40,
            shot: 0,
            media: None,
        }
    }

    #[test]
    fn tree_finds_exactly_the_photons_in_range() {
        let photons: Vec<Photon> = (0..500)
            .map(|i| {
                let (a, b) = jitter_pair(i);
                photon_at(a * 10.0, 0.0, b * 10.0)
            })
            .collect();
        let all = photons.clone();
        let map = test_map(photons, 10_000);
        let centre = DVec3::new(0.5, 0.0, -1.0);
        let mut found = Vec::new();
        let (count, reach) = map.nearest(centre, 1.5, &mut found);
        let expected = all
            .iter()
            .filter(|p| p.position.distance(centre) <= 1.5)
            .count();
        assert_eq!(count, expected);
        assert_eq!(reach, 1.5);
    }

    #[test]
    fn bounded_search_keeps_the_nearest() {
        let photons: Vec<Photon> = (0..2000)
            .map(|i| {
                let (a, b) = jitter_pair(i);
                photon_at(a * 10.0, b * 10.0, 0.0)
            })
            .collect();
        let all = photons.clone();
        let map = test_map(photons, 25);
        let centre = DVec3::new(0.3, -0.7, 0.0);
        let mut distances: Vec<f64> = all.iter().map(|p| p.position.distance(centre)).collect();
        distances.sort_by(f64::total_cmp);
        let mut found = Vec::new();
        let (count, reach) = map.nearest(centre, 3.0, &mut found);
        assert_eq!(count, 25);
        assert_eq!(reach, distances[24]);
        let mut got: Vec<f64> = found.iter().map(|f| f.1.sqrt()).collect();
        got.sort_by(f64::total_cmp);
        for (got, expected) in got.iter().zip(&distances) {
            assert!((got - expected).abs() < 1e-12);
        }
    }

    #[test]
    fn uniform_photons_give_their_density() {
        // One photon of power 0.01 per 0.1 × 0.1 square lit straight on: irradiance 1.
        let mut photons = Vec::new();
        for i in -100..=100 {
            for j in -100..=100 {
                let mut p = photon_at(f64::from(i) * 0.1, 0.0, f64::from(j) * 0.1);
                p.power = DVec3::splat(0.01);
                photons.push(p);
            }
        }
        let axes = build_tree(&mut photons);
        let map = PhotonMap {
            photons,
            axes,
            radius: 0.5,
            gather_min: 20,
            gather_max: 100,
            expand_increase: 0.2,
            expand_min: 40,
            shot: 0,
            media: None,
        };
        let light = map.irradiance(DVec3::ZERO, DVec3::Y, 1.0);
        assert!((light.x - 1.0).abs() < 0.1, "{light}");
        // Photons arriving aslant weigh as much under brilliance 1.
        let aslant = DVec3::new(0.6, 0.8, 0.0);
        assert_eq!(map.irradiance(DVec3::ZERO, aslant, 1.0), light);
        assert!(map.irradiance(DVec3::ZERO, aslant, 2.0).x < light.x);
    }

    #[test]
    fn budget_stops_traces_and_storing_at_its_limits() {
        let budget = Budget::new(3, 2);
        assert!((0..3).all(|_| budget.take_trace()));
        assert!(budget.limit_hit.get().is_none());
        assert!(!budget.take_trace() && !budget.has_traces());
        assert!(budget.limit_hit.get().is_some());
        let budget = Budget::new(10, 2);
        let mut photons = Vec::new();
        for _ in 0..5 {
            budget.store(photon_at(0.0, 0.0, 0.0), &mut photons);
        }
        assert_eq!(photons.len(), 2);
        assert!(budget.limit_hit.get().is_some());
    }

    #[test]
    fn vanishing_spacing_shoots_nothing() {
        let world = World::build_from_objects(Vec::new());
        let shooter = Shooter {
            world: &world,
            max_level: 5,
            bailout: 0.0,
            budget: Budget::new(TRACE_LIMIT, STORED_LIMIT),
            media: None,
            media_photons: RefCell::new(Vec::new()),
        };
        let light = LightSource::point(DVec3::new(0.0, 5.0, 0.0), DVec3::ONE);
        let target = Target {
            centre: DVec3::ZERO,
            radius: 1.0,
            spacing_multiplier: 1.0,
            material: 0,
        };
        let mut photons = Vec::new();
        for spacing in [1e-320, 1e-17, 0.0, -1.0, f64::NAN, f64::INFINITY] {
            let settings = PhotonSettings {
                density: PhotonDensity::Spacing(spacing),
                ..PhotonSettings::default()
            };
            let mut parallel = light.clone();
            parallel.parallel = Some(DVec3::ZERO);
            for light in [&light, &parallel] {
                let shot = shooter.shoot_at(light, &target, spacing, &settings, 0, &mut photons);
                assert_eq!(shot, 0, "spacing {spacing}");
            }
        }
    }

    #[test]
    fn parallel_beam_starts_on_the_light_plane_in_line_with_the_target() {
        let mut light = LightSource::point(DVec3::new(3.0, 10.0, 0.0), DVec3::ONE);
        light.parallel = Some(DVec3::new(3.0, 0.0, 0.0));
        let target = Target {
            centre: DVec3::new(0.0, 1.0, 0.0),
            radius: 1.0,
            spacing_multiplier: 1.0,
            material: 0,
        };
        let Some(Beam::Parallel { axis, start }) = Beam::towards(&light, &target) else {
            panic!("a parallel light shoots a parallel beam");
        };
        assert_eq!(axis, DVec3::NEG_Y);
        assert!(
            start.distance(DVec3::new(0.0, 10.0, 0.0)) < 1e-12,
            "{start}"
        );
        light.parallel = Some(light.position);
        assert!(Beam::towards(&light, &target).is_none());
    }

    #[test]
    fn jitter_stays_in_range() {
        for key in 0..1000 {
            let (a, b) = jitter_pair(key);
            assert!((-0.5..0.5).contains(&a) && (-0.5..0.5).contains(&b));
        }
    }
}
