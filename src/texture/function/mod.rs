//! Compiled user functions: POV-Ray's `function { .. }` in a form render threads evaluate
//! fast.
//!
//! In: a tree of [`Node`]s built by the evaluator from a function's body (constants already
//! folded, parameters numbered, calls of other user functions resolved), or the pattern,
//! pigment, transformation or spline of a vector-valued function ([`Body`]). Out:
//! [`Function`], a `Send + Sync` value whose [`Function::eval`] maps parameter values to a
//! float and [`Function::eval_vector`] to up to five components.
//! Holds: evaluation never allocates and never panics (arguments beyond those passed read as
//! 0); the tree's depth is bounded by the source expression's nesting.

pub mod internal;
mod internal_fractals;
mod internal_shapes;
mod internal_surfaces;
pub mod internal_table;
pub mod spline;
mod vector;

pub use internal_table::Internal;
pub use vector::{Body, Component, Output};

use std::sync::Arc;

use glam::DVec3;

use crate::noise::{noise, SceneNoiseGenerator};

/// Most parameters a compiled function may take.
pub const MAX_PARAMETERS: usize = 32;

/// Tolerance of `=` and `!=`, the same as the scene language's.
const EQUALITY_EPSILON: f64 = 1e-10;

/// A compiled function of its parameters.
#[derive(Clone, Debug)]
pub struct Function {
    /// What it computes.
    body: Body,
    /// Number of parameters (`x, y, z` when the source declares none).
    arity: usize,
    /// Longest chain of calls of other functions inside the body (0 without calls).
    call_depth: usize,
}

impl Function {
    /// A float function of `arity` parameters computing `root`.
    pub fn new(root: Node, arity: usize) -> Function {
        let body = Body::Expression(root);
        Function {
            call_depth: body.call_depth(),
            body,
            arity,
        }
    }

    /// A pattern, pigment, transformation or spline function; its arity is the body's.
    pub fn with_body(body: Body) -> Function {
        Function {
            arity: body.arity(),
            call_depth: body.call_depth(),
            body,
        }
    }

    /// What the function computes.
    pub fn body(&self) -> &Body {
        &self.body
    }

    /// Number of parameters.
    pub fn arity(&self) -> usize {
        self.arity
    }

    /// Longest chain of nested calls of other functions its evaluation makes.
    pub fn call_depth(&self) -> usize {
        self.call_depth
    }

    /// What a call returns: a float, a colour or a vector.
    pub fn output(&self) -> Output {
        self.body.output()
    }

    /// The value for the given parameters (missing ones read as 0); the first component of
    /// a colour or vector.
    #[inline]
    pub fn eval(&self, parameters: &[f64]) -> f64 {
        match &self.body {
            Body::Expression(root) => root.eval(parameters),
            other => other.eval_vector(parameters)[0],
        }
    }

    /// All components for the given parameters: a float function's value comes first,
    /// unused components are 0.
    #[inline]
    pub fn eval_vector(&self, parameters: &[f64]) -> [f64; 5] {
        match &self.body {
            Body::Expression(root) => [root.eval(parameters), 0.0, 0.0, 0.0, 0.0],
            other => other.eval_vector(parameters),
        }
    }

    /// The value at a point, for functions of `x, y, z`.
    #[inline]
    pub fn eval_point(&self, point: glam::DVec3) -> f64 {
        self.eval(&[point.x, point.y, point.z])
    }
}

/// Operations of one float argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unary {
    Negate,
    Not,
    Abs,
    Acos,
    Acosh,
    Asin,
    Asinh,
    Atan,
    Atanh,
    Ceil,
    Cos,
    Cosh,
    Degrees,
    Exp,
    Floor,
    Int,
    Ln,
    Log,
    Radians,
    Sin,
    Sinh,
    Sqrt,
    Tan,
    Tanh,
}

impl Unary {
    /// The operation for a built-in function name.
    pub fn from_name(name: &str) -> Option<Unary> {
        Some(match name {
            "abs" => Unary::Abs,
            "acos" => Unary::Acos,
            "acosh" => Unary::Acosh,
            "asin" => Unary::Asin,
            "asinh" => Unary::Asinh,
            "atan" => Unary::Atan,
            "atanh" => Unary::Atanh,
            "ceil" => Unary::Ceil,
            "cos" => Unary::Cos,
            "cosh" => Unary::Cosh,
            "degrees" => Unary::Degrees,
            "exp" => Unary::Exp,
            "floor" => Unary::Floor,
            "int" => Unary::Int,
            "ln" => Unary::Ln,
            "log" => Unary::Log,
            "radians" => Unary::Radians,
            "sin" => Unary::Sin,
            "sinh" => Unary::Sinh,
            "sqrt" => Unary::Sqrt,
            "tan" => Unary::Tan,
            "tanh" => Unary::Tanh,
            _ => return None,
        })
    }

