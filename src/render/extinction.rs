//! Extinction: how much participating media dim light crossing them, leaving out the light
//! they add; what a shadow ray through media needs.
//!
//! In: the media along a stretch of a ray (a container's, or the atmosphere's a light's
//! `media_attenuation` asks for) and the stretch. Out: the fraction of light that passes
//! ([`transmittance`]), and what the viewing-ray integrator in [`super::media`] shares with
//! it: the media's density at a point, `exp(−x)`, the sampling limits. Holds: no
//! allocation; sample positions are fixed, so results do not depend on thread count.

use crate::scene::Media;
use crate::texture::pigment::pigment_colour;
use glam::DVec3;

/// Stand-in settings for an empty list of media.
pub(super) static DEFAULT_MEDIA: std::sync::LazyLock<Media> =
    std::sync::LazyLock::new(Media::default);

/// At most this many samples are taken along one ray's shadow stretch by methods 1 and 2.
const MAX_EVEN_SAMPLES: u32 = 100_000;

/// At most this many samples are taken in one interval (methods 1 and 2), on viewing and
/// shadow rays alike; a larger `samples` (the parser takes up to 10,000) is cut to it.
pub(super) const MAX_INTERVAL_SAMPLES: usize = 256;

/// What `media` let through along the ray from `origin` along unit `direction` between
/// distances `start` and `end` (for shadow rays: the light's dimming on its way).
///
/// Measured in POV-Ray 3.7 (step and ramp densities in an absorbing box crossed by the
/// shadow rays of a scattering slab): method 3 takes the pieces of viewing rays (N =
/// max(2, ⌊n/2⌋ + 1) pieces of weight L/N whose samples lie L/(N + 1) apart) without
/// subdividing them, except that the first piece's starting sample is taken at the
/// stretch's far end when the ray `entered` the container at `start` (for a ray starting
/// inside, the pieces are those of viewing rays); methods 1 and 2 sample the middles of
/// `intervals · samples` equal pieces. Both are exact for constant densities.
pub fn transmittance(
    media: &[Media],
    origin: DVec3,
    direction: DVec3,
    (start, end): (f64, f64),
    entered: bool,
) -> DVec3 {
    let length = end - start;
    if !(length > 0.0 && length.is_finite() && media.iter().any(Media::extinguishes)) {
        return DVec3::ONE;
    }
    let extinction_at = |t: f64| {
        let at = origin + direction * t;
        media
            .iter()
            .filter(|m| m.extinguishes())
            .map(|item| extinction_of(item) * density_at(item, at))
            .sum::<DVec3>()
    };
    let ruling = media.first().unwrap_or(&DEFAULT_MEDIA);
    let (method, samples) = (ruling.method, ruling.samples.0);
    let mut depth = DVec3::ZERO;
    if method == 3 {
        let pieces = (samples / 2 + 1).max(2);
        let spacing = length / f64::from(pieces + 1);
        let weight = length / f64::from(pieces);
        let mut at_start = extinction_at(if entered { end } else { start });
        for piece in 0..pieces {
            let from = start + f64::from(piece) * spacing;
            let middle = extinction_at(from + 0.5 * spacing);
            let at_end = extinction_at(from + spacing);
            depth += (at_start + middle + at_end) * (weight / 3.0);
            at_start = at_end;
        }
    } else {
        let count = ruling
            .intervals
            .saturating_mul(samples.min(MAX_INTERVAL_SAMPLES as u32))
            .clamp(1, MAX_EVEN_SAMPLES);
        let step = length / f64::from(count);
        for index in 0..count {
            depth += extinction_at(start + (f64::from(index) + 0.5) * step) * step;
        }
    }
    exp_neg(depth)
}

/// Absorption plus scattering extinction of `media` at density 1.
fn extinction_of(media: &Media) -> DVec3 {
    let scattering = media
        .scattering
        .as_ref()
        .map_or(DVec3::ZERO, |s| s.colour * s.extinction);
    media.absorption + scattering
}

/// The (colour) density of `media` at `point`: its densities multiplied.
pub(super) fn density_at(media: &Media, point: DVec3) -> DVec3 {
    let mut density = DVec3::ONE;
    for pigment in &media.densities {
        density *= pigment_colour(pigment, point).rgb_vec();
    }
    density
}

/// `exp(−x)` per channel.
pub(super) fn exp_neg(x: DVec3) -> DVec3 {
    DVec3::new((-x.x).exp(), (-x.y).exp(), (-x.z).exp())
}
