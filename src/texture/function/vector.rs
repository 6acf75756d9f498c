//! The bodies of compiled functions, among them POV-Ray's vector-valued functions:
//! `function { pattern { .. } }`, `function { pigment { .. } }`,
//! `function { transform { .. } }` and `function { spline { .. } }`, and the members
//! (`.red`, `.gray`, `.hf` ..) that pick one of their components inside other functions.
//!
//! In: a point `x, y, z` (a spline's parameter `t`). Out: up to five components, evaluated by
//! the pattern and pigment code the renderer uses ([`crate::texture::pigment::pigment_colour`]).
//! Holds: pure and allocation-free per call, like every pattern and pigment.
//!
//! Measured against POV-Ray 3.7 (`#debug` of calls at chosen points):
//! - a pattern function gives the pattern's value after its wave modifiers, and a block
//!   pattern's block index (`checker` 0 or 1, `hexagon` 0, 1 or 2); no map is involved.
//! - a pigment function gives the pigment's five components; inside a function a member must
//!   pick one: `.red .green .blue .filter .transmit`, `.x .y .z .t` and `.u .v` for the first
//!   components, `.gray` (0.297 red + 0.589 green + 0.114 blue) and `.hf`, the height-field
//!   value (red + green / 255) · 0.996093.
//! - a transformation function gives the point transformed, three components; POV-Ray's
//!   `.t .filter .transmit` of it read whatever its evaluator last left there, durer reads 0.
//! - a spline function takes the parameter alone and gives the spline's point.

use super::spline::Spline;
use super::Node;
use crate::texture::pattern::PatternKind;
use crate::{
    math::Transform,
    texture::{pattern::Pattern, Pigment, PigmentMap},
};
use glam::DVec3;
use std::sync::Arc;

/// What a compiled function computes.
#[derive(Clone, Debug)]
pub enum Body {
    /// A float expression of the parameters.
    Expression(Node),
    /// `function { pattern { .. } }`: the pattern's value at the point mapped by `transform`
    /// (world to pattern space).
    Pattern {
        /// The pattern with its modifiers.
        pattern: Box<Pattern>,
        /// The transformations written in the pattern block, world to pattern space.
        transform: Transform,
    },
    /// `function { pigment { .. } }`: the pigment's colour at the point.
    Pigment(Box<Pigment>),
    /// `function { transform { .. } }`: the point transformed.
    Transform(Transform),
    /// `function { spline { .. } }`: the spline's point at the parameter, interpolated the
    /// spline's own way.
    Spline(Arc<Spline>),
}

/// What a call of a function returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// A float (expression and pattern functions).
    Float,
    /// A colour: red, green, blue, filter, transmit (pigment functions).
    Colour,
    /// A vector of this many components (transformation and spline functions).
    Vector(u8),
}

impl Body {
    /// Number of parameters the body reads: `x, y, z`, or a spline's parameter alone.
    /// (Expressions declare their own.)
    pub fn arity(&self) -> usize {
        match self {
            Body::Spline(_) => 1,
            _ => 3,
        }
    }

    /// Longest chain of nested function evaluations below the body: function patterns
    /// inside a pattern or pigment count, with the calls they make.
    pub fn call_depth(&self) -> usize {
        match self {
            Body::Expression(root) => root.call_depth(),
            Body::Pattern { pattern, .. } => pattern_depth(pattern),
            Body::Pigment(pigment) => pigment_depth(pigment),
            Body::Transform(_) | Body::Spline(_) => 0,
        }
    }

    /// What a call returns.
    pub fn output(&self) -> Output {
        match self {
            Body::Expression(_) | Body::Pattern { .. } => Output::Float,
            Body::Pigment(_) => Output::Colour,
            Body::Transform(_) => Output::Vector(3),
            Body::Spline(spline) => Output::Vector(spline.components),
        }
    }

    /// The components for the given parameters (missing ones read as 0).
    #[inline]
    pub fn eval_vector(&self, parameters: &[f64]) -> [f64; 5] {
        let parameter = |index: usize| parameters.get(index).copied().unwrap_or(0.0);
        let point = DVec3::new(parameter(0), parameter(1), parameter(2));
        match self {
            Body::Expression(root) => [root.eval(parameters), 0.0, 0.0, 0.0, 0.0],
            Body::Pattern { pattern, transform } => {
                let inner = transform.point_to_inner(point);
                let value = if !inner.is_finite() {
                    0.0
                } else if pattern.block_count().is_some() {
                    pattern.block(inner) as f64
                } else {
                    pattern.value(inner)
                };
                [value, 0.0, 0.0, 0.0, 0.0]
            }
            Body::Pigment(pigment) => {
                crate::texture::pigment::pigment_colour(pigment, point).to_array()
            }
            Body::Transform(transform) => {
                let moved = transform.point_to_outer(point);
                [moved.x, moved.y, moved.z, 0.0, 0.0]
            }
            Body::Spline(spline) => spline.evaluate(parameter(0), spline.kind),
        }
    }
}