    /// Applies the operation.
    #[inline]
    pub fn apply(self, a: f64) -> f64 {
        match self {
            Unary::Negate => -a,
            Unary::Not => f64::from(a == 0.0),
            Unary::Abs => a.abs(),
            Unary::Acos => a.acos(),
            Unary::Acosh => a.acosh(),
            Unary::Asin => a.asin(),
            Unary::Asinh => a.asinh(),
            Unary::Atan => a.atan(),
            Unary::Atanh => a.atanh(),
            Unary::Ceil => a.ceil(),
            Unary::Cos => a.cos(),
            Unary::Cosh => a.cosh(),
            Unary::Degrees => a.to_degrees(),
            Unary::Exp => a.exp(),
            Unary::Floor => a.floor(),
            Unary::Int => a.trunc(),
            Unary::Ln => a.ln(),
            Unary::Log => a.log10(),
            Unary::Radians => a.to_radians(),
            Unary::Sin => a.sin(),
            Unary::Sinh => a.sinh(),
            Unary::Sqrt => a.sqrt(),
            Unary::Tan => a.tan(),
            Unary::Tanh => a.tanh(),
        }
    }
}

/// Operations of two float arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Binary {
    Add,
    Subtract,
    Multiply,
    Divide,
    Less,
    LessEqual,
    Equal,
    NotEqual,
    GreaterEqual,
    Greater,
    And,
    Or,
    Pow,
    Atan2,
    Mod,
    Min,
    Max,
}

impl Binary {
    /// Applies the operation.
    #[inline]
    pub fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Binary::Add => a + b,
            Binary::Subtract => a - b,
            Binary::Multiply => a * b,
            Binary::Divide => a / b,
            Binary::Less => f64::from(a < b),
            Binary::LessEqual => f64::from(a <= b),
            Binary::Equal => f64::from((a - b).abs() < EQUALITY_EPSILON),
            Binary::NotEqual => f64::from((a - b).abs() >= EQUALITY_EPSILON),
            Binary::GreaterEqual => f64::from(a >= b),
            Binary::Greater => f64::from(a > b),
            Binary::And => f64::from(a != 0.0 && b != 0.0),
            Binary::Or => f64::from(a != 0.0 || b != 0.0),
            Binary::Pow => a.powf(b),
            Binary::Atan2 => a.atan2(b),
            Binary::Mod => a % b,
            Binary::Min => a.min(b),
            Binary::Max => a.max(b),
        }
    }
}

/// One node of a compiled expression.
#[derive(Clone, Debug)]
pub enum Node {
    /// A number (literals and everything computed at compile time).
    Constant(f64),
    /// The parameter with this index.
    Parameter(usize),
    /// An operation of one value.
    Unary(Unary, Box<Node>),
    /// An operation of two values.
    Binary(Binary, Box<[Node; 2]>),
    /// `condition ? a : b`.
    Conditional(Box<[Node; 3]>),
    /// `select(a, negative, zero, positive)`; the three-argument form repeats `positive`
    /// as `zero`.
    Select(Box<[Node; 4]>),
    /// `sum(i, from, to, body)` or `prod(..)`: `body` reads the counter as parameter
    /// `counter`, the other parameters as passed.
    Series {
        /// True for `prod`, false for `sum`.
        product: bool,
        /// Index of the counter among the parameters.
        counter: usize,
        /// From, to and body.
        parts: Box<[Node; 3]>,
    },
    /// A call of another compiled float function.
    Call(Arc<Function>, Box<[Node]>),
    /// One component of a call of a colour or vector function (`P(x, y, z).red`).
    Member(Arc<Function>, Component, Box<[Node]>),
    /// A call of one of POV-Ray's internal functions.
    Internal(Internal, Box<[Node]>),
    /// `f_noise3d(x, y, z)`: noise with the scene's `noise_generator` as it stands when the
    /// function is evaluated (measured: POV-Ray's follows the latest `global_settings`).
    SceneNoise(SceneNoiseGenerator, Box<[Node]>),
}

impl Node {
    /// Longest chain of calls of other functions below this node.
    pub(crate) fn call_depth(&self) -> usize {
        match self {
            Node::Constant(_) | Node::Parameter(_) => 0,
            Node::Unary(_, a) => a.call_depth(),
            Node::Binary(_, parts) => max_depth(&parts[..]),
            Node::Conditional(parts) => max_depth(&parts[..]),
            Node::Select(parts) => max_depth(&parts[..]),
            Node::Series { parts, .. } => max_depth(&parts[..]),
            Node::Call(function, arguments) | Node::Member(function, _, arguments) => {
                (function.call_depth() + 1).max(max_depth(arguments))
            }
            Node::Internal(_, arguments) | Node::SceneNoise(_, arguments) => max_depth(arguments),
        }
    }

