//! Patterns: functions from a point in pattern space to a value in [0, 1] or a block index,
//! with POV-Ray's modifiers (turbulence, warps, frequency, phase, wave shapes).
//!
//! In: a point already mapped into pattern space by the owning pigment/normal/texture's
//! transform. Out: the pattern value ([`PatternSpec::value`]) or, for block patterns such as
//! `checker`, the block index ([`PatternSpec::block`]). Holds: pure and allocation-free per
//! call; non-finite input gives 0.
//!
//! Maps (colour, pigment, normal, texture maps) and what a value means live with the textures
//! (`render::pattern`); this module only knows patterns.

use glam::DVec3;

use crate::scene::Transform;

/// Offset POV-Ray adds to each coordinate before flooring in the checker pattern.
const CHECKER_OFFSET: f64 = 1e-10;

/// The modulus of POV-Ray's default ramp wave, slightly above 1 so that 1 itself survives.
const RAMP_WAVE_PERIOD: f64 = 1.00001;

/// A pattern with its modifiers.
#[derive(Clone, Debug)]
pub struct PatternSpec {
    /// Which pattern.
    pub kind: PatternKind,
}

/// The patterns.
#[derive(Clone, Debug)]
pub enum PatternKind {
    /// 3-D checkerboard of unit cubes; block index 0 or 1.
    Checker,
    /// Ramp along a direction (the fractional part of `dot(p, direction)`).
    Gradient(DVec3),
}

impl PatternSpec {
    /// The pattern with POV-Ray's default modifiers.
    pub fn new(kind: PatternKind) -> PatternSpec {
        PatternSpec { kind }
    }

    /// Called for every transformation written inside the owning block after the pattern
    /// keyword (the owner also composes it into its own transform), so that warps can
    /// remember the frame they were written in.
    pub fn note_transform(&mut self, transform: &Transform) {
        let _ = transform;
    }

    /// For block patterns (`checker`, `hexagon`, `brick`, ...): how many blocks there are.
    /// `None` for patterns with a continuous value.
    pub fn block_count(&self) -> Option<usize> {
        match self.kind {
            PatternKind::Checker => Some(2),
            PatternKind::Gradient(_) => None,
        }
    }

    /// The block index (below [`Self::block_count`]) at a pattern-space point.
    pub fn block(&self, point: DVec3) -> usize {
        match self.kind {
            PatternKind::Checker => checker_block(point),
            PatternKind::Gradient(_) => 0,
        }
    }

    /// The pattern's value in [0, 1] at a pattern-space point (after turbulence, warps,
    /// frequency, phase and the wave shape). Block patterns give their block index.
    pub fn value(&self, point: DVec3) -> f64 {
        if !point.is_finite() {
            return 0.0;
        }
        match self.kind {
            PatternKind::Checker => checker_block(point) as f64,
            PatternKind::Gradient(direction) => gradient_value(point, direction),
        }
    }

    /// For patterns with a dedicated normal perturbation when used in `normal { }` (bumps,
    /// dents, ripples, waves, wrinkles, quilted, facets...): the perturbation vector to add to
    /// the surface normal at `point` for a bump size of 1. `None` means "derive the slope from
    /// [`Self::value`]".
    pub fn normal_perturbation(&self, point: DVec3) -> Option<DVec3> {
        let _ = point;
        None
    }
}

/// Which of two checker blocks (0 or 1) the pattern-space point lies in.
pub fn checker_block(point: DVec3) -> usize {
    let sum = (point.x + CHECKER_OFFSET).floor()
        + (point.y + CHECKER_OFFSET).floor()
        + (point.z + CHECKER_OFFSET).floor();
    // Sums beyond 2^53 are all even; rem_euclid keeps negative sums in 0..2.
    if sum.rem_euclid(2.0) >= 1.0 {
        1
    } else {
        0
    }
}

/// The gradient pattern's value in [0, 1] at a pattern-space point.
pub fn gradient_value(point: DVec3, direction: DVec3) -> f64 {
    let length = direction.length();
    if !(length > 0.0 && length.is_finite()) {
        return 0.0;
    }
    let mut value = point.dot(direction / length);
    if value > 1.0 {
        value %= 1.0;
    }
    ramp_wave(value)
}

/// POV-Ray's default `ramp_wave` applied to a raw pattern value.
fn ramp_wave(value: f64) -> f64 {
    let mut wrapped = value % RAMP_WAVE_PERIOD;
    if wrapped < 0.0 {
        wrapped -= wrapped.floor();
    }
    if wrapped.is_finite() {
        wrapped
    } else {
        0.0
    }
}
