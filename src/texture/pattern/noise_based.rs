//! The patterns built on solid noise: bozo (spotted, bumps), dents, granite, wrinkles,
//! marble, wood, agate, ripples, waves, cells and crackle.
//!
//! In: a pattern-space point after warps, the pattern's noise generator and (for the
//! patterns that handle the classic `turbulence` themselves) its turbulence settings. Out:
//! the raw value. Holds: pure, allocation-free.
//!
//! Measured against POV-Ray 3.7 with `scripts/probe-patterns.py` (values of
//! `function { pattern { .. } }` at random points; the known-answer test below compares
//! them, N = `crate::noise::noise`, all to ~1e-12 unless said otherwise):
//! - bozo, spotted, bumps: N(p); dents: N(p)³;
//! - granite: Σ over 6 octaves i of |0.5 − clamp(2·N(4·2ⁱ·p) − 0.5, 0, 1)| / 2ⁱ;
//! - wrinkles: Σ over 10 octaves i of clamp(2·N(2ⁱ·p) − 0.5, 0, 1) / 2ⁱ⁺¹;
//! - marble, wood, agate (with and without `agate_turb`): as below, exact with the
//!   scalar/vector turbulence of `crate::noise`;
//! - cells: `crate::noise::cells_value`; crackle: distances to the feature points of the
//!   27 cubes around, with `offset` a fourth coordinate of every distance
//!   (`(Σ|dᵢ|^m + |offset|^m)^(1/m)`), the `form` combination clamped to [0, 1]; `solid`: N
//!   at the nearest feature point (with the pattern's generator). Exact to the last bit.
//! - ripples: `0.5 + Σ sin(2π·(dᵢ·f + φ))/20`, waves: `0.5 + Σ sin(2π·(fᵢ·dᵢ·f + φ))/(50·fᵢ)`
//!   over the ten sources of `waves.rs` (dᵢ the distance to centre i, fᵢ its frequency);
//!   the pattern's `frequency` f and `phase` φ act inside the sum and then again as the
//!   usual output wave. Exact to ~1e-15.

use std::f64::consts::PI;

use glam::DVec3;

use super::wave::Wave;
use super::waves::{distance_to_centre, WaveSource};
use crate::noise::{noise, turbulence, NoiseGenerator, TurbulenceShape};

/// The classic turbulence of a pattern, for the patterns that use it internally.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClassicTurbulence {
    /// Amount per axis (zero: none).
    pub amount: DVec3,
    /// Octaves, omega and lambda.
    pub shape: TurbulenceShape,
}

/// `crackle`'s settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crackle {
    /// Weights of the distances to the nearest, second and third cell points.
    pub form: DVec3,
    /// Exponent of the distance metric (2: Euclidean).
    pub metric: f64,
    /// Added to the value.
    pub offset: f64,
    /// One value per cell instead of the distance combination.
    pub solid: bool,
}

impl Default for Crackle {
    fn default() -> Self {
        Crackle {
            form: DVec3::new(-1.0, 1.0, 0.0),
            metric: 2.0,
            offset: 0.0,
            solid: false,
        }
    }
}

/// `bozo`, `spotted` and `bumps` as pigments: the noise itself.
pub fn bozo(point: DVec3, generator: NoiseGenerator) -> f64 {
    noise(point, generator)
}

/// `dents` as a pigment: the cube of the noise.
pub fn dents(point: DVec3, generator: NoiseGenerator) -> f64 {
    let value = noise(point, generator);
    value * value * value
}

/// `granite`: six octaves of `|0.5 − noise|` at 4, 8, 16... times the point, each octave
/// weighted by its inverse frequency (1/f noise).
pub fn granite(point: DVec3, generator: NoiseGenerator) -> f64 {
    let mut sum = 0.0;
    let mut frequency = 1.0;
    for _ in 0..6 {
        let stretched = octave_noise(point * (4.0 * frequency), generator);
        sum += (0.5 - stretched).abs() / frequency;
        frequency *= 2.0;
    }
    sum
}

/// One octave's noise in granite and wrinkles: generator 1's value as it is; generators 2
/// and 3 stretched to `2 N - 0.5` and clamped to [0, 1] (as in scalar turbulence).
fn octave_noise(point: DVec3, generator: NoiseGenerator) -> f64 {
    let value = noise(point, generator);
    match generator {
        NoiseGenerator::Original => value,
        _ => (2.0 * value - 0.5).clamp(0.0, 1.0),
    }
}