/// Longest chain of function evaluations a pattern makes (a function pattern: one more than
/// its function's).
fn pattern_depth(pattern: &Pattern) -> usize {
    match &pattern.kind {
        PatternKind::Function(function) => function.call_depth() + 1,
        _ => 0,
    }
}

/// Longest chain of function evaluations a pigment makes, through its maps and entries.
fn pigment_depth(pigment: &Pigment) -> usize {
    let deepest = |pigments: &mut dyn Iterator<Item = &Pigment>| {
        pigments.map(pigment_depth).max().unwrap_or(0)
    };
    match pigment {
        Pigment::Pattern { pattern, map, .. } => {
            let in_map = match map {
                PigmentMap::Blocks(blocks) => deepest(&mut blocks.iter()),
                PigmentMap::Pigments(entries) => deepest(&mut entries.iter().map(|entry| &entry.1)),
                PigmentMap::Colours(_) => 0,
            };
            pattern_depth(pattern).max(in_map)
        }
        Pigment::Average { entries, .. } => deepest(&mut entries.iter().map(|entry| &entry.1)),
        Pigment::UvMapped(inner) => pigment_depth(inner),
        _ => 0,
    }
}

/// A member picking one value out of a colour or vector function's result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Component {
    /// The component with this index (0 red / x / u ... 4 transmit).
    Index(u8),
    /// `.gray`: the colour's brightness.
    Gray,
    /// `.hf`: the value a height field reads from the colour.
    HeightField,
}

/// Weights of red, green and blue in `.gray` (as in POV-Ray and the scene language).
const GRAY_WEIGHTS: [f64; 3] = [0.297, 0.589, 0.114];

/// The factor POV-Ray scales `.hf` by (measured: `(red + green / 255) · 0.996093`).
const HEIGHT_FIELD_SCALE: f64 = 0.996093;

impl Component {
    /// The component a member name selects, for a function returning `output`; `None` when
    /// the member does not exist there.
    pub fn from_member(name: &str, output: Output) -> Option<Component> {
        let index = match name {
            "x" | "u" | "red" => 0,
            "y" | "v" | "green" => 1,
            "z" | "blue" => 2,
            "t" | "filter" => 3,
            "transmit" => 4,
            "gray" | "grey" => return Some(Component::Gray),
            "hf" => return Some(Component::HeightField),
            _ => return None,
        };
        match output {
            Output::Float => None,
            Output::Colour | Output::Vector(_) => Some(Component::Index(index)),
        }
    }

    /// The selected value.
    #[inline]
    pub fn pick(self, values: [f64; 5]) -> f64 {
        match self {
            Component::Index(index) => values[usize::from(index).min(4)],
            Component::Gray => {
                GRAY_WEIGHTS[0] * values[0]
                    + GRAY_WEIGHTS[1] * values[1]
                    + GRAY_WEIGHTS[2] * values[2]
            }
            Component::HeightField => (values[0] + values[1] / 255.0) * HEIGHT_FIELD_SCALE,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Colour;

    #[test]
    fn members_pick_components() {
        let values = [0.25, 0.5, 0.75, 0.125, 0.0625];
        let colour = Output::Colour;
        let pick = |name| Component::from_member(name, colour).unwrap().pick(values);
        assert_eq!(pick("red"), 0.25);
        assert_eq!(pick("v"), 0.5);
        assert_eq!(pick("blue"), 0.75);
        assert_eq!(pick("t"), 0.125);
        assert_eq!(pick("transmit"), 0.0625);
        assert!((pick("gray") - (0.297 * 0.25 + 0.589 * 0.5 + 0.114 * 0.75)).abs() < 1e-15);
        // POV-Ray prints 0.499999623529 for `.hf` of rgb <0.5, 0.5, 0>.
        let hf = Component::HeightField.pick([0.5, 0.5, 0.0, 0.0, 0.0]);
        assert!((hf - 0.499999623529).abs() < 1e-12);
        assert_eq!(Component::from_member("red", Output::Float), None);
        assert_eq!(Component::from_member("w", colour), None);
    }

    #[test]
    fn pigment_and_transform_bodies() {
        let pigment = Body::Pigment(Box::new(Pigment::Solid(Colour::rgbft(
            0.25, 0.5, 0.75, 0.125, 0.0,
        ))));
        assert_eq!(pigment.output(), Output::Colour);
        assert_eq!(
            pigment.eval_vector(&[1.0, 2.0, 3.0]),
            [0.25, 0.5, 0.75, 0.125, 0.0]
        );
        let moved = Body::Transform(Transform::translation(DVec3::new(1.0, 0.0, -1.0)));
        assert_eq!(
            moved.eval_vector(&[1.0, 2.0, 3.0]),
            [2.0, 2.0, 2.0, 0.0, 0.0]
        );
    }
}