    /// The node's value for the given parameters.
    pub fn eval(&self, parameters: &[f64]) -> f64 {
        match self {
            Node::Constant(value) => *value,
            Node::Parameter(index) => parameters.get(*index).copied().unwrap_or(0.0),
            Node::Unary(op, a) => op.apply(a.eval(parameters)),
            Node::Binary(op, pair) => op.apply(pair[0].eval(parameters), pair[1].eval(parameters)),
            Node::Conditional(parts) => {
                if parts[0].eval(parameters) != 0.0 {
                    parts[1].eval(parameters)
                } else {
                    parts[2].eval(parameters)
                }
            }
            Node::Select(parts) => {
                let selector = parts[0].eval(parameters);
                if selector < 0.0 {
                    parts[1].eval(parameters)
                } else if selector == 0.0 {
                    parts[2].eval(parameters)
                } else {
                    parts[3].eval(parameters)
                }
            }
            Node::Series {
                product,
                counter,
                parts,
            } => series(*product, *counter, parts, parameters),
            Node::Call(function, arguments) => {
                let values = argument_values(arguments, parameters);
                function.eval(&values[..arguments.len().min(MAX_PARAMETERS)])
            }
            Node::Member(function, component, arguments) => {
                let values = argument_values(arguments, parameters);
                let vector = function.eval_vector(&values[..arguments.len().min(MAX_PARAMETERS)]);
                component.pick(vector)
            }
            Node::Internal(which, arguments) => {
                let values = argument_values(arguments, parameters);
                which.eval(&values)
            }
            Node::SceneNoise(generator, arguments) => {
                let values = argument_values(arguments, parameters);
                noise(DVec3::new(values[0], values[1], values[2]), generator.get())
            }
        }
    }
}

/// The longest call chain below any of `nodes`.
fn max_depth(nodes: &[Node]) -> usize {
    nodes.iter().map(Node::call_depth).max().unwrap_or(0)
}

/// Evaluates call arguments into a fixed buffer (extra arguments are dropped).
#[inline]
fn argument_values(arguments: &[Node], parameters: &[f64]) -> [f64; MAX_PARAMETERS] {
    let mut values = [0.0; MAX_PARAMETERS];
    for (value, argument) in values.iter_mut().zip(arguments) {
        *value = argument.eval(parameters);
    }
    values
}

/// Most terms one `sum` or `prod` adds up (guards endless evaluation).
const SERIES_LIMIT: f64 = 1e6;

/// `sum` or `prod` of `parts[2]` for the counter from `parts[0]` to `parts[1]` in steps of 1.
fn series(product: bool, counter: usize, parts: &[Node; 3], parameters: &[f64]) -> f64 {
    let from = parts[0].eval(parameters);
    let to = parts[1].eval(parameters);
    let mut local = [0.0; MAX_PARAMETERS];
    let count = parameters.len().min(MAX_PARAMETERS);
    local[..count].copy_from_slice(&parameters[..count]);
    let used = (counter + 1).max(count).min(MAX_PARAMETERS);
    let mut total = if product { 1.0 } else { 0.0 };
    let mut index = from;
    let mut steps = 0.0;
    while index <= to && steps < SERIES_LIMIT {
        if let Some(slot) = local.get_mut(counter) {
            *slot = index;
        }
        let term = parts[2].eval(&local[..used]);
        total = if product { total * term } else { total + term };
        index += 1.0;
        steps += 1.0;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parameter(index: usize) -> Node {
        Node::Parameter(index)
    }

    #[test]
    fn arithmetic_and_calls() {
        // f(x, y) = x * x + y
        let square_plus = Arc::new(Function::new(
            Node::Binary(
                Binary::Add,
                Box::new([
                    Node::Binary(Binary::Multiply, Box::new([parameter(0), parameter(0)])),
                    parameter(1),
                ]),
            ),
            2,
        ));
        assert_eq!(square_plus.eval(&[3.0, 1.0]), 10.0);
        // g(x) = f(x + 1, 2)
        let caller = Function::new(
            Node::Call(
                square_plus,
                Box::new([
                    Node::Binary(Binary::Add, Box::new([parameter(0), Node::Constant(1.0)])),
                    Node::Constant(2.0),
                ]),
            ),
            1,
        );
        assert_eq!(caller.eval(&[2.0]), 11.0);
    }

    #[test]
    fn select_and_series() {
        let select = Function::new(
            Node::Select(Box::new([
                parameter(0),
                Node::Constant(-1.0),
                Node::Constant(0.0),
                Node::Constant(1.0),
            ])),
            1,
        );
        assert_eq!(select.eval(&[-2.0]), -1.0);
        assert_eq!(select.eval(&[0.0]), 0.0);
        assert_eq!(select.eval(&[5.0]), 1.0);
        // sum(i, 1, 4, i) with i as parameter 1
        let sum = Function::new(
            Node::Series {
                product: false,
                counter: 1,
                parts: Box::new([Node::Constant(1.0), Node::Constant(4.0), parameter(1)]),
            },
            1,
        );
        assert_eq!(sum.eval(&[0.0]), 10.0);
    }

    #[test]
    fn missing_parameters_read_zero() {
        let function = Function::new(parameter(5), 1);
        assert_eq!(function.eval(&[1.0]), 0.0);
    }
}