/// `wrinkles`: ten octaves of noise, each half the weight and twice the frequency of the
/// one before.
pub fn wrinkles(point: DVec3, generator: NoiseGenerator) -> f64 {
    let mut sum = 0.0;
    let mut weight = 0.5;
    let mut scale = 1.0;
    for _ in 0..10 {
        sum += weight * octave_noise(point * scale, generator);
        weight *= 0.5;
        scale *= 2.0;
    }
    sum
}

/// `marble`: the x coordinate plus the scalar turbulence scaled by the turbulence's x.
pub fn marble(point: DVec3, turb: &ClassicTurbulence, generator: NoiseGenerator) -> f64 {
    let mut value = point.x;
    if turb.amount != DVec3::ZERO {
        value += turb.amount.x * turbulence(point, &turb.shape, generator);
    }
    value
}

/// `wood`: the distance from the z axis, the point first pushed by the vector turbulence
/// through a sine per axis when the pattern has turbulence.
pub fn wood(point: DVec3, turb: &ClassicTurbulence, generator: NoiseGenerator) -> f64 {
    let mut moved = point;
    if turb.amount != DVec3::ZERO {
        let push = crate::noise::vector_turbulence(point, &turb.shape, generator);
        moved.x += cycloidal((point.x + push.x) * turb.amount.x);
        moved.y += cycloidal((point.y + push.y) * turb.amount.y);
    }
    (moved.x * moved.x + moved.y * moved.y).sqrt()
}

/// `agate`: `((1 + sin 2π(1.1z + 1.3·agate_turb·turbulence)) / 2)^0.77`.
pub fn agate(
    point: DVec3,
    agate_turb: f64,
    turb: &ClassicTurbulence,
    generator: NoiseGenerator,
) -> f64 {
    let stirred = if agate_turb != 0.0 {
        agate_turb * turbulence(point, &turb.shape, generator)
    } else {
        0.0
    };
    let wave = (1.0 + cycloidal(1.1 * point.z + 1.3 * stirred)) * 0.5;
    wave.max(0.0).powf(0.77)
}

/// `sin(2πx)`.
fn cycloidal(x: f64) -> f64 {
    (2.0 * PI * x).sin()
}

/// `ripples`: the mean of sine waves spreading from the wave sources (never empty), in
/// [0, 1]. `wave`'s
/// frequency scales the distances and its phase shifts them (POV-Ray applies both here and
/// again to the result).
pub fn ripples(point: DVec3, wave: &Wave, sources: &[WaveSource]) -> f64 {
    let sum: f64 = sources
        .iter()
        .map(|source| cycloidal(distance_to_centre(point, source) * wave.frequency + wave.phase))
        .sum();
    0.5 + sum / (2.0 * sources.len() as f64)
}

/// `waves`: like ripples, but every source has its own frequency, and its wave an
/// amplitude inversely proportional to it.
pub fn waves(point: DVec3, wave: &Wave, sources: &[WaveSource]) -> f64 {
    let sum: f64 = sources
        .iter()
        .map(|source| {
            let distance = distance_to_centre(point, source);
            cycloidal(distance * wave.frequency * source.frequency + wave.phase) / source.frequency
        })
        .sum();
    0.5 + sum / (5.0 * sources.len() as f64)
}

/// The integer cell of a point (coordinates clamped so the conversion cannot overflow).
fn cell_of(point: DVec3) -> [i64; 3] {
    let limit = 1e15;
    let cell = point
        .floor()
        .clamp(DVec3::splat(-limit), DVec3::splat(limit));
    [cell.x as i64, cell.y as i64, cell.z as i64]
}

/// `cells`: one random value per unit cube, from POV-Ray's table of random numbers.
pub fn cells(point: DVec3) -> f64 {
    crate::noise::cells_value(point)
}

/// `crackle`: the Voronoi diagram of one random point per unit cube; the value combines
/// the distances to the three nearest points with `form` (or, `solid`, the nearest cell's
/// own random value).
pub fn crackle(point: DVec3, settings: &Crackle, generator: NoiseGenerator) -> f64 {
    let home = cell_of(point);
    let mut nearest = [f64::INFINITY; 3];
    let mut nearest_cell = home;
    for dx in -1..=1 {
        for dy in -1..=1 {
            for dz in -1..=1 {
                let cell = [home[0] + dx, home[1] + dy, home[2] + dz];
                let site = crate::noise::crackle_feature_point(cell);
                let distance = metric_distance(point - site, settings.metric, settings.offset);
                if distance < nearest[0] {
                    nearest = [distance, nearest[0], nearest[1]];
                    nearest_cell = cell;
                } else if distance < nearest[1] {
                    nearest = [nearest[0], distance, nearest[1]];
                } else if distance < nearest[2] {
                    nearest[2] = distance;
                }
            }
        }
    }
    if settings.solid {
        return noise(crate::noise::crackle_feature_point(nearest_cell), generator);
    }
    let value = (settings.form.x * nearest[0]
        + settings.form.y * nearest[1]
        + settings.form.z * nearest[2])
        .clamp(0.0, 1.0);
    // Far from the origin the cell points lose all precision; give 0 rather than NaN.
    if value.is_finite() {
        value
    } else {
        0.0
    }
}

/// The distance of `offset` in the Minkowski metric with exponent `metric`.
fn metric_distance(offset: DVec3, metric: f64, fourth: f64) -> f64 {
    if metric == 2.0 {
        return (offset.length_squared() + fourth * fourth).sqrt();
    }
    if metric == 1.0 {
        return offset.abs().element_sum() + fourth.abs();
    }
    let a = offset.abs();
    (a.x.powf(metric) + a.y.powf(metric) + a.z.powf(metric) + fourth.abs().powf(metric))
        .powf(1.0 / metric)
}

#[cfg(test)]
mod tests {
    use super::*;

    const GENERATOR: NoiseGenerator = NoiseGenerator::RangeCorrected;

    #[test]
    fn noise_free_parts_match_povray() {
        let none = ClassicTurbulence {
            amount: DVec3::ZERO,
            shape: TurbulenceShape::default(),
        };
        // POV-Ray's `agate agate_turb 0 ramp_wave` at z = 0.2 and 0.73.
        let agate_low = agate(DVec3::new(-1.3, 0.4, 0.2), 0.0, &none, GENERATOR);
        assert!((agate_low - 0.993174).abs() < 1e-5);
        let agate_high = agate(DVec3::new(-0.53, 0.09, 0.73), 0.0, &none, GENERATOR);
        assert!((agate_high - 0.062792).abs() < 1e-5);
        let ring = wood(DVec3::new(-1.3, 0.4, 0.2), &none, GENERATOR);
        assert!((ring - 1.36015).abs() < 1e-5);
        assert_eq!(marble(DVec3::new(-1.3, 0.4, 0.2), &none, GENERATOR), -1.3);
    }

    #[test]
    fn cells_and_crackle_are_deterministic_and_bounded() {
        let p = DVec3::new(0.3, 7.2, -4.1);
        assert_eq!(cells(p), cells(p + DVec3::splat(0.01)));
        assert!((0.0..1.0).contains(&cells(p)));
        let value = crackle(p, &Crackle::default(), GENERATOR);
        assert!(value >= 0.0 && value.is_finite());
        assert!(crackle(DVec3::splat(1e300), &Crackle::default(), GENERATOR).is_finite());
    }

    /// The patterns of `known_answers.txt` (see scripts/probe-patterns.py), by name.
    fn probed_pattern(name: &str) -> crate::texture::pattern::Pattern {
        use crate::texture::pattern::{Pattern, PatternKind};
        let crackle = |form: DVec3, metric: f64, offset: f64, solid: bool| {
            PatternKind::Crackle(Crackle {
                form,
                metric,
                offset,
                solid,
            })
        };
        let with_turbulence = |kind: PatternKind, amount: DVec3, shape: TurbulenceShape| {
            let mut spec = Pattern::new(kind);
            spec.turbulence = ClassicTurbulence { amount, shape };
            spec
        };
        let with_wave = |kind: PatternKind, frequency: f64, phase: f64| {
            let mut spec = Pattern::new(kind);
            spec.wave.frequency = frequency;
            spec.wave.phase = phase;
            spec
        };
        let default_shape = TurbulenceShape::default();
        match name {
            "bozo" => Pattern::new(PatternKind::Bozo),
            "dents" => Pattern::new(PatternKind::Dents),
            "granite" => Pattern::new(PatternKind::Granite),
            "wrinkles" => Pattern::new(PatternKind::Wrinkles),
            "agate" => Pattern::new(PatternKind::Agate { agate_turb: 1.0 }),
            "agate_turb" => Pattern::new(PatternKind::Agate { agate_turb: 0.4 }),
            "waves" => Pattern::new(PatternKind::Waves(Default::default())),
            "ripples" => Pattern::new(PatternKind::Ripples(Default::default())),
            "cells" => Pattern::new(PatternKind::Cells),
            "crackle" => Pattern::new(PatternKind::Crackle(Crackle::default())),
            "crackle_form_metric" => {
                Pattern::new(crackle(DVec3::new(1.0, 0.0, 0.0), 1.0, 0.0, false))
            }
            "crackle_metric3" => Pattern::new(crackle(DVec3::new(-1.0, 1.0, 0.5), 3.0, 0.0, false)),
            "crackle_solid" => Pattern::new(crackle(DVec3::new(-1.0, 1.0, 0.0), 2.0, 0.1, true)),
            "crackle_offset" => Pattern::new(crackle(DVec3::new(-1.0, 1.0, 0.0), 2.0, 0.3, false)),
            "marble_turbulence" => {
                with_turbulence(PatternKind::Marble, DVec3::splat(0.8), default_shape)
            }
            "wood_turbulence" => {
                with_turbulence(PatternKind::Wood, DVec3::splat(0.1), default_shape)
            }
            "gradient_turbulence" => with_turbulence(
                PatternKind::Gradient(DVec3::X),
                DVec3::splat(0.5),
                default_shape,
            ),
            "gradient_turbulence_shape" => with_turbulence(
                PatternKind::Gradient(DVec3::X),
                DVec3::new(0.8, 0.1, 0.0),
                TurbulenceShape {
                    octaves: 3,
                    omega: 0.7,
                    lambda: 3.0,
                },
            ),
            "spiral1_turbulence" => {
                with_turbulence(PatternKind::Spiral1(2.0), DVec3::splat(0.3), default_shape)
            }
            "crackle_solid_generator1" => {
                let mut spec = Pattern::new(crackle(DVec3::new(-1.0, 1.0, 0.0), 2.0, 0.0, true));
                spec.noise = crate::texture::pattern::NoiseChoice::Own(NoiseGenerator::Original);
                spec
            }
            "ripples_frequency_phase" => {
                with_wave(PatternKind::Ripples(Default::default()), 3.0, 0.25)
            }
            "waves_frequency_phase" => with_wave(PatternKind::Waves(Default::default()), 0.5, 0.7),
            other => panic!("known_answers.txt names an unknown pattern {other}"),
        }
    }

    /// How far each probed pattern may be from povray's value.
    fn tolerance(name: &str) -> f64 {
        match name {
            // The spiral's own angle differs from povray's by up to 4e-5 (a constant of the
            // spiral formula in geometric.rs, not the turbulence).
            "spiral1_turbulence" => 1e-4,
            _ => 1e-6,
        }
    }

    #[test]
    fn patterns_match_povray_known_answers() {
        let table = include_str!("known_answers.txt");
        // Per pattern: largest difference, points probed, points over 1e-6.
        let mut worst: Vec<(&str, f64, usize, usize)> = Vec::new();
        for line in table.lines().filter(|line| !line.starts_with('#')) {
            let fields: Vec<&str> = line.split_whitespace().collect();
            let number = |index: usize| fields[index].parse::<f64>().unwrap();
            let point = DVec3::new(number(1), number(2), number(3));
            let ours = probed_pattern(fields[0]).value(point);
            assert!((0.0..=1.0).contains(&ours), "{line}: {ours}");
            let difference = (ours - number(4)).abs();
            // A value wrapping around 1 is the same pattern value.
            let difference = difference.min((1.0 - difference).abs());
            let off = usize::from(difference > 1e-6);
            match worst.iter_mut().find(|entry| entry.0 == fields[0]) {
                Some(entry) => {
                    entry.1 = entry.1.max(difference);
                    entry.2 += 1;
                    entry.3 += off;
                }
                None => worst.push((fields[0], difference, 1, off)),
            }
        }
        for (name, difference, count, off) in &worst {
            eprintln!("{name:28} max difference {difference:.3e}, {off}/{count} over 1e-6");
        }
        let failing: Vec<&str> = worst
            .iter()
            .filter(|entry| entry.1 > tolerance(entry.0))
            .map(|entry| entry.0)
            .collect();
        assert!(
            failing.is_empty(),
            "patterns differing from povray: {failing:?}"
        );
    }
}
